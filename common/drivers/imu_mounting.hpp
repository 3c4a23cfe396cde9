// How the IMU's board sits in the frame (parameter imu_orientation), so a board mounted turned or
// upside down flies once the orientation check (docs/console.md, "First flight") has found it:
// the sample, in the board's axes, turned into the body's before anything uses it. The board's
// own chip placement is the driver's (common/drivers/mpu6050.hpp, ChipToBody); this is the
// board's in the frame, the same kind of table.
//
//   0 as docs/conventions.md draws it; 1, 2, 3: turned 90, 180, 270 degrees clockwise seen from
//   above (its X arrow to the right, backwards, to the left); 4..7: the same, then turned over
//   about its own X arrow (upside down).
//
// Board axes s from body axes v: turned by 90 k, s = (v_y, -v_x, v_z) for k = 1; turned over,
// s = (s_x, -s_y, -s_z). Each row is the inverse: body axis i is sign[i] x board axis axis[i].
// The simulator mounts its IMU by the same words (sim/wiring.hpp: imu_mount_yaw_deg = 90 k,
// imu_upside_down = u is undone by imu_orientation = k + 4 u).
#pragma once

#include <stdint.h>

#include <common/drivers/mpu6050.hpp>

namespace drivers {

inline constexpr int kImuOrientations = 8;

inline constexpr ChipToBody kImuMountings[kImuOrientations] = {
    {{0, 1, 2}, {1, 1, 1}},   {{1, 0, 2}, {-1, 1, 1}}, {{0, 1, 2}, {-1, -1, 1}}, {{1, 0, 2}, {1, -1, 1}},
    {{0, 1, 2}, {1, -1, -1}}, {{1, 0, 2}, {1, 1, -1}}, {{0, 1, 2}, {-1, 1, -1}}, {{1, 0, 2}, {-1, -1, -1}},
};

// The row for a parameter value; out of the table (the parameter's range prevents it): as drawn.
constexpr const ChipToBody& imu_mounting(int32_t orientation) {
  return kImuMountings[orientation >= 0 && orientation < kImuOrientations ? orientation : 0];
}

}  // namespace drivers
