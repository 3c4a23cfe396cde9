// The console's part of autotune (issue 34): from the QR's first report in mode autotune it
// records the identification (IdentificationRecorder: stream 0 carries the excited axis' moment
// and rate, the plot's selection waits and comes back after), then fits and designs with tune/
// (AutotuneProposal), and the parameter screen shows the gains flown beside the new ones with
// their figures; the pilot takes the new gains or goes back (docs/console.md, "Autotune").
#pragma once

#include <stdint.h>

#include <functional>
#include <future>
#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <common/telemetry.hpp>
#include <pc/core/autotune_proposal.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/identification_recorder.hpp>
#include <pc/core/parameter_sync.hpp>
#include <pc/core/stream_session.hpp>

namespace qrterm {

class AutotuneSession {
 public:
  using Note = std::function<void(Severity, const std::string&)>;
  explicit AutotuneSession(Note note) : note_(std::move(note)) {}

  // Every attitude report. `flown`: the parameters in force (what the design starts from).
  void on_attitude(const wire::TelemetryAttitude& attitude, uint32_t telemetry_hz, uint32_t control_hz,
                   const wire::ParameterValues& flown, uint32_t now_ms);
  // Points stream 0 at the pair the recorder wants now, or gives it back to the plot; takes the
  // design once it is done.
  void tick(StreamSession& streams, uint32_t now_ms);
  // A sample of the carried stream (StreamSession's carried hook).
  void on_carried(const std::vector<uint8_t>& ids, uint32_t index, const std::vector<double>& values);

  // The parameter screen's keys: the new gains, or those flown before, to the QR.
  void accept(ParameterSync& parameters);
  void back(ParameterSync& parameters);

  const AutotuneProposal& proposal() const { return proposal_; }
  const IdentificationRecorder& recorder() const { return recorder_; }

 private:
  // Acts on the recorder's change of state: a refusal or a record to fit.
  void after(IdentificationRecorder::State before);

  Note note_;
  IdentificationRecorder recorder_;
  AutotuneProposal proposal_;
  wire::ParameterValues flown_;
  uint32_t control_hz_ = 1000;
  std::vector<uint8_t> pairs_[3];
  std::future<AutotuneProposal::Outcome>
      designing_;  // the fit and design, off the console's loop  // each axis' moment and rate ids in the QR's table, once looked up
};

}  // namespace qrterm
