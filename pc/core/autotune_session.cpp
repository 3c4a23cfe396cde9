#include <pc/core/autotune_session.hpp>

#include <chrono>
#include <optional>

#include <tune/report_json.hpp>

namespace qrterm {

void AutotuneSession::on_attitude(const wire::TelemetryAttitude& attitude, uint32_t telemetry_hz, uint32_t control_hz,
                                  const wire::ParameterValues& flown, uint32_t now_ms) {
  const IdentificationRecorder::State before = recorder_.state();
  recorder_.set_control_hz(control_hz);
  recorder_.on_mode(attitude.mode, attitude.tick, telemetry_hz, now_ms);
  if (before != IdentificationRecorder::State::recording &&
      recorder_.state() == IdentificationRecorder::State::recording) {
    flown_ = flown;
    control_hz_ = control_hz;
    note_(Severity::info, "autotune: recording the identification (roll, pitch, yaw; 9.1 s)");
  }
  after(before);
}

void AutotuneSession::tick(StreamSession& streams, uint32_t now_ms) {
  if (designing_.valid() && designing_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    proposal_.take(designing_.get(), flown_);
    if (proposal_.standing() == AutotuneProposal::Standing::refused) {
      note_(Severity::warning, proposal_.why());
    } else {
      // The models in the log as qrsim --autotune prints them, to hold one flight against the other.
      const tune::IdentificationDesign& d = *proposal_.design();
      for (size_t axis = 0; axis < 3; ++axis) {
        note_(Severity::info,
              std::string("autotune: ") + tune::kAxisNames[axis] + " model " + tune::model_json(d.models[axis]));
      }
      note_(Severity::info, "autotune: new gains on the parameter screen (^T takes them)");
    }
  }
  const std::optional<size_t> axis = recorder_.streamed_axis(now_ms);
  if (!axis) {
    if (!streams.carried().empty()) streams.carry({});
    return;
  }
  std::vector<uint8_t>& pair = pairs_[*axis];
  if (pair.empty()) {
    const std::optional<uint8_t> moment = streams.catalog().find(kAxisPairs[*axis].moment);
    const std::optional<uint8_t> rate = streams.catalog().find(kAxisPairs[*axis].rate);
    if (!moment || !rate) return;  // the table is not complete yet: the record will be short
    pair = {*moment, *rate};
  }
  if (streams.carried() != pair) streams.carry(pair);
}

void AutotuneSession::on_carried(const std::vector<uint8_t>& ids, uint32_t index, const std::vector<double>& values) {
  if (values.size() < 2) return;
  const IdentificationRecorder::State before = recorder_.state();
  for (size_t axis = 0; axis < 3; ++axis) {
    if (pairs_[axis] == ids) recorder_.on_sample(axis, index, values[0], values[1]);
  }
  after(before);
}

void AutotuneSession::after(IdentificationRecorder::State before) {
  const IdentificationRecorder::State now = recorder_.state();
  if (now == before) return;
  if (now == IdentificationRecorder::State::failed) {
    proposal_.refuse("autotune: " + recorder_.why());
    note_(Severity::warning, proposal_.why());
  } else if (now == IdentificationRecorder::State::recorded) {
    note_(Severity::info, "autotune: recorded; fitting and designing");
    designing_ = std::async(std::launch::async, &AutotuneProposal::compute, recorder_.records(), flown_,
                            static_cast<double>(control_hz_));
    recorder_.clear();
  }
}

void AutotuneSession::accept(ParameterSync& parameters) {
  if (!proposal_.accept(parameters)) return note_(Severity::warning, "autotune: no new gains to take (= flies it)");
  note_(Severity::info, "autotune: the new gains sent");
}

void AutotuneSession::back(ParameterSync& parameters) {
  if (!proposal_.back(parameters)) return note_(Severity::warning, "autotune: no gains to go back to");
  note_(Severity::info, "autotune: the gains before sent again");
}

}  // namespace qrterm
