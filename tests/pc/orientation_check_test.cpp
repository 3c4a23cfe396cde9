// The orientation check (pc/core/orientation_check.hpp, imu_mounting.hpp): which of the eight
// mountings explains the three steps, held against the firmware's table and the simulator's
// mounting; what no mounting explains; and the check's steps fed with a hand's rates as the QR
// reports them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <common/drivers/imu_mounting.hpp>
#include <pc/core/imu_mounting.hpp>
#include <pc/core/orientation_check.hpp>
#include <sim/wiring.hpp>

namespace {

using qrterm::AxisAnswer;
using qrterm::MountingVerdict;

// What the QR reports of a motion about each body axis for an IMU mounted as the simulator mounts
// it (sim/wiring.hpp) and corrected by the firmware's table row `in_force`
// (common/drivers/imu_mounting.hpp): written apart from each other and from the console's
// inference.
std::array<AxisAnswer, 3> answers_of(const sim::Wiring& wiring, int in_force) {
  std::array<AxisAnswer, 3> answers;
  for (size_t step = 0; step < 3; ++step) {
    sim::Vec3 motion{};
    (step == 0 ? motion.x : step == 1 ? motion.y : motion.z) = 1;
    const sim::Vec3 board = sim::imu_gyro_axes(wiring, motion);
    const double board_axes[] = {board.x, board.y, board.z};
    const drivers::ChipToBody& row = drivers::kImuMountings[in_force];
    for (int i = 0; i < 3; ++i) {
      const double reported = row.sign[i] * board_axes[row.chip_axis[i]];
      if (reported != 0) answers[step] = AxisAnswer{i, reported > 0 ? 1 : -1};
    }
  }
  return answers;
}

sim::Wiring mounted(int orientation) {
  sim::Wiring wiring;
  wiring.imu_yaw_deg = 90 * (orientation % 4);
  wiring.imu_upside_down = orientation / 4;
  return wiring;
}

// The console's matrices are the table's rows turned round: row m turns board m's axes back into
// the body's, board_from_body(m) is its inverse.
TEST(ImuMounting, TheConsolesMountingsAreTheFirmwaresTable) {
  for (int m = 0; m < qrterm::kImuOrientations; ++m) {
    const qrterm::AxisMatrix board = qrterm::board_from_body(m);
    const drivers::ChipToBody& row = drivers::kImuMountings[m];
    for (size_t body = 0; body < 3; ++body) {
      for (size_t b = 0; b < 3; ++b) {
        const int table = b == row.chip_axis[body] ? row.sign[body] : 0;
        EXPECT_EQ(board[b][body], table) << "orientation " << m << ", body axis " << body << ", board axis " << b;
      }
    }
  }
}

// Every mounting the simulator makes is named from the three steps, with the board taken as drawn
// (imu_orientation 0), and once its orientation is set the check finds it "as set".
TEST(ImuMounting, EachOfTheEightMountingsIsFoundFromItsThreeSteps) {
  for (int m = 0; m < qrterm::kImuOrientations; ++m) {
    const MountingVerdict found = qrterm::infer_mounting(answers_of(mounted(m), 0), 0);
    EXPECT_EQ(found.kind, MountingVerdict::Kind::mounting) << m;
    EXPECT_EQ(found.orientation, m);
    const MountingVerdict again = qrterm::infer_mounting(answers_of(mounted(m), m), m);
    EXPECT_EQ(again.kind, MountingVerdict::Kind::mounting) << m;
    EXPECT_EQ(again.orientation, m);
    EXPECT_EQ(qrterm::verdict_text(again, m).rfind("as set: imu_orientation = " + std::to_string(m), 0), 0u)
        << qrterm::verdict_text(again, m);
    // Set wrong, the check still names the board as it sits.
    const int wrong = (m + 1) % qrterm::kImuOrientations;
    const MountingVerdict through = qrterm::infer_mounting(answers_of(mounted(m), wrong), wrong);
    EXPECT_EQ(through.orientation, m) << "with " << wrong << " in force";
  }
}

// The case worked by hand: the board turned 90 deg clockwise, its X arrow to the right. Tilted
// right side down, the body turns about x, which is the board's -y: pitch reads minus; nose up
// turns about body y, the board's x: roll plus; yaw stays yaw.
TEST(ImuMounting, ABoardTurnedAQuarterClockwiseReadsRollAsMinusPitch) {
  const std::array<AxisAnswer, 3> answers{AxisAnswer{1, -1}, AxisAnswer{0, 1}, AxisAnswer{2, 1}};
  const MountingVerdict v = qrterm::infer_mounting(answers, 0);
  ASSERT_EQ(v.kind, MountingVerdict::Kind::mounting);
  EXPECT_EQ(v.orientation, 1);
  EXPECT_EQ(qrterm::verdict_text(v, 0),
            "the board is turned 90 deg clockwise (X arrow right): imu_orientation = 1 explains every step");
  EXPECT_EQ(qrterm::mounting_name(6), "upside down, X arrow backward");
}

// One axis read backwards (the simulator's gyro_signs) is a mirror image: whatever the mounting,
// no imu_orientation explains it, and the verdict says so rather than offering one.
TEST(ImuMounting, AnAxisReadBackwardsIsExplainedByNoMounting) {
  for (int m = 0; m < qrterm::kImuOrientations; ++m) {
    for (int axis = 0; axis < 3; ++axis) {
      sim::Wiring wiring = mounted(m);
      wiring.gyro_signs[static_cast<size_t>(axis)] = -1;
      const MountingVerdict v = qrterm::infer_mounting(answers_of(wiring, 0), 0);
      EXPECT_EQ(v.kind, MountingVerdict::Kind::mirrored) << "mounting " << m << ", axis " << axis;
      EXPECT_NE(qrterm::verdict_text(v, 0).find("an axis reads backwards"), std::string::npos);
    }
  }
}

TEST(ImuMounting, ABoardOnItsSideOrTwoStepsOnOneAxisAreNoMounting) {
  // On its side: roll read as yaw, yaw as minus roll (a quarter turn about y).
  const MountingVerdict side = qrterm::infer_mounting({AxisAnswer{2, 1}, AxisAnswer{1, 1}, AxisAnswer{0, -1}}, 0);
  EXPECT_EQ(side.kind, MountingVerdict::Kind::on_its_side);
  const MountingVerdict twice = qrterm::infer_mounting({AxisAnswer{0, 1}, AxisAnswer{0, -1}, AxisAnswer{2, 1}}, 0);
  EXPECT_EQ(twice.kind, MountingVerdict::Kind::same_axis);
  EXPECT_EQ(qrterm::verdict_text(twice, 0), "two steps moved roll: no mounting does that; check again");
}

// docs/console.md's table of the eight mountings, what each reads with 0 in force, is the
// console's: names and readings.
TEST(ImuMounting, TheManualsTableIsTheConsoles) {
  std::ifstream in(QR_CONSOLE_DOC);
  ASSERT_TRUE(in) << QR_CONSOLE_DOC;
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const size_t start = doc.find("### The orientation check");
  ASSERT_NE(start, std::string::npos);
  const std::string section = doc.substr(start, doc.find("\n## ", start) - start);
  const std::regex row(R"(\n\| ([0-7]) \| ([^|]+) \| (\w+) ([+-]) \| (\w+) ([+-]) \| (\w+) ([+-]) \|)");
  constexpr const char* kAxisNames[] = {"roll", "pitch", "yaw"};
  int rows = 0;
  for (std::sregex_iterator it(section.begin(), section.end(), row), stop; it != stop; ++it, ++rows) {
    const std::smatch& m = *it;
    const int orientation = std::stoi(m[1]);
    EXPECT_EQ(orientation, rows) << "in order";
    EXPECT_EQ(m[2].str(), qrterm::mounting_name(orientation));
    const qrterm::AxisMatrix reads = qrterm::reported_axes(orientation, 0);
    for (size_t step = 0; step < 3; ++step) {
      const size_t axis = reads[0][step] != 0 ? 0 : reads[1][step] != 0 ? 1 : 2;
      EXPECT_EQ(m[3 + 2 * step].str(), kAxisNames[axis]) << "imu_orientation " << orientation << ", step " << step + 1;
      EXPECT_EQ(m[4 + 2 * step].str(), reads[axis][step] > 0 ? "+" : "-")
          << "imu_orientation " << orientation << ", step " << step + 1;
    }
  }
  EXPECT_EQ(rows, qrterm::kImuOrientations);
}

// The check itself, fed telemetry_rates at 50 Hz as the QR sends them while a hand moves it.
class Bench {
 public:
  static constexpr uint32_t kHz = 50;

