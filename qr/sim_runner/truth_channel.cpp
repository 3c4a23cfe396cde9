#include <qr/sim_runner/truth_channel.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <qr/sim_runner/text_fields.hpp>
#include <sim/quaternion.hpp>

namespace qrsim {
namespace {

// "radio arm MODE" for the modes the radio's arm switch arms, by their mode switch position (the
// mode table's column, wire::mode_at_switch), or "radio off".
bool parse_radio_command(const std::vector<std::string>& words, TruthCommand& command, std::string& error) {
  if (words.size() == 2 && words[1] == "off") {
    command = TruthCommand{.kind = TruthCommand::Kind::radio_off};
    return true;
  }
  for (uint8_t position = 0; position < wire::kModeSwitchPositions; ++position) {
    const wire::Mode mode = wire::mode_at_switch(position);
    if (words.size() == 3 && words[1] == "arm" && words[2] == wire::mode_key(mode)) {
      command = TruthCommand{.kind = TruthCommand::Kind::radio_arm, .mode = mode};
      return true;
    }
  }
  error = "radio takes";
  for (uint8_t position = 0; position < wire::kModeSwitchPositions; ++position) {
    error += std::string(position == 0 ? " 'arm " : ", 'arm ") + wire::mode_key(wire::mode_at_switch(position)) + "'";
  }
  error += " or 'off'";
  return false;
}

// "turn AXIS N SECONDS", N a whole number of turns.
bool parse_turn_command(const std::vector<std::string>& words, TruthCommand& command, std::string& error) {
  sim::HandTurnSpec spec;
  double turns = 0;
  if (words.size() != 4) {
    error = "turn needs AXIS N SECONDS (AXIS x, y or z; N whole turns)";
  } else if (!sim::body_axis_from_text(words[1], spec.axis)) {
    error = "turn: axis is x, y or z, not '" + words[1].substr(0, 40) + "'";
  } else if (!parse_real(words[2], turns) || !parse_real(words[3], spec.seconds)) {
    error = "turn: bad number in '" + words[2].substr(0, 40) + " " + words[3].substr(0, 40) + "'";
  } else {
    spec.turns = sim::whole_turns(turns);
    const std::string problem = sim::hand_turn_problem(spec);
    if (problem.empty()) {
      command = TruthCommand{.kind = TruthCommand::Kind::turn, .turn = spec};
      return true;
    }
    error = "turn: " + problem;
  }
  return false;
}

// "tilt AXIS DEG SECONDS", DEG within +-90.
bool parse_tilt_command(const std::vector<std::string>& words, TruthCommand& command, std::string& error) {
  sim::HandTiltSpec spec;
  if (words.size() != 4) {
    error = "tilt needs AXIS DEG SECONDS (AXIS x, y or z)";
  } else if (!sim::body_axis_from_text(words[1], spec.axis)) {
    error = "tilt: axis is x, y or z, not '" + words[1].substr(0, 40) + "'";
  } else if (!parse_real(words[2], spec.degrees) || !parse_real(words[3], spec.seconds)) {
    error = "tilt: bad number in '" + words[2].substr(0, 40) + " " + words[3].substr(0, 40) + "'";
  } else {
    const std::string problem = sim::hand_tilt_problem(spec);
    if (problem.empty()) {
      command = TruthCommand{.kind = TruthCommand::Kind::tilt, .tilt = spec};
      return true;
    }
    error = "tilt: " + problem;
  }
  return false;
}

}  // namespace

bool parse_truth_command(std::string_view line, TruthCommand& push, std::string& error) {
  const std::vector<std::string> words = words_of(line);
  if (words.empty()) {
    error = "empty command";
    return false;
  }
  if (words[0] == "reset") {
    if (words.size() != 1) {
      error = "reset takes nothing after it";
      return false;
    }
    push = TruthCommand{.kind = TruthCommand::Kind::reset};
    return true;
  }
  if (words[0] == "radio") return parse_radio_command(words, push, error);
  if (words[0] == "turn") return parse_turn_command(words, push, error);
  if (words[0] == "tilt") return parse_tilt_command(words, push, error);
  if (words[0] != "push") {
    error = "unknown command '" + words[0].substr(0, 40) +
            "' (push TX TY TZ SECONDS, reset, turn AXIS N SECONDS, tilt AXIS DEG SECONDS, radio arm MODE, radio off)";
    return false;
  }
  if (words.size() != 5) {
    error = "push needs TX TY TZ SECONDS";
    return false;
  }
  double v[4] = {};
  for (size_t i = 0; i < 4; ++i) {
    if (!parse_real(words[i + 1], v[i])) {
      error = "bad number '" + words[i + 1].substr(0, 40) + "'";
      return false;
    }
  }
  for (size_t i = 0; i < 3; ++i) {
    if (std::fabs(v[i]) > 10) {
      error = "torque beyond 10 N m";
      return false;
    }
  }
  if (v[3] <= 0 || v[3] > 10) {
    error = "seconds must be in (0, 10]";
    return false;
  }
  push.kind = TruthCommand::Kind::push;
  push.torque = sim::Vec3{v[0], v[1], v[2]};
  push.seconds = v[3];
  return true;
}

sim::PlantState reset_state(const sim::PlantState& now) {
  sim::PlantState state;
  state.position = sim::Vec3{now.position.x, now.position.y, 0};
  state.attitude = sim::from_euler(sim::Euler{0, 0, sim::to_euler(now.attitude).yaw});
  return state;
}

std::string truth_line(double t_s, const sim::Quadrotor& plant) {
  const sim::PlantState& state = plant.state();
  const sim::Euler e = sim::to_euler(state.attitude);
  constexpr double kDeg = 57.29577951308232;
  double turning[sim::kRotorCount] = {};
  // To the 0.1 rad/s printed, and + 0.0: a still counter-clockwise rotor reads 0.0, not -0.0.
  for (size_t i = 0; i < sim::kRotorCount; ++i) {
    turning[i] = std::round(state.rotor_speed[i] * plant.rotors()[i].spin * 10) / 10 + 0.0;
  }
  char text[256];
  std::snprintf(text, sizeof text,
                "truth t=%.3f roll=%.2f pitch=%.2f yaw=%.2f height=%.3f north=%.3f east=%.3f climb=%.3f "
                "rotors=%.1f,%.1f,%.1f,%.1f\n",
                t_s, e.roll * kDeg, e.pitch * kDeg, e.yaw * kDeg, -state.position.z, state.position.x, state.position.y,
                -state.velocity.z, turning[0], turning[1], turning[2], turning[3]);
  return text;
}

std::string devboard_line(double t_s, uint32_t core_mhz, double tick_instr_mean, uint32_t tick_instr_max,
                          uint32_t ticks) {
  char text[128];
  std::snprintf(text, sizeof text, "devboard t=%.3f core_mhz=%u tick_instr_mean=%.0f tick_instr_max=%u ticks=%u\n", t_s,
                static_cast<unsigned>(core_mhz), tick_instr_mean, static_cast<unsigned>(tick_instr_max),
                static_cast<unsigned>(ticks));
  return text;
}

}  // namespace qrsim
