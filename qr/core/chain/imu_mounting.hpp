// The IMU board's mounting in the frame (parameter imu_orientation) undone in the flight chain:
// the table is common/drivers/imu_mounting.hpp (the console reads it too, for the orientation
// check); here the sample is turned from the board's axes into the body's before anything uses it.
#pragma once

#include <common/drivers/imu_mounting.hpp>
#include <qr/core/board.hpp>

namespace qr::chain {

using drivers::imu_mounting;
using drivers::kImuMountings;

// A sample in the board's axes into the body's: the gyro and the accelerometer alike.
inline SensorSample mounted(const drivers::ChipToBody& mounting, const SensorSample& board) {
  SensorSample body = board;
  drivers::chip_to_body(mounting, board.gyro, body.gyro);
  drivers::chip_to_body(mounting, board.accel, body.accel);
  return body;
}

}  // namespace qr::chain