  Bench()
      : check(qrterm::OrientationCheck::Hooks{
            [this](qrterm::Severity, const std::string& text) { notes.push_back(text); }, [this] { return in_force; },
            [this](size_t axis) {
              hands.push_back(axis);
              return simulator;
            },
            [this](int orientation) {
              set.push_back(orientation);
              return std::string();
            }}) {}

  // Still for `seconds`, with the gyro's bias on every axis.
  void rest(double seconds) {
    for (int i = 0; i < std::lround(seconds * kHz); ++i) send({0, 0, 0});
  }
  // A hand's tilt of `degrees` about reported axis `axis` (and `cross` times as much about the next
  // one): out in 0.5 s, held 0.5 s, back in 0.5 s, then still.
  void tilt(size_t axis, double degrees, double cross = 0) {
    const int third = kHz / 2;
    const double peak = degrees * std::numbers::pi / 2 / 0.5;  // deg/s
    for (int i = 0; i < 3 * third; ++i) {
      const double phase = std::numbers::pi * ((i % third) + 0.5) / third;
      const double rate = i < third ? peak * std::sin(phase) : i < 2 * third ? 0 : -peak * std::sin(phase);
      std::array<double, 3> r{};
      r[axis] = rate;
      r[(axis + 1) % 3] = cross * rate;
      send(r);
    }
    rest(0.5);
  }
  void send(const std::array<double, 3>& deg_s) {
    constexpr double kMilliradPerDeg = 1000 * std::numbers::pi / 180;
    check.on_rates({static_cast<int16_t>(std::lround((deg_s[0] + bias) * kMilliradPerDeg)),
                    static_cast<int16_t>(std::lround((deg_s[1] + bias) * kMilliradPerDeg)),
                    static_cast<int16_t>(std::lround((deg_s[2] + bias) * kMilliradPerDeg))},
                   kHz);
  }

