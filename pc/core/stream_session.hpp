// The console's side of observable streams (docs/protocol.md section 13): it learns the QR's
// observable table at connect, asks for the plot's selection as stream 0, unpacks the samples into
// the PlotModel and writes every one to a CSV in the log folder (a new file for each selection,
// units in the column names). The cost of a selection is shown before it is asked for; the QR
// has the last word (nack over_budget).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <common/observable_messages.hpp>
#include <common/sample_packing.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/csv_writer.hpp>
#include <pc/core/link_session.hpp>
#include <pc/core/observable_catalog.hpp>
#include <pc/core/plot_model.hpp>

namespace qrterm {

// The plot's traces travel as this stream; the QR has room for more (other clients, later screens).
inline constexpr uint8_t kPlotStream = 0;
// A table with rows missing is asked for again this often.
inline constexpr uint32_t kTableRetryMs = 2000;

class StreamSession {
 public:
  struct Hooks {
    std::function<void(Severity, const std::string&)> note;
    std::function<std::unique_ptr<std::ostream>(const std::string& name)> open;  // a file in the log folder
  };
  explicit StreamSession(Hooks hooks) : hooks_(std::move(hooks)) {}

  // --- the wire
  void on(const wire::ObservableInfo& m) { catalog_.on(m); }
  void on(const wire::ObservableText& m) { catalog_.on(m); }
  void on(const wire::ObservableSamples& m, double now_s);
  // An answer to observable_get or stream_request (reason none: ack).
  void on_answer(wire::MessageType type, wire::NackReason reason, uint32_t telemetry_hz);
  // observable_get went unanswered: a firmware without streams. Not asked again until the link
  // comes up anew.
  void table_unanswered();
  // The link came up (again): the QR may be a new one.
  void link_up();
  // Asks for the table while rows are missing, and for the selection when it changed.
  void tick(LinkSession& link, uint32_t now_ms);

  // --- the pilot
  // Adds the observables named in `names` (separated by spaces), as many as fit.
  void pick(const std::string& names);
  void remove_last();
  void faster();
  void slower();

  // --- the screen
  const ObservableCatalog& catalog() const { return catalog_; }
  const PlotModel& plot() const { return plot_; }
  PlotModel& plot() { return plot_; }
  // "3 x 200 Hz = 600 samples/s: 2400 of 8370 B/s": the selection's cost beside the room.
  std::string cost_text(uint32_t telemetry_hz) const;
  // "streaming", "asking the QR", "refused: ...", "no table yet (12/31)".
  const std::string& state() const { return state_; }
  uint32_t samples_received() const { return received_; }
  uint32_t samples_lost() const { return unpacker_.lost(); }
  // Arrival to the last sample's time on the screen is the screen's business; this is when the
  // newest samples arrived (console seconds), for the latency figure.
  double last_arrival_s() const { return last_arrival_s_; }

 private:
  void selection_changed();
  void open_csv();

  Hooks hooks_;
  ObservableCatalog catalog_;
  PlotModel plot_;
  wire::SampleUnpacker unpacker_;
  std::optional<wire::StreamRequest> asked_;  // sent, not answered yet
  bool request_owed_ = false;                 // the selection or rate changed since the last request
  bool streaming_ = false;                    // the QR acked the current selection
  bool table_owed_ = true;
  uint32_t table_asked_ms_ = 0;
  bool table_asked_ = false;
  bool table_given_up_ = false;
  std::string state_ = "no table yet";
  uint32_t received_ = 0;
  double last_arrival_s_ = 0;
  int csv_count_ = 0;
  uint32_t flushed_ms_ = 0;
  std::unique_ptr<std::ostream> csv_file_;
  std::optional<CsvWriter> csv_;
};

}  // namespace qrterm
