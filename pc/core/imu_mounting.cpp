#include <pc/core/imu_mounting.hpp>

namespace qrterm {
namespace {

constexpr const char* kAxisNames[] = {"roll", "pitch", "yaw"};

AxisMatrix product(const AxisMatrix& a, const AxisMatrix& b) {
  AxisMatrix p{};
  for (size_t r = 0; r < 3; ++r) {
    for (size_t c = 0; c < 3; ++c) {
      for (size_t k = 0; k < 3; ++k) p[r][c] += a[r][k] * b[k][c];
    }
  }
  return p;
}

// A rotation's inverse is its transpose.
AxisMatrix transposed(const AxisMatrix& a) {
  AxisMatrix t{};
  for (size_t r = 0; r < 3; ++r) {
    for (size_t c = 0; c < 3; ++c) t[r][c] = a[c][r];
  }
  return t;
}

int determinant(const AxisMatrix& a) {
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

}  // namespace

// The table's row says body axis i is sign[i] x board axis chip_axis[i]: the body from the board;
// a rotation's inverse is its transpose.
AxisMatrix board_from_body(int orientation) {
  const drivers::ChipToBody& row = drivers::imu_mounting(orientation);
  AxisMatrix body_from_board{};
  for (size_t i = 0; i < 3; ++i) body_from_board[i][row.chip_axis[i]] = row.sign[i];
  return transposed(body_from_board);
}

// The firmware turns the board's axes back into the body's by the inverse of in_force's mounting.
AxisMatrix reported_axes(int orientation, int in_force) {
  return product(transposed(board_from_body(in_force)), board_from_body(orientation));
}

// Turned over about its own X arrow, the arrow points where it did: where it points and which
// face is up say the mounting without an order of turns to get wrong.
std::string mounting_name(int orientation) {
  static constexpr const char* kTurns[] = {"as drawn (X arrow forward)", "turned 90 deg clockwise (X arrow right)",
                                           "turned 180 deg (X arrow backward)",
                                           "turned 270 deg clockwise (X arrow left)"};
  static constexpr const char* kArrows[] = {"forward", "right", "backward", "left"};
  const int k = orientation % 4;
  if (orientation < 4) return kTurns[k];
  return std::string("upside down, X arrow ") + kArrows[k];
}

MountingVerdict infer_mounting(const std::array<AxisAnswer, 3>& answers, int in_force) {
  AxisMatrix seen{};
  for (size_t step = 0; step < 3; ++step) {
    const AxisAnswer& a = answers[step];
    for (size_t earlier = 0; earlier < step; ++earlier) {
      if (answers[earlier].axis == a.axis) return {MountingVerdict::Kind::same_axis, 0, a.axis};
    }
    seen[static_cast<size_t>(a.axis)][step] = a.sign;
  }
  for (int m = 0; m < kImuOrientations; ++m) {
    if (reported_axes(m, in_force) == seen) return {MountingVerdict::Kind::mounting, m, 0};
  }
  return {determinant(seen) < 0 ? MountingVerdict::Kind::mirrored : MountingVerdict::Kind::on_its_side, 0, 0};
}

std::string verdict_text(const MountingVerdict& verdict, int in_force) {
  switch (verdict.kind) {
    case MountingVerdict::Kind::mounting: {
      const std::string setting = "imu_orientation = " + std::to_string(verdict.orientation);
      if (verdict.orientation == in_force) {
        return "as set: " + setting + " (" + mounting_name(verdict.orientation) + ") explains every step";
      }
      return "the board is " + mounting_name(verdict.orientation) + ": " + setting + " explains every step";
    }
    case MountingVerdict::Kind::same_axis:
      return std::string("two steps moved ") + kAxisNames[verdict.axis] + ": no mounting does that; check again";
    case MountingVerdict::Kind::mirrored:
      return "no mounting explains it: an axis reads backwards (a mirror image, which no way of mounting the board "
             "gives): look for a sign error in the IMU's driver or the board";
    case MountingVerdict::Kind::on_its_side:
      return "no mounting explains it: the board stands on its side (its z is not the body's), which "
             "imu_orientation does not cover";
  }
  return "";
}

}  // namespace qrterm
