// Test mode, one tick at a time: what the replay runs for each recorded sample, and the columns
// it reports. Shared by the host replay (qr/tools/replay.cpp) and the devboard's
// (qr/boards/rv32virt/replay_main.cpp), so both write the same CSV, bit for bit.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/mode.hpp>
#include <qr/core/board.hpp>
#include <qr/core/safety.hpp>

namespace qr::chain {

// The tick as the flight task sets run it: calibration until it is done, then full control.
// Returns the mode the tick ran in.
template <class Chain>
wire::Mode replay_tick(Chain& chain, const SensorSample& sample, const ControlInput& sticks, bool& calibrated) {
  chain.set_pilot(sticks);
  chain.filter(sample);
  if (!calibrated) {
    calibrated = chain.calibrate();
    return wire::Mode::calibration;
  }
  chain.estimate();
  chain.control_attitude();
  chain.control_yaw();
  chain.mix();
  return wire::Mode::full_control;
}

template <class Chain>
struct ReplayColumn {
  const char* name;
  int32_t (*value)(const Chain&);
};

// The output columns after time_us and mode, in the order the host/devboard checksum folds them
// (tests/chain/chain_checksum.hpp), so a replay's output can be checked against it.
template <class Chain>
inline constexpr ReplayColumn<Chain> kReplayColumns[] = {
    {"roll_e4", [](const Chain& c) -> int32_t { return c.roll_e4(); }},
    {"pitch_e4", [](const Chain& c) -> int32_t { return c.pitch_e4(); }},
    {"yaw_e4", [](const Chain& c) -> int32_t { return c.yaw_e4(); }},
    {"p_e3", [](const Chain& c) -> int32_t { return c.p_e3(); }},
    {"q_e3", [](const Chain& c) -> int32_t { return c.q_e3(); }},
    {"r_e3", [](const Chain& c) -> int32_t { return c.r_e3(); }},
    {"roll_sp_e4", [](const Chain& c) -> int32_t { return c.roll_setpoint_e4(); }},
    {"pitch_sp_e4", [](const Chain& c) -> int32_t { return c.pitch_setpoint_e4(); }},
    {"yaw_rate_sp_e3", [](const Chain& c) -> int32_t { return c.yaw_rate_setpoint_e3(); }},
    {"p_sp_e3", [](const Chain& c) -> int32_t { return c.p_setpoint_e3(); }},
    {"q_sp_e3", [](const Chain& c) -> int32_t { return c.q_setpoint_e3(); }},
    {"tilt_mrad", [](const Chain& c) -> int32_t { return c.tilt_mrad(); }},
    {"roll_acc_e4", [](const Chain& c) -> int32_t { return c.roll_from_accel_e4(); }},
    {"pitch_acc_e4", [](const Chain& c) -> int32_t { return c.pitch_from_accel_e4(); }},
    {"p_bias_e6", [](const Chain& c) -> int32_t { return c.p_bias_e6(); }},
    {"q_bias_e6", [](const Chain& c) -> int32_t { return c.q_bias_e6(); }},
    {"gyro_f_x", [](const Chain& c) -> int32_t { return c.gyro_filtered(0); }},
    {"gyro_f_y", [](const Chain& c) -> int32_t { return c.gyro_filtered(1); }},
    {"gyro_f_z", [](const Chain& c) -> int32_t { return c.gyro_filtered(2); }},
    {"accel_f_x", [](const Chain& c) -> int32_t { return c.accel_filtered(0); }},
    {"accel_f_y", [](const Chain& c) -> int32_t { return c.accel_filtered(1); }},
    {"accel_f_z", [](const Chain& c) -> int32_t { return c.accel_filtered(2); }},
    {"moment_roll_e3", [](const Chain& c) -> int32_t { return c.moments_e3().roll; }},
    {"moment_pitch_e3", [](const Chain& c) -> int32_t { return c.moments_e3().pitch; }},
    {"moment_yaw_e3", [](const Chain& c) -> int32_t { return c.moments_e3().yaw; }},
    {"applied_roll_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().roll; }},
    {"applied_pitch_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().pitch; }},
    {"applied_yaw_e3", [](const Chain& c) -> int32_t { return c.applied_moments_e3().yaw; }},
    {"ae0", [](const Chain& c) -> int32_t { return c.engines().value[0]; }},
    {"ae1", [](const Chain& c) -> int32_t { return c.engines().value[1]; }},
    {"ae2", [](const Chain& c) -> int32_t { return c.engines().value[2]; }},
    {"ae3", [](const Chain& c) -> int32_t { return c.engines().value[3]; }},
    {"calibrated", [](const Chain& c) -> int32_t { return c.calibrated() ? 1 : 0; }},
};

}  // namespace qr::chain
