// The descent warning: a vehicle flying down faster than it can stop before the ground. A pilot
// flying by hand set the lift 15 below the hover and fell at 5.7 m/s into the ground with nothing
// on the screen to say so; this rule tells while there is still height to stop in.
//
// From the QR's height estimate h (m above where it was calibrated: the ground it took off from)
// and its climb rate v (m/s, up), it warns when the vehicle flies, descends faster than a safe
// touchdown (v < -kSafeTouchdownMS), and either
//   - the height it needs to stop reaches h: |v| kReactionS (the descent while the pilot sees,
//     decides and presses) + v^2 / (2 a) (braking at the acceleration a the engines can spare) +
//     kMarginM, or
//   - it is within kNearGroundM of the ground (it would touch down too fast however early the
//     pilot acts).
// a comes from the hover lift the QR learnt: the lift stick is per mille of the engines' speed and
// thrust goes with speed squared, so full lift (1000) carries (1000 / hover)^2 times the weight
// and spares g ((1000 / hover)^2 - 1) upwards; the rule counts on kSpareShare of that. Before the
// QR has learnt its hover the conservative kUnknownSpareMS2 stands in. docs/console.md ("The
// descent warning") gives the reasons for each figure.
//
// DescentWatch keeps the warning standing over the reports: it rises with one log line that says
// what the pilot can do, and holds a moment after the rule is clear.
#pragma once

#include <stdint.h>

#include <optional>
#include <string>

#include <common/telemetry.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

inline constexpr double kGravityMS2 = 9.81;
// The landings the simulator's scenarios call good touch down below 1 m/s (docs/simulator.md):
// slower than this a descent is a landing, and never warns.
inline constexpr double kSafeTouchdownMS = 1.0;
// Within this of the ground a descent faster than a safe touchdown warns whatever the engines
// could still do.
inline constexpr double kNearGroundM = 3.0;
// The pilot reads the warning, decides and presses PgUp: a second of descent goes by before the
// engines change anything (the height report comes every 120 ms at the default telemetry rate,
// inside it).
inline constexpr double kReactionS = 1.0;
// What the vehicle should still have under it once stopped: the height estimate's error over a
// flight (the barometer) and the landing gear.
inline constexpr double kMarginM = 1.0;
// Half of full lift's spare thrust: the pilot does not reach full lift at once (PgUp adds 100 a
// press), near full lift the mixer gives the lift away to keep the attitude, and the hover the QR
// learnt may be up to 10 % of thrust low (qr/core/chain/landed_detector.hpp).
inline constexpr double kSpareShare = 0.5;
// Before the QR has learnt its hover: what a vehicle that hovers at about 840 of 1000 spares at
// kSpareShare, so any vehicle that hovers lower is credited with less than it has.
inline constexpr double kUnknownSpareMS2 = 2.0;

enum class DescentDanger : uint8_t {
  none,
  cannot_stop,   // the height it needs to stop reaches the height it has
  too_fast_low,  // near the ground, faster than a safe touchdown
};

struct DescentVerdict {
  bool warn = false;
  DescentDanger danger = DescentDanger::none;  // why it warns (cannot_stop when both hold)
  double spare_m_s2 = 0;                       // the upward acceleration counted on
  double needed_m = 0;  // height the descent needs to stop: reaction + braking + margin (infinite: cannot)
};

// The upward acceleration counted on to stop a descent, m/s^2, from the hover lift (0..1000 in the
// lift stick's scale; 0: not learnt yet).
double spare_acceleration_m_s2(uint16_t hover_lift);

// The rule above. height_m and climb_m_s are the QR's estimates; flying is its flying/landed
// verdict (telemetry flag kFlagFlying).
DescentVerdict judge_descent(double height_m, double climb_m_s, uint16_t hover_lift, bool flying);

// The descent warning stays up until its rule has been clear for this long: a climb rate that
// wavers about the threshold does not make it blink, nor write a log line at each blink.
inline constexpr uint32_t kSinkingHoldMs = 1000;

class DescentWatch {
 public:
  // A height report, judged with the telemetry that holds it (the flying flag, the mode, who
  // flies) and whether the console flies the simulator. Returns the log line when the warning
  // rises; empty otherwise.
  std::string on_height(const wire::TelemetryHeight& height, const TelemetryModel& telemetry, bool simulator,
                        uint32_t now_ms);
  // While the warning stands: the descent speed now, m/s, down.
  std::optional<double> speed_m_s() const;

 private:
  struct Sinking {
    double speed_m_s;       // down, the latest report's
    uint32_t last_warn_ms;  // the last report whose verdict warned
  };
  std::optional<Sinking> sinking_;
};

// The QR is in panic: the sticks do nothing, so the warning asks for no lift.
bool sinking_in_panic(const TelemetryModel& telemetry);

}  // namespace qrterm
