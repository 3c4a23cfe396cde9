// Fuzz target: arbitrary lines into the simulator's truth channel (qrsim --truth-fd,
// qr/sim_runner/truth_channel.cpp). Beyond what ASan and UBSan catch: a refused line says why; an
// accepted push is finite and within the channel's bounds (10 N m, 10 s); an accepted turn keeps
// the hand turn's limits (sim/hand_turn.hpp), an accepted tilt the hand tilt's (sim/hand_tilt.hpp);
// an accepted radio arm names a mode the radio's arm switch arms.
#include <stddef.h>
#include <stdint.h>

#include <cmath>
#include <string>
#include <string_view>

#include <qr/sim_runner/truth_channel.hpp>

#include "fuzz_checks.hpp"

using fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  qrsim::TruthCommand push;
  std::string error;
  if (!qrsim::parse_truth_command(line, push, error)) {
    require(!error.empty());
    return 0;
  }
  if (push.kind == qrsim::TruthCommand::Kind::reset || push.kind == qrsim::TruthCommand::Kind::radio_off) return 0;
  if (push.kind == qrsim::TruthCommand::Kind::turn) {
    require(sim::hand_turn_problem(push.turn).empty() && push.turn.turns != 0);
    return 0;
  }
  if (push.kind == qrsim::TruthCommand::Kind::tilt) {
    require(sim::hand_tilt_problem(push.tilt).empty() && std::isfinite(push.tilt.degrees) && push.tilt.degrees != 0 &&
            std::fabs(push.tilt.degrees) <= 90);
    return 0;
  }
  if (push.kind == qrsim::TruthCommand::Kind::radio_arm) {
    require(wire::flies(push.mode) && push.mode != wire::Mode::height_hold);  // what an arm switch can arm
    return 0;
  }
  for (const double t : {push.torque.x, push.torque.y, push.torque.z}) require(std::isfinite(t) && std::fabs(t) <= 10);
  require(std::isfinite(push.seconds) && push.seconds > 0 && push.seconds <= 10);
  return 0;
}
