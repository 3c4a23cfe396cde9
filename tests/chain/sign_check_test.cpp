// The sign check (qr/core/chain/sign_check.hpp, docs/safety.md rule 21): the probe finds a loop or
// a mixer that pushes an error further, the wrong-way monitor a vehicle that answers its loops the
// wrong way in the air, and the calibration refuses gravity read off body z. Each against the
// fault it exists for, and against the right vehicle, which it must leave alone.
#include <gtest/gtest.h>

#include <qr/core/chain/controllers.hpp>
#include <qr/core/chain/engine_mixer.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/core/chain/sign_check.hpp>

namespace qr::chain {
namespace {

using N = FixedNumbers;
using Thrust = N::Thrust;
using Angle = N::Angle;
using Rate = N::Rate;

// The flight's loops with the default gains, each answering a positive error on its own axis as
// FlightChain::check_signs asks them. `wrong`: the axis (0..2) whose answer loses its sign, as
// the IN4073 report's controller did; -1 none.
struct Loops {
  AttitudeController<N> roll, pitch;
  YawRateController<N> yaw;
  int wrong = -1;
  explicit Loops(int wrong_axis = -1) : wrong(wrong_axis) {
    const wire::ParameterValues p;
    using wire::ParamId;
    for (auto* c : {&roll, &pitch}) {
      c->set_gains(p.get(ParamId::roll_pitch_p1), p.get(ParamId::roll_pitch_p2), p.get(ParamId::roll_pitch_i),
                   p.get(ParamId::roll_pitch_d));
    }
    yaw.set_gains(p.get(ParamId::yaw_p), p.get(ParamId::yaw_i));
  }
  Moments<Thrust> answer(int axis) {
    const Angle off = kProbeAngle<Angle>;
    Thrust m = axis == 0   ? roll.moment(Angle{}, off, Rate{})
               : axis == 1 ? pitch.moment(Angle{}, off, Rate{})
                           : yaw.moment(Rate{}, kProbeYawRate<Rate>);
    if (axis == wrong) m = -m;
    Moments<Thrust> out;
    (axis == 0 ? out.roll : axis == 1 ? out.pitch : out.yaw) = m;
    return out;
  }
};

// A mixer whose engines 1 and 3 (right and left) are swapped, as a mixing table typed wrong.
struct SwappedMixer {
  EngineMixer<N> mixer;
  EngineCommand mix_thrust(Thrust lift, const Moments<Thrust>& m) {
    EngineCommand e = mixer.mix_thrust(lift, m);
    const uint16_t right = e.value[1];
    e.value[1] = e.value[3];
    e.value[3] = right;
    return e;
  }
};

TEST(SignCheck, TheProbePassesTheFlightsOwnLoopsAndMixer) {
  Loops loops;
  EngineMixer<N> mixer;
  EXPECT_EQ(probe_signs(loops, mixer, mixer.thrust_of_lift(kProbeLift)), SignAxis::none);
}

TEST(SignCheck, TheProbeNamesEachLoopThatPushesItsErrorFurther) {
  for (int axis = 0; axis < 3; ++axis) {
    Loops loops(axis);
    EngineMixer<N> mixer;
    EXPECT_EQ(probe_signs(loops, mixer, mixer.thrust_of_lift(kProbeLift)), static_cast<SignAxis>(axis + 1)) << axis;
  }
}

TEST(SignCheck, TheProbeFindsAMixerWiredTheWrongWay) {
  Loops loops;
  SwappedMixer mixer;
  EXPECT_EQ(probe_signs(loops, mixer, mixer.mixer.thrust_of_lift(kProbeLift)), SignAxis::roll);
}

// A gain at 0 (a parameter's minimum) answers nothing: no push either way, no wrong sign.
TEST(SignCheck, ALoopThatAnswersNothingIsNoWrongSign) {
  Loops loops;
  loops.roll.set_gains(0, 0, 0, 0);
  loops.yaw.set_gains(0, 0);
  EngineMixer<N> mixer;
  EXPECT_EQ(probe_signs(loops, mixer, mixer.thrust_of_lift(kProbeLift)), SignAxis::none);
}

// ---- the wrong-way monitor, on rates and moments a vehicle would show ----

// One tick of a simple vehicle on one axis: the loop answers the rate it reads with a moment
// against it; `answer` is how the vehicle's rate responds to that moment (+1 rightly, -1 the
// wrong way), plus a disturbance.
struct AxisFlight {
  WrongWayMonitor monitor;
  double rate = 20;  // mrad/s
  int answer = 1;
  int axis = 0;
  SignAxis step(bool landed = false, bool lifting = true, uint8_t loops = 7) {
    const double moment_on_axis = -rate / 4;  // the loop: against the rate
    int32_t moment[3] = {0, 0, 0};
    int32_t rates[3] = {0, 0, 0};
    moment[axis] = static_cast<int32_t>(moment_on_axis);
    rates[axis] = static_cast<int32_t>(rate);
    const SignAxis found = monitor.update(moment, rates, loops, landed, lifting);
    rate += answer * moment_on_axis / 20;  // 1.25 % a tick, growing or decaying
    return found;
  }
};

// Ticks until a verdict, or -1 within `limit` ticks.
int ticks_to_verdict(AxisFlight& f, int limit, SignAxis& found, bool landed = false) {
  for (int t = 0; t < limit; ++t) {
    found = f.step(landed);
    if (found != SignAxis::none) return t;
  }
  return -1;
}

TEST(WrongWayMonitor, AVehicleAnsweringTheWrongWayIsFoundWithinTwoBlocks) {
  for (int axis = 0; axis < 3; ++axis) {
    AxisFlight f;
    f.axis = axis;
    f.answer = -1;
    f.monitor.arm();
    SignAxis found = SignAxis::none;
    const int t = ticks_to_verdict(f, static_cast<int>(WrongWayMonitor::kWindowTicks), found);
    ASSERT_GE(t, 0) << axis;
    EXPECT_EQ(found, static_cast<SignAxis>(axis + 1));
    EXPECT_FALSE(f.monitor.watching());
    // Found once its rate passed the floor, within the two blocks that follow.
    EXPECT_GE(f.rate, WrongWayMonitor::kMinRateMrad);
  }
}

TEST(WrongWayMonitor, AVehicleOnTheGroundIsWatchedToo) {
  AxisFlight f;
  f.answer = -1;
  f.monitor.arm();
  SignAxis found = SignAxis::none;
  EXPECT_GE(ticks_to_verdict(f, 5000, found, /*landed=*/true), 0);
  EXPECT_EQ(found, SignAxis::roll);
}

// A vehicle that answers rightly: a fast turn at the take-off, pushed against, slows down.
TEST(WrongWayMonitor, AVehicleAnsweringRightlyIsLeftAlone) {
  AxisFlight f;
  f.monitor.arm();
  f.rate = 2000;
  SignAxis found = SignAxis::none;
  EXPECT_EQ(ticks_to_verdict(f, static_cast<int>(WrongWayMonitor::kWindowTicks) + 10, found), -1);
  EXPECT_FALSE(f.monitor.watching()) << "the window ends 1 s after the take-off";
}

TEST(WrongWayMonitor, NothingCountsBeforeTheEnginesTurnOrWhereTheSticksFly) {
  AxisFlight f;
  f.answer = -1;
  f.monitor.arm();
  for (int t = 0; t < 300; ++t) ASSERT_EQ(f.step(false, /*lifting=*/false), SignAxis::none);
  for (int t = 0; t < 300; ++t) ASSERT_EQ(f.step(false, true, /*loops=*/0), SignAxis::none);
  EXPECT_TRUE(f.monitor.watching());
  // The same growth, judged once the engines turn and the loops fly: found.
  SignAxis found = SignAxis::none;
  EXPECT_GE(ticks_to_verdict(f, 100, found), 0);
}

TEST(WrongWayMonitor, AfterTheWindowAPushIsNoVerdict) {
  AxisFlight f;
  f.monitor.arm();
  for (uint32_t t = 0; t <= WrongWayMonitor::kWindowTicks; ++t) f.step();
  ASSERT_FALSE(f.monitor.watching());
  f.answer = -1;  // what a push the loop cannot win looks like
  SignAxis found = SignAxis::none;
  EXPECT_EQ(ticks_to_verdict(f, 2000, found), -1);
}

TEST(WrongWayMonitor, ARateThatGrowsWhileTheLoopsPushWithItIsNoVerdict) {
  // A set-point step: the loop pushes the way the rate grows.
  WrongWayMonitor m;
  m.arm();
  for (int t = 0; t < 400; ++t) {
    const int32_t moment[3] = {200, 0, 0};
    const int32_t rate[3] = {t * 10, 0, 0};
    ASSERT_EQ(m.update(moment, rate, 7, false, true), SignAxis::none) << t;
  }
}

// ---- the lift-off kick, on a vehicle whose answer to each push is a matrix ----

// Two axes (roll, pitch) of a vehicle at take-off: the kick's pushes reach it through the motors'
// lag (30 ms), and `answer[j][i]` is how axis j turns for a push on axis i, as the estimate reads
// it (identity: a vehicle that answers rightly). About 15 mrad of its own axis 90 ms into a push,
// as the simulator's vehicle turns; a little damping stands for the loops.
struct KickedVehicle {
  LiftOffKick kick;
  double answer[2][2] = {{1, 0}, {0, 1}};
  double lagged[2] = {0, 0};
  double rate[2] = {0, 0};   // mrad/s
  double angle[2] = {0, 0};  // mrad
  double pushes_seen[2] = {0, 0};
  SignAxis step(bool quiet = true, bool lifting = true) {
    const int32_t read[2] = {static_cast<int32_t>(angle[0]), static_cast<int32_t>(angle[1])};
    const SignAxis found = kick.update(quiet, lifting, read);
    for (int i = 0; i < 2; ++i) {
      pushes_seen[i] += kick.push(i) != 0 ? 1 : 0;
      lagged[i] += (kick.push(i) - lagged[i]) / 30;
    }
    for (int j = 0; j < 2; ++j) {
      rate[j] += 14.0 * (answer[j][0] * lagged[0] + answer[j][1] * lagged[1]);
      rate[j] *= 0.995;
      angle[j] += rate[j] / 1000;
    }
    return found;
  }
  // Ticks until a verdict (-1: none in `limit`), with the verdict.
  int run(int limit, SignAxis& found) {
    for (int t = 0; t < limit; ++t) {
      found = step();
      if (found != SignAxis::none) return t;
    }
    return -1;
  }
};

TEST(LiftOffKick, AVehicleAnsweringRightlyIsPushedOnRollThenPitchAndLeftAlone) {
  KickedVehicle v;
  v.kick.arm();
  SignAxis found = SignAxis::none;
  EXPECT_EQ(v.run(1000, found), -1);
  // Each push a doublet of 2 x 40 ms; roll's answer 11 to 18 mrad by 90 ms as in the simulator.
  EXPECT_EQ(v.pushes_seen[0], 2 * LiftOffKick::kHalfTicks);
  EXPECT_EQ(v.pushes_seen[1], 2 * LiftOffKick::kHalfTicks);
  EXPECT_FALSE(v.kick.kicking());
  EXPECT_EQ(v.kick.pushed_axes(), 0) << "over: the monitor has the axes back";
}

TEST(LiftOffKick, ThePushesAreADoubletOnRollThenOnPitch) {
  KickedVehicle v;
  v.kick.arm();
  for (uint32_t t = 0; t < LiftOffKick::kTicks; ++t) {
    v.step();
    const int8_t roll = t < 40 ? 1 : t < 80 ? -1 : 0;
    const int8_t pitch = t < 60 ? 0 : t < 100 ? 1 : t < 140 ? -1 : 0;
    ASSERT_EQ(v.kick.push(0), roll) << t;
    ASSERT_EQ(v.kick.push(1), pitch) << t;
    ASSERT_EQ(v.kick.pushed_axes(), t + 1 >= LiftOffKick::kTicks ? 0 : t < 60 ? 1 : 3) << t;
  }
}

// A sensor axis read backwards (or an IMU half turned, motors crossed over an axis): the estimate
// turns that axis the other way. Found while that push's answer lasts, before the kick is over.
TEST(LiftOffKick, AnAxisThatTurnsTheOtherWayIsTheVerdict) {
  for (int axis = 0; axis < 2; ++axis) {
    KickedVehicle v;
    v.answer[axis][axis] = -1;
    v.kick.arm();
    SignAxis found = SignAxis::none;
    const int t = v.run(1000, found);
    EXPECT_EQ(found, static_cast<SignAxis>(axis + 1)) << axis;
    const int from = axis == 0 ? 0 : static_cast<int>(LiftOffKick::kPitchFrom);
    EXPECT_GE(t, from + static_cast<int>(LiftOffKick::kLagTicks)) << axis;
    EXPECT_LT(t, from + static_cast<int>(LiftOffKick::kAnswerTicks)) << axis;
    EXPECT_FALSE(v.kick.kicking()) << "a verdict ends the kick";
  }
}

// A motor on its neighbour's output: roll's push turns the vehicle about a diagonal, half as far
// on roll (one engine of its two answers there) and as far on pitch, either way round. An IMU
// turned a quarter: roll's push read as pitch. Found 90 ms in, on roll.
TEST(LiftOffKick, ARollPushAnsweredAcrossIsTheVerdict) {
  const double across[][2] = {{0.5, -0.5}, {0.5, 0.5}, {0, 1}, {0, -1}};
  for (const auto& a : across) {
    KickedVehicle v;
    v.answer[0][0] = a[0];
    v.answer[1][0] = a[1];
    v.kick.arm();
    SignAxis found = SignAxis::none;
    EXPECT_EQ(v.run(1000, found), static_cast<int>(LiftOffKick::kAcrossAt)) << a[0] << " " << a[1];
    EXPECT_EQ(found, SignAxis::roll);
  }
}

// A vehicle that answers rightly with some coupling (a tenth of roll's on pitch) or the estimate's
// noise is no verdict; nor is an answer too small to judge.
TEST(LiftOffKick, ASmallCouplingOrAnAnswerTooSmallIsNoVerdict) {
  const double answers[][4] = {{1, 0.25, -0.25, 1}, {0.2, 0, 0, 0.2}, {1.5, -0.3, 0.3, 1.5}};
  for (const auto& a : answers) {
    KickedVehicle v;
    v.answer[0][0] = a[0];
    v.answer[1][0] = a[1];
    v.answer[0][1] = a[2];
    v.answer[1][1] = a[3];
    v.kick.arm();
    SignAxis found = SignAxis::none;
    EXPECT_EQ(v.run(1000, found), -1) << a[0] << " " << a[1];
  }
}

TEST(LiftOffKick, ItWaitsForTheLiftOffAndForACalibration) {
  KickedVehicle v;
  v.answer[0][0] = -1;
  for (int t = 0; t < 300; ++t) ASSERT_EQ(v.step(), SignAxis::none) << "not armed";
  v.kick.arm();
  for (int t = 0; t < 300; ++t) {
    ASSERT_EQ(v.step(true, /*lifting=*/false), SignAxis::none);
    ASSERT_FALSE(v.kick.kicking());
  }
  SignAxis found = SignAxis::none;
  EXPECT_GE(v.run(200, found), 0);
  EXPECT_EQ(found, SignAxis::roll);
  // Once: the next flight is not kicked until the next calibration arms it.
  EXPECT_EQ(v.run(1000, found), -1);
  EXPECT_FALSE(v.kick.kicking());
}

// The pilot's stick (or a mode without the angle loops) stops the kick without a verdict, for
// good: the push does not come back when the stick does.
TEST(LiftOffKick, TheSticksStopItWithoutAVerdict) {
  KickedVehicle v;
  v.answer[0][0] = -1;
  v.kick.arm();
  for (int t = 0; t < 10; ++t) v.step();
  ASSERT_TRUE(v.kick.kicking());
  ASSERT_EQ(v.step(/*quiet=*/false), SignAxis::none);
  EXPECT_FALSE(v.kick.kicking());
  SignAxis found = SignAxis::none;
  EXPECT_EQ(v.run(1000, found), -1);
  EXPECT_EQ(v.kick.pushed_axes(), 0);
}

// A lift-off with the sticks moving is not kicked, nor is the flight later, when the vehicle
// would still be answering them.
TEST(LiftOffKick, ALiftOffWithTheSticksMovingIsNotKickedLater) {
  KickedVehicle v;
  v.answer[0][0] = -1;
  v.kick.arm();
  ASSERT_EQ(v.step(/*quiet=*/false, /*lifting=*/true), SignAxis::none);
  SignAxis found = SignAxis::none;
  EXPECT_EQ(v.run(1000, found), -1);
  EXPECT_EQ(v.pushes_seen[0], 0);
}

// ---- the calibration: gravity where a level vehicle does not read it ----

SensorSample at_rest(int16_t ax, int16_t ay, int16_t az) {
  SensorSample s;
  s.accel[0] = ax;
  s.accel[1] = ay;
  s.accel[2] = az;
  return s;
}

CalibrationAxis calibrate(SensorCalibration<N>& c, const SensorSample& s) {
  c.restart();
  while (!c.add(s)) {
  }
  return c.refused();
}

TEST(SignCheck, TheCalibrationRefusesGravityOffBodyZ) {
  const int16_t g = 8192;
  struct Case {
    SensorSample sample;
    CalibrationAxis refused;
  } cases[] = {
      {at_rest(0, 0, -g), CalibrationAxis::none},            // level
      {at_rest(g / 6, -g / 6, -g), CalibrationAxis::none},   // 10 degrees off and a bias: taken
      {at_rest(0, 0, g), CalibrationAxis::z},                // upside down
      {at_rest(g, 0, 0), CalibrationAxis::x},                // on its nose: x reads gravity
      {at_rest(0, -g, 0), CalibrationAxis::y},               // on its side
      {at_rest(g / 3, 0, -g * 9 / 10), CalibrationAxis::x},  // 20 degrees off level
  };
  for (const Case& c : cases) {
    SensorCalibration<N> cal;
    EXPECT_EQ(calibrate(cal, c.sample), c.refused)
        << c.sample.accel[0] << " " << c.sample.accel[1] << " " << c.sample.accel[2];
    EXPECT_EQ(cal.done(), c.refused == CalibrationAxis::none);
  }
}

TEST(SignCheck, ARefusedCalibrationKeepsTheOffsetsInUse) {
  SensorCalibration<N> cal;
  SensorSample good = at_rest(100, 0, -8192);
  good.gyro[0] = 30;
  ASSERT_EQ(calibrate(cal, good), CalibrationAxis::none);
  const Rate offset = cal.gyro_offset(0);
  ASSERT_EQ(calibrate(cal, at_rest(0, 0, 8192)), CalibrationAxis::z);
  EXPECT_TRUE(cal.done());
  EXPECT_EQ(cal.gyro_offset(0), offset);
  EXPECT_FALSE(cal.accepted());
}

}  // namespace
}  // namespace qr::chain