  int in_force = 0;
  bool simulator = true;
  double bias = 3;  // deg/s: a QR not calibrated yet
  std::vector<std::string> notes;
  std::vector<size_t> hands;
  std::vector<int> set;
  qrterm::OrientationCheck check;
};

// A board turned 90 deg clockwise, not calibrated: each step is answered once the QR is set down
// still, the simulator's hand asked for each axis in turn, the verdict names imu_orientation 1,
// and Enter sets it.
TEST(OrientationCheck, ThreeStepsNameTheMountingAndEnterSetsIt) {
  Bench b;
  b.check.start();
  b.rest(0.6);
  const struct {
    size_t axis;
    double degrees;
  } read[] = {{1, -45}, {0, 45}, {2, 45}};  // what the QR reports of roll +, pitch +, yaw +
  for (size_t step = 0; step < 3; ++step) {
    ASSERT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::ready);
    ASSERT_EQ(b.check.step(), step);
    b.check.enter();
    EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::moving);
    b.tilt(read[step].axis, read[step].degrees);
    ASSERT_TRUE(b.check.result(step).has_value()) << step;
    const qrterm::StepResult& r = *b.check.result(step);
    EXPECT_EQ(r.answer.axis, static_cast<int>(read[step].axis));
    EXPECT_EQ(r.answer.sign, read[step].degrees > 0 ? 1 : -1);
    EXPECT_NEAR(r.most_deg[read[step].axis], read[step].degrees, 1.5) << "the rest's bias taken out";
    b.rest(0.3);
  }
  EXPECT_EQ(b.hands, (std::vector<size_t>{0, 1, 2}));
  ASSERT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::result);
  EXPECT_EQ(b.check.verdict().orientation, 1);
  EXPECT_EQ(b.check.offered(), 1);
  EXPECT_EQ(b.notes.back(),
            "orientation check: the board is turned 90 deg clockwise (X arrow right): imu_orientation = 1 explains "
            "every step");
  b.check.enter();
  EXPECT_EQ(b.set, (std::vector<int>{1}));
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::set);
  EXPECT_NE(b.notes.back().find("calibrate again (3)"), std::string::npos) << b.notes.back();
  // Checked again with it set: as set, nothing more to offer.
  b.in_force = 1;
  b.check.enter();
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::ready);
  EXPECT_EQ(b.check.in_force(), 1);
  for (size_t step = 0; step < 3; ++step) {
    b.check.enter();
    b.tilt(step, 40);
  }
  ASSERT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::result);
  EXPECT_EQ(b.check.offered(), std::nullopt);
  EXPECT_EQ(b.check.verdict().orientation, 1);
}

// A step is answered only by a clear motion about one axis that has come back to rest: a small
// wobble is not an answer, a tilt still held is not yet, and two axes at once are asked again.
TEST(OrientationCheck, AStepWaitsForAClearMotionAboutOneAxisSetDown) {
  Bench b;
  b.simulator = false;
  b.check.start();
  b.rest(0.5);
  b.check.enter();
  EXPECT_NE(b.notes.back().find("step 1, tilt right (roll +): tilt it right side down"), std::string::npos)
      << b.notes.back();
  b.tilt(0, 12);
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::moving) << "12 deg is no clear answer";
  b.check.enter();  // again, from here
  b.tilt(0, 45, 0.7);
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::ready);
  EXPECT_FALSE(b.check.result(0).has_value());
  EXPECT_EQ(b.notes.back(), "step 1: roll and pitch both moved: do it again, about one axis (Enter)");
  b.check.enter();
  b.tilt(0, 45, 0.3);
  ASSERT_TRUE(b.check.result(0).has_value());
  EXPECT_EQ(b.check.result(0)->answer.axis, 0);
  EXPECT_EQ(b.check.step(), 1u);
}

// Out of safe a step stops, and none starts; Backspace's restart forgets the answers.
TEST(OrientationCheck, RunsInSafeOnly) {
  Bench b;
  b.check.start();
  b.check.on_mode(wire::Mode::safe);
  b.check.enter();
  b.check.on_mode(wire::Mode::manual);
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::ready);
  b.check.enter();
  EXPECT_EQ(b.check.phase(), qrterm::OrientationCheck::Phase::ready);
  EXPECT_EQ(b.notes.back(), "the orientation check runs in safe only: 0 first");
  EXPECT_EQ(b.hands.size(), 1u);
  b.check.on_mode(wire::Mode::safe);
  b.check.enter();
  b.tilt(0, 45);
  ASSERT_TRUE(b.check.result(0).has_value());
  b.check.start();
  EXPECT_FALSE(b.check.result(0).has_value());
  EXPECT_EQ(b.check.step(), 0u);
}

}  // namespace
