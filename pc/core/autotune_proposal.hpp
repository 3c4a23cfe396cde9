// The gains an identification flight proposes, beside those flown during it (issue 34: "the
// pilot accepts them on the parameter screen (old and new side by side) and can go back"). Made
// from the IdentificationRecorder's records by tune/'s one pipeline (fit, design, figures: the
// same calls as qrsim --autotune); a refused fit is kept as its reason. Accepting sends the six
// new values through ParameterSync (each acked, then read back); going back sends the old ones.
#pragma once

#include <stdint.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <pc/core/parameter_sync.hpp>
#include <tune/identification_design.hpp>

namespace qrterm {

struct GainChange {
  wire::ParamId id{};
  int32_t before = 0;  // raw, as flown during the identification
  int32_t after = 0;   // raw, as designed (rounded and clamped to the parameter)
};

class AutotuneProposal {
 public:
  enum class Standing : uint8_t { none, refused, proposed, accepted, back };

  // The fit and the design, on any thread (they take a good part of a second: the console's loop
  // keeps the heartbeat meanwhile); `why` the fit's refusal.
  struct Outcome {
    std::optional<tune::IdentificationDesign> design;
    std::string why;
  };
  static Outcome compute(const std::array<tune::AxisRecord, 3>& records, const wire::ParameterValues& flown,
                         double control_hz);
  // The outcome for the gains flown with `flown` in force: proposed, or refused with the reason.
  void take(const Outcome& outcome, const wire::ParameterValues& flown);
  // Both at once (the tests).
  void make(const std::array<tune::AxisRecord, 3>& records, const wire::ParameterValues& flown, double control_hz) {
    take(compute(records, flown, control_hz), flown);
  }
  // The identification kept nothing (an early end, a lost sample): `why` is shown instead.
  void refuse(const std::string& why);

  // The new values to the QR (true if there was a proposal to take).
  bool accept(ParameterSync& parameters);
  // The values flown before to the QR (true if there was a proposal).
  bool back(ParameterSync& parameters);

  Standing standing() const { return standing_; }
  const std::string& why() const { return why_; }
  const std::vector<GainChange>& changes() const { return changes_; }
  const std::optional<tune::IdentificationDesign>& design() const { return design_; }
  // The screen's lines: the models, the gains old and new, the predicted figures before and after,
  // and the standing; empty when there is nothing to show.
  std::vector<std::string> lines() const;

 private:
  bool send(ParameterSync& parameters, bool after);

  Standing standing_ = Standing::none;
  std::string why_;
  std::optional<tune::IdentificationDesign> design_;
  std::vector<GainChange> changes_;
};

}  // namespace qrterm
