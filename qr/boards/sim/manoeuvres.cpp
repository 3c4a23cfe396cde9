#include <qr/boards/sim/manoeuvres.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include <qr/core/chain/pilot_setpoints.hpp>

namespace qrsim {
namespace {

constexpr double kRad = std::numbers::pi / 180;

int16_t stick(double value) { return static_cast<int16_t>(std::clamp(std::lround(value), -1000L, 1000L)); }

bool holding(const ManoeuvreStep& m) { return m.since < m.spec.hold_s; }

// Full control: roll and pitch sticks are angle set-points, full stick the max_tilt_mrad parameter.
double stick_per_degree(const ManoeuvreStep& m) {
  return kRad * 1000 / (m.parameters.get(wire::ParamId::max_tilt_mrad) * 1e-3);
}

void hover(ManoeuvreStep&) {}

void roll_step(ManoeuvreStep& m) {
  if (holding(m)) m.sticks.roll = stick(m.spec.amount * stick_per_degree(m));
}

void pitch_step(ManoeuvreStep& m) {
  if (holding(m)) m.sticks.pitch = stick(m.spec.amount * stick_per_degree(m));
}

// Yaw stick: full stick is the max_yaw_rate parameter (Q10 rad/s).
void yaw_rate_step(ManoeuvreStep& m) {
  const double max_rate = std::ldexp(m.parameters.get(wire::ParamId::max_yaw_rate_rad_s), -10);
  m.sticks.yaw = stick(m.spec.amount / max_rate * 1000);
}

// A push on the airframe, not a pilot's input: roll and pitch torque for hold_s.
void torque_impulse(ManoeuvreStep& m) {
  const double torque = holding(m) ? m.spec.amount : 0;
  m.plant.set_disturbance({torque, torque, 0}, {});
}

void link_loss(ManoeuvreStep& m) { m.pilot.go_silent(true); }

void panic_request(ManoeuvreStep& m) {
  if (m.first) m.pilot.request_mode(wire::Mode::panic);
  m.sticks.lift = 0;  // after an emergency stop the pilot lets go of the lift
}

struct Row {
  Manoeuvre kind;
  void (*fly)(ManoeuvreStep&);
};

// In Manoeuvre order.
constexpr Row kRows[] = {
    {Manoeuvre::none, hover},
    {Manoeuvre::roll_step, roll_step},
    {Manoeuvre::pitch_step, pitch_step},
    {Manoeuvre::yaw_rate_step, yaw_rate_step},
    {Manoeuvre::torque_impulse, torque_impulse},
    {Manoeuvre::link_loss, link_loss},
    {Manoeuvre::panic_request, panic_request},
};

constexpr bool rows_in_order() {
  for (size_t i = 0; i < std::size(kRows); ++i) {
    if (static_cast<size_t>(kRows[i].kind) != i) return false;
  }
  return true;
}
static_assert(rows_in_order(), "one row per Manoeuvre, in its order");

}  // namespace

void fly_manoeuvre(ManoeuvreStep& step) { kRows[static_cast<size_t>(step.spec.manoeuvre)].fly(step); }

}  // namespace qrsim
