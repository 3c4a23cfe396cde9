// The console's side of the QR's parameters: the values the pilot wants (from the parameter file
// and the gain keys), the values the QR reports in force, and the upload that brings the QR to
// the wanted ones. One param_set at a time (the resend queue keeps one request per type, and a
// newer one would replace the last), then one param_get of all of them, so every value on the
// screen is one the QR has confirmed, whether or not it reports after each set.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <common/replies.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/gain_steps.hpp>
#include <pc/core/link_session.hpp>

namespace qrterm {

class ParameterSync {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  ParameterSync(const wire::ParameterValues& wanted, Note note) : wanted_(wanted), note_(std::move(note)) {}

  const wire::ParameterValues& wanted() const { return wanted_; }
  std::optional<int32_t> reported(wire::ParamId id) const;
  size_t to_send() const { return queue_.size() + (in_flight_ ? 1 : 0); }

  // Every parameter goes up (the link came up: the QR may have restarted with its defaults).
  void send_all();
  // A gain key: one step of its parameter, sent at once. The log gets one line for a burst of
  // steps of one parameter (30 presses are one change to read, not 30): when the steps stop for
  // kStepsSettleMs, another parameter is stepped, or end_steps() says another key came.
  void step(const GainStep& step);
  void end_steps();
  size_t steps_taken() const { return steps_taken_; }  // every step asked for, since start
  // The clock, for the burst's end; called every console tick, link or not.
  void settle_steps(uint32_t now_ms);
  // A value typed or loaded on the parameter screen: sent at once if in range, else refused.
  wire::NackReason set(wire::ParamId id, int32_t raw);
  // Sent and not answered yet, or waiting its turn.
  bool pending(wire::ParamId id) const { return on_its_way(id); }
  // A value the QR says is in force.
  void on_report(const wire::ParamReport& report);
  // The pilot's read-back (p): asks the QR for every value; once all have come, the log says
  // whether they are the console's, and names those that are not.
  void read_back(LinkSession& link, uint32_t now_ms);

  // Sends the next param_set when the last one is answered, and the read-back after the last.
  void tick(LinkSession& link, uint32_t now_ms);

 private:
  // The steps of one parameter not yet in the log.
  struct StepBurst {
    wire::ParamId id;
    int32_t from;  // before the first step
    uint32_t steps;
    uint32_t last_ms;
  };

  void queue(wire::ParamId id);
  bool on_its_way(wire::ParamId id) const;
  void take_report(const wire::ParamReport& report);
  void count_read_back(const wire::ParamReport& report);

  wire::ParameterValues wanted_;
  Note note_;
  std::optional<int32_t> reported_[wire::kParameterCount];
  std::deque<wire::ParamId> queue_;
  std::optional<wire::ParamId> in_flight_;  // the param_set waiting for its answer
  bool announced_ = false;                  // "sending N parameters" said for this upload
  bool read_back_owed_ = false;
  size_t read_back_left_ = 0;  // reports still to come after the pilot's p
  std::vector<std::string> read_back_differ_;
  std::optional<StepBurst> burst_;
  uint32_t now_ms_ = 0;
  size_t steps_taken_ = 0;
};

// A burst of gain steps ends after this long without one.
inline constexpr uint32_t kStepsSettleMs = 1000;

// "roll_pitch_p1 = 4.25": a parameter and a raw value in its real unit.
std::string param_text(wire::ParamId id, int32_t raw);

}  // namespace qrterm
