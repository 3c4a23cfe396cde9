// The pre-flight every runner's pilot flies before its own work (issue 31): the sensors settle
// after power-up, the pilot uploads its parameters, the QR calibrates on the ground, and the
// pilot arms full control. The scenario and the soak once wrote it each for itself; what they
// still do differently is said in the plan, so that neither flight's figures moved when they
// came to share it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <utility>
#include <vector>

#include <common/mode.hpp>
#include <common/parameter_table.hpp>

namespace qrsim {

class Pilot;

struct PreflightPlan {
  // Uploaded in this order once the sensors have settled, before calibration: a calibration
  // taken with the flight's own parameters.
  std::vector<std::pair<wire::ParamId, int32_t>> parameters;
  // The pilot flies through a radio (qrsim --rc crsf): the QR's pilot parameter says so, uploaded
  // after the others, and the pilot's sticks go out on the radio from then on.
  bool radio = false;
  // When the pilot asks for calibration: in the control period that uploads the parameters (the
  // soak's pilot) or in the next one (the scenario's). The two runners grew apart by this one
  // period; each keeps its own so that no recorded flight moved.
  bool calibrate_with_upload = false;
  // The telemetry log starts as the pilot arms (the soak logs its whole flight and downloads it).
  bool log_from_arming = false;
  // False: the pre-flight ends calibrated in safe, on the ground and unarmed (a scenario's
  // "start: safe", which arms a mode of its own).
  bool arm = true;
};

class Preflight {
 public:
  // refused: the QR ended the calibration without taking it (its debug text says why: a vehicle
  // not level, an IMU mounted otherwise, docs/safety.md rule 21), or refused to begin it (a NACK:
  // an IMU not healthy, rule 20); the pre-flight goes no further.
  enum class Stage : uint8_t { power_up, calibrate, arm, ready, refused };

  explicit Preflight(PreflightPlan plan) : plan_(std::move(plan)) {}

  // One control period, before the pilot's step. `mode`: the QR's mode as the runner judges it
  // (the scenario's pilot by the console's telemetry, the soak by the firmware, which its
  // referee watches). True once the QR is ready: armed in full control, or calibrated in safe
  // when the plan does not arm.
  bool step(double t, wire::Mode mode, Pilot& pilot);

  Stage stage() const { return stage_; }
  bool refused() const { return stage_ == Stage::refused; }
  // For a runner's "stuck in ..." error: "power up", "calibration", "arming" (the stage not left).
  const char* stage_name() const;
  // The last mode the pre-flight asked for (safe: none yet), for a referee of mode changes.
  wire::Mode requested() const { return requested_; }

 private:
  void upload(Pilot& pilot) const;
  void ask(wire::Mode mode, Pilot& pilot);
  bool calibrated_on_ground(wire::Mode mode, const Pilot& pilot) const;
  bool calibration_refused(wire::Mode mode, const Pilot& pilot) const;

  PreflightPlan plan_;
  Stage stage_ = Stage::power_up;
  wire::Mode requested_ = wire::Mode::safe;
  bool calibration_asked_ = false;
  bool calibrating_seen_ = false;  // telemetry showed the calibration mode
  size_t text_at_ask_ = 0;         // the QR's debug text so far when the calibration was asked for
  uint32_t nacks_at_ask_ = 0;      // and the NACKs the pilot had had
};

}  // namespace qrsim
