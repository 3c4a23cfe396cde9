// The eight ways the IMU's board may sit in the frame (parameter imu_orientation: the table the
// firmware undoes them by, common/drivers/imu_mounting.hpp), as matrices, and which of them
// explains what the QR reported while the vehicle was tilted right, nose up and turned right by
// hand (docs/console.md, "The orientation check").
//
//   0 as docs/conventions.md draws it; 1, 2, 3: turned 90, 180, 270 degrees clockwise seen from
//   above; 4..7: the same, then turned over about the board's own X arrow (upside down).
#pragma once

#include <array>
#include <string>

#include <common/drivers/imu_mounting.hpp>

namespace qrterm {

inline constexpr int kImuOrientations = drivers::kImuOrientations;

// A signed permutation of the three axes: row r, column c is +1 or -1 where axis r of one frame
// is axis c of the other, else 0. Axes 0, 1, 2: x (roll), y (pitch), z (yaw).
using AxisMatrix = std::array<std::array<int, 3>, 3>;

// The board's axes from the body's, for the board sitting as imu_orientation `orientation` says.
AxisMatrix board_from_body(int orientation);
// What the QR reports (its body axes, rows) of a motion about each body axis (columns) when the
// board sits as `orientation` says and the firmware takes it to sit as `in_force` says.
AxisMatrix reported_axes(int orientation, int in_force);
// "as drawn (X arrow forward)", "turned 90 deg clockwise (X arrow right)", "upside down, X arrow
// backward", ...
std::string mounting_name(int orientation);

// One step of the check: the reported axis that moved (0 roll, 1 pitch, 2 yaw) and which way.
struct AxisAnswer {
  int axis = 0;
  int sign = 1;
};

struct MountingVerdict {
  enum class Kind {
    mounting,     // `orientation` explains every step
    same_axis,    // two steps moved the same reported axis (`axis`): no answer yet
    mirrored,     // an axis reads backwards: a mirror image, which no mounting gives
    on_its_side,  // a turn no imu_orientation has: the board's z is not along the body's
  };
  Kind kind = Kind::mounting;
  int orientation = 0;  // mounting only
  int axis = 0;         // same_axis only
};

// From the three steps' answers (roll +, pitch +, yaw + asked, in that order) and the orientation
// in force while they were taken.
MountingVerdict infer_mounting(const std::array<AxisAnswer, 3>& answers, int in_force);

// The verdict in a line for the pilot: "the board is turned 90 deg clockwise: imu_orientation = 1
// explains every step", "as set: imu_orientation = 0 (as drawn) explains every step", ...
std::string verdict_text(const MountingVerdict& verdict, int in_force);

}  // namespace qrterm
