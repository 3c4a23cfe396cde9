// The console's side of observable streams (docs/protocol.md section 13): it learns the QR's
// observable table at connect and asks the QR's four streams for what the screens show: the
// plot's selection as stream 0, or, while the radio screen is open, the radio's sixteen channels
// (rc_ch1..rc_ch16) as all four, four channels each (section 13.5; the plot's stream waits). One
// stream_request is out at a time (the resend queue holds one request of a type), and a stream is
// asked again only when what it should carry changes. The plot's samples go into the PlotModel
// and to a CSV in the log folder (a new file for each selection, units in the column names), the
// radio's into the RadioSetup. The cost of a selection is shown before it is asked for; the QR
// has the last word (nack over_budget). While a log download runs, the plot's stream is lowered so
// that the download keeps its share of the line, and restored when it ends (section 13.6).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <common/observable_messages.hpp>
#include <common/sample_packing.hpp>
#include <common/stream_budget.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/csv_writer.hpp>
#include <pc/core/link_session.hpp>
#include <pc/core/observable_catalog.hpp>
#include <pc/core/plot_model.hpp>
#include <pc/core/radio_setup.hpp>

namespace qrterm {

// The plot's traces travel as this stream; the radio screen takes all of them while it is open.
inline constexpr uint8_t kPlotStream = 0;
inline constexpr uint8_t kStreams = wire::kStreamCount;
static_assert(kStreams * wire::kStreamObservablesMax == kRadioChannels, "four streams of four carry the channels");
// A table with rows missing is asked for again this often.
inline constexpr uint32_t kTableRetryMs = 2000;
// What the plot's stream may take of the line while a log download runs (docs/protocol.md section
// 13.6): a tenth of it. The download's parts get the line the telemetry leaves, about 9400 B/s at
// 50 Hz, so it keeps nearly nine tenths of its rate on a quiet line; `phi phi_sp` at 1000 Hz
// (6000 B/s) left it a third.
inline constexpr uint32_t kDownloadStreamBytesPerS = wire::kLineBytesPerS / 10;

// A stream as the console wants the QR to run it: these observables, in sample order, every
// `divider` control periods; divider 0 and no observables: stopped.
struct StreamPlan {
  std::vector<uint8_t> ids;
  uint16_t divider = 0;
  bool operator==(const StreamPlan&) const = default;
};

class StreamSession {
 public:
  struct Hooks {
    std::function<void(Severity, const std::string&)> note;
    std::function<std::unique_ptr<std::ostream>(const std::string& name)> open;  // a file in the log folder
    // A sample of the stream carried for autotune: its observables (the ids asked for), its
    // number in the stream (control periods at divider 1, lost samples counted), the values.
    std::function<void(const std::vector<uint8_t>& ids, uint32_t index, const std::vector<double>& values)> carried;
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
  // stream_request went unanswered: asked again when what a stream should carry changes, or the
  // link comes up anew.
  void stream_unanswered();
  // The link came up (again): the QR may be a new one.
  void link_up();
  // Asks for the table while rows are missing, and for a stream whose plan changed.
  void tick(LinkSession& link, uint32_t now_ms);

  // --- the radio screen: opening it starts its RadioSetup (ends counted from then) and gives it
  // the four streams; closing it gives stream 0 back to the plot and stops the others.
  void open_radio();
  void close_radio();
  const RadioSetup& radio() const { return radio_; }
  RadioSetup& radio() { return radio_; }
  // "16 channels at 25 Hz", "asking the QR (2 of 4 streams)", "refused: over_budget", ...
  const std::string& radio_state() const { return radio_state_; }
  // The QR runs the four streams as the radio screen asked.
  bool radio_streaming() const { return radio_streaming_; }

  // --- autotune (identification_recorder.hpp): while `ids` is not empty, stream 0 carries them
  // at the control rate in the plot's place (its traces wait, as for the radio screen), and the
  // samples go to the carried hook; empty gives stream 0 back to the plot.
  void carry(const std::vector<uint8_t>& ids) { carried_ = ids; }
  const std::vector<uint8_t>& carried() const { return carried_; }

  // --- a log download: while one runs, the plot's stream is asked for at the fastest of the
  // plot's rates that costs at most kDownloadStreamBytesPerS, and at the pilot's rate again after
  // (the radio's channels and autotune's identification are left as they are). Said in the log.
  void download_running(bool running);
  // The plot's stream runs slower than the pilot chose, for a download.
  bool lowered() const;

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
  uint32_t samples_lost() const { return unpackers_[kPlotStream].lost(); }
  // Arrival to the last sample's time on the screen is the screen's business; this is when the
  // newest samples arrived (console seconds), for the latency figure.
  double last_arrival_s() const { return last_arrival_s_; }

 private:
  void selection_changed();
  void open_csv();
  // The radio's channels' rows in the QR's table, once it has all sixteen.
  bool radio_streams() const { return radio_open_ && rc_ids_.has_value(); }
  StreamPlan wanted(uint8_t stream) const;
  // The divider the plot's stream is asked for at: the pilot's, or lowered during a download.
  uint16_t plot_divider() const;
  // The plot's rate at `divider`, as the pilot reads it: "100 Hz".
  std::string plot_rate(uint16_t divider) const;
  void ask(LinkSession& link, uint8_t stream, const StreamPlan& plan, uint32_t now_ms);
  void answered(uint8_t stream, const StreamPlan& plan, wire::NackReason reason, uint32_t telemetry_hz);
  void on_plot_samples(const wire::ObservableSamples& m, double now_s);
  void on_carried_samples(const wire::ObservableSamples& m);
  void note_radio_state();

  Hooks hooks_;
  ObservableCatalog catalog_;
  PlotModel plot_;
  RadioSetup radio_;
  bool radio_open_ = false;
  std::vector<uint8_t> carried_;                // autotune's pair; empty: the plot has stream 0
  std::optional<std::vector<uint8_t>> rc_ids_;  // rc_ch1..rc_ch16's ids in the QR's table
  std::string radio_state_ = "no table yet";
  bool radio_streaming_ = false;
  wire::SampleUnpacker unpackers_[kStreams];
  StreamPlan asked_[kStreams];                               // the last plan asked for, answered or not
  StreamPlan running_[kStreams];                             // the last plan the QR acked
  std::optional<std::pair<uint8_t, StreamPlan>> in_flight_;  // sent, not answered yet
  bool stalled_ = false;                                     // a request went unanswered
  bool download_ = false;                                    // a log download runs
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
