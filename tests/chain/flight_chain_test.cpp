// The chain as the firmware runs it (FlightChain), end to end: the signs from a tilted vehicle
// or a stick to the engines (the IN4073 report's controller pushed the wrong way), calibration,
// the modes' moment sources, parameters, and the flight build against the double reference over
// the synthetic flight.
#include <gtest/gtest.h>

#include <cmath>

#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/replay_tick.hpp>
#include <qr/host/real_numbers.hpp>

#include "chain_checksum.hpp"
#include "chain_pilot.hpp"
#include "chain_test_support.hpp"

namespace qr {
namespace {

using chain::test::climbing;
using chain::test::Mode;
using chain::test::Pilot;
using chain::test::sample_at;
using chain::test::sticks;
using DoubleChain = FlightChain<chain::DoubleNumbers>;

// For the sign tests below: the estimate must first reach the tilt the accelerometer shows. With
// the default C1 (8 s, chosen for free flight) that takes many seconds, so those vehicles use an
// estimator that follows the accelerometer within 0.06 s (C1 = 64, C2 = 4 C1^2).
wire::ParameterValues quick_estimator() {
  wire::ParameterValues p;
  EXPECT_EQ(p.set(static_cast<uint8_t>(wire::ParamId::attitude_c1), 64), wire::NackReason::none);
  EXPECT_EQ(p.set(static_cast<uint8_t>(wire::ParamId::attitude_c2), 4 * 64 * 64), wire::NackReason::none);
  return p;
}

// The sign chain the IN4073 team got wrong: a vehicle tilted right, with level wanted, must be
// pushed back left: right engine (1) up, left engine (3) down. Nose up: back (2) up, front (0)
// down. Turning right with no yaw wanted: the clockwise pair (0, 2) up.
TEST(FlightChain, DisturbedVehicleIsPushedBack) {
  Pilot<FixedChain> right;
  right.chain.set_parameters(quick_estimator());
  right.calibrate_level();
  EngineCommand e = right.run(Mode::full, sample_at(0.1, 0), sticks(500), 1000);
  EXPECT_GT(right.chain.roll_e4(), 900);
  EXPECT_LT(right.chain.moments_e3().roll, 0);
  EXPECT_GT(e.value[1], e.value[3]);

  Pilot<FixedChain> nose_up;
  nose_up.chain.set_parameters(quick_estimator());
  nose_up.calibrate_level();
  e = nose_up.run(Mode::full, sample_at(0, 0.1), sticks(500), 1000);
  EXPECT_GT(nose_up.chain.pitch_e4(), 900);
  EXPECT_GT(e.value[2], e.value[0]);

  Pilot<FixedChain> turning;
  turning.calibrate_level();
  e = turning.run(Mode::yaw, sample_at(0, 0, 0, 0, 0.5), sticks(500), 200);
  EXPECT_NEAR(turning.chain.r_e3(), 500, 2);
  EXPECT_GT(e.value[0], e.value[1]);
  EXPECT_GT(e.value[2], e.value[3]);
}

// Stick right (roll set-point > estimate): left engine (3) up, right (1) down; pull (pitch
// set-point > estimate): front (0) up; twist right: the counter-clockwise pair (1, 3) up. In every
// mode that maps the stick, closed loop or open.
TEST(FlightChain, SticksMoveTheRightEngines) {
  for (const Mode mode : {Mode::full, Mode::yaw, Mode::manual}) {
    Pilot<FixedChain> p;
    p.calibrate_level();
    EngineCommand e = p.run(mode, sample_at(0, 0), sticks(500, 500), 5);
    EXPECT_GT(e.value[3], 500) << int(mode);
    EXPECT_LT(e.value[1], 500) << int(mode);
    EXPECT_EQ(e.value[0], e.value[2]) << int(mode);
    e = p.run(mode, sample_at(0, 0), sticks(500, 0, 500), 5);
    EXPECT_GT(e.value[0], 500) << int(mode);
    EXPECT_LT(e.value[2], 500) << int(mode);
    e = p.run(mode, sample_at(0, 0), sticks(500, 0, 0, 500), 5);
    EXPECT_GT(e.value[1], e.value[0]) << int(mode);
    EXPECT_GT(e.value[3], e.value[2]) << int(mode);
  }
  Pilot<FixedChain> p;
  p.calibrate_level();
  p.run(Mode::full, sample_at(0, 0), sticks(500, 1000, -1000, 1000), 1);
  EXPECT_EQ(p.chain.roll_setpoint_e4(), 5240);  // max_tilt_mrad default 0.524 rad (30 deg) at full stick
  EXPECT_EQ(p.chain.pitch_setpoint_e4(), -5240);
  EXPECT_EQ(p.chain.yaw_rate_setpoint_e3(), 2000);  // max_yaw_rate default 2 rad/s
}

TEST(FlightChain, YawModeLeavesRollAndPitchToTheSticks) {
  // Tilted right in yaw mode, sticks neutral: no roll correction (that is full control's job).
  Pilot<FixedChain> p;
  p.calibrate_level();
  const EngineCommand e = p.run(Mode::yaw, sample_at(0.1, 0), sticks(500), 1000);
  EXPECT_EQ(p.chain.moments_e3().roll, 0);
  EXPECT_EQ(e.value[1], e.value[3]);
}

// Acro (engine_sources.hpp, Tilt::rate): the rate loops alone. A tilt with the sticks centred asks
// for nothing (no angle loop: the vehicle stays where it is left); half roll stick asks for half
// max_yaw_rate_rad_s (1 rad/s by default): a positive roll moment while the vehicle does not turn,
// and none once the gyro reads that rate.
TEST(FlightChain, AcroFliesTheRateLoopsToTheSticksRates) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  p.chain.fly({chain::Tilt::rate, chain::Yaw::rate, chain::Lift::stick});
  const auto acro_tick = [&p](const SensorSample& s, const ControlInput& c) {
    p.chain.set_pilot(c);
    p.chain.filter(s);
    p.chain.estimate();
    p.chain.control_attitude();
    p.chain.control_yaw();
    return p.chain.mix();
  };
  for (int n = 0; n < 500; ++n) acro_tick(sample_at(0.2, 0), sticks(500));
  EXPECT_EQ(p.chain.moments_e3().roll, 0) << "tilted, sticks centred: no angle loop";
  for (int n = 0; n < 20; ++n) acro_tick(sample_at(0.2, 0), sticks(500, 500));
  EXPECT_NEAR(p.chain.rate_setpoint_e3(0), 1000, 2) << "half stick: half of max_yaw_rate_rad_s";
  EXPECT_GT(p.chain.moments_e3().roll, 100000) << "a roll rate asked, none read: a roll moment";
  for (int n = 0; n < 200; ++n) acro_tick(sample_at(0.2, 0, 1.0), sticks(500, 500));
  EXPECT_LT(std::abs(p.chain.moments_e3().roll), 5000) << "the rate read is the rate asked";
}

TEST(FlightChain, CalibrationRemovesTheOffsets) {
  const double gyro_offset[3] = {40, -25, 15}, accel_offset[3] = {60, -35, 90};
  Pilot<FixedChain> p;
  EXPECT_FALSE(p.chain.calibrated());
  // Before calibration the offsets show: 35 counts on y is 4.3 mrad of roll.
  p.run(Mode::full, sample_at(0, 0, 0, 0, 0, gyro_offset, accel_offset), sticks(0), 100);
  EXPECT_GT(p.chain.roll_e4(), 30);
  p.calibrate_level(gyro_offset, accel_offset);
  EXPECT_TRUE(p.chain.calibrated());
  p.run(Mode::full, sample_at(0, 0, 0, 0, 0, gyro_offset, accel_offset), sticks(0), 2000);
  EXPECT_EQ(p.chain.roll_e4(), 0);
  EXPECT_EQ(p.chain.pitch_e4(), 0);
  EXPECT_EQ(p.chain.p_e3(), 0);
  EXPECT_EQ(p.chain.q_e3(), 0);
  EXPECT_EQ(p.chain.r_e3(), 0);
  EXPECT_EQ(p.chain.yaw_e4(), 0);
  // And a real tilt still reads as one: rolled at 1 rad/s and pitched at -0.5 rad/s, the gyro
  // agreeing. The body rates of those Euler rates (no yaw): p = roll', q = pitch' cos(roll),
  // r = -pitch' sin(roll).
  for (int n = 1; n <= 200; ++n) {
    const double roll = n * 0.001, pitch = -n * 0.0005;
    p.tick(Mode::full,
           sample_at(roll, pitch, 1.0, -0.5 * std::cos(roll), 0.5 * std::sin(roll), gyro_offset, accel_offset),
           sticks(0));
  }
  p.run(Mode::full, sample_at(0.2, -0.1, 0, 0, 0, gyro_offset, accel_offset), sticks(0), 1000);
  EXPECT_NEAR(p.chain.roll_e4(), 2000, 2);
  EXPECT_NEAR(p.chain.pitch_e4(), -1000, 2);
  EXPECT_EQ(p.chain.tilt_mrad(), 200);
}

TEST(FlightChain, CalibrationStartsOverWhenEnteredAgain) {
  Pilot<FixedChain> p;
  p.calibrate_level({10, 0, 0});
  p.run(Mode::full, sample_at(0, 0, 0, 0, 0, {10, 0, 0}), sticks(0), 10);
  EXPECT_EQ(p.chain.p_e3(), 0);
  // Calibration mode again, the gyro offset has moved: a new run of kCalibrationSamples.
  p.chain.enter_calibration();
  p.chain.filter(sample_at(0, 0, 0, 0, 0, {30, 0, 0}));
  EXPECT_FALSE(p.chain.calibrate());
  p.calibrate_level({30, 0, 0});
  p.run(Mode::full, sample_at(0, 0, 0, 0, 0, {30, 0, 0}), sticks(0), 10);
  EXPECT_EQ(p.chain.p_e3(), 0);
}

TEST(FlightChain, ParametersReachTheBlocks) {
  Pilot<FixedChain> p;
  EXPECT_EQ(p.chain.cutoff_hz(), 20);
  wire::ParameterValues values;
  ASSERT_EQ(values.set(static_cast<uint8_t>(wire::ParamId::filter_cutoff_hz), 50), wire::NackReason::none);
  ASSERT_EQ(values.set(static_cast<uint8_t>(wire::ParamId::idle_level), 300), wire::NackReason::none);
  ASSERT_EQ(values.set(static_cast<uint8_t>(wire::ParamId::max_yaw_rate_rad_s), 1024), wire::NackReason::none);
  ASSERT_EQ(values.set(static_cast<uint8_t>(wire::ParamId::max_tilt_mrad), 349), wire::NackReason::none);
  p.chain.set_parameters(values);
  EXPECT_EQ(p.chain.cutoff_hz(), 50);
  p.calibrate_level();
  const EngineCommand e = p.run(Mode::manual, sample_at(0, 0), sticks(200, 300), 1);
  for (const uint16_t v : e.value) EXPECT_GE(v, 300);
  p.run(Mode::full, sample_at(0, 0), sticks(500, -500, 0, 1000), 1);
  EXPECT_EQ(p.chain.yaw_rate_setpoint_e3(), 1000);  // max_yaw_rate 1 rad/s
  EXPECT_EQ(p.chain.roll_setpoint_e4(), -1745);     // half of max_tilt 0.349 rad (20 deg)
}

// The rate loops' integrals (anti-windup, controllers.hpp): they grow on a held angle error in
// full control, start empty whenever full control is entered, stay empty while the lift is 0,
// and hold while the mixer has to scale the moments down.
// A level vehicle whose thrust exceeds its weight: the accelerometer reads `g` along -z.

TEST(FlightChain, IntegralsStartEmptyAndHoldWhenTheyMust) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  p.run(Mode::full, climbing(1.3), sticks(500), 60);                // take-off (the landed detector's test below)
  p.run(Mode::full, sample_at(0, 0), sticks(500, 300, -300), 500);  // set-points 0.105 / -0.105 rad
  const int32_t roll_after_half_a_second = p.chain.roll_integral_e3();
  EXPECT_GT(roll_after_half_a_second, 0);
  EXPECT_LT(p.chain.pitch_integral_e3(), 0);
  p.run(Mode::full, sample_at(0, 0), sticks(500, 300, -300), 500);
  EXPECT_GT(p.chain.roll_integral_e3(), roll_after_half_a_second);

  // Leaving full control for a tick and coming back: one tick's worth, not the old sum.
  p.tick(Mode::yaw, sample_at(0, 0), sticks(500, 300, -300));
  p.tick(Mode::full, sample_at(0, 0), sticks(500, 300, -300));
  EXPECT_GT(p.chain.roll_integral_e3(), 0);
  EXPECT_LT(p.chain.roll_integral_e3(), roll_after_half_a_second / 100);

  // Lift 0 (on the ground, or cut): empty, whatever the error.
  p.run(Mode::full, sample_at(0, 0), sticks(0, 300, -300), 300);
  EXPECT_EQ(p.chain.roll_integral_e3(), 0);
  EXPECT_EQ(p.chain.pitch_integral_e3(), 0);

  // Just above idle the moments do not fit and the mixer scales them: from the tick after the
  // first such mix (the controllers run before the mixer) the integrals hold.
  p.tick(Mode::full, sample_at(0, 0), sticks(200, 1000, -1000));
  const int32_t roll = p.chain.roll_integral_e3(), pitch = p.chain.pitch_integral_e3();
  EXPECT_LT(roll, roll_after_half_a_second / 100);
  p.run(Mode::full, sample_at(0, 0), sticks(200, 1000, -1000), 300);
  EXPECT_EQ(p.chain.roll_integral_e3(), roll);
  EXPECT_EQ(p.chain.pitch_integral_e3(), pitch);
}

// The landed detector (landed_detector.hpp): on the ground the accelerometer reads 1 g whatever
// the lift, and the integrals stay empty however long a stick is held; a climb (more than
// takeoff_mg, 1.1 g, for 50 ms) lets them work; lift 0 means landed again.
TEST(FlightChain, OnTheGroundTheIntegralsStayEmpty) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  EXPECT_TRUE(p.chain.landed());
  // 3 degrees of roll stick (100/1000 of 30) at lift 400 for 15 s: nothing winds up.
  p.run(Mode::full, sample_at(0, 0), sticks(400, 100, -100, 300), 15000);
  EXPECT_TRUE(p.chain.landed());
  EXPECT_EQ(p.chain.roll_integral_e3(), 0);
  EXPECT_EQ(p.chain.pitch_integral_e3(), 0);
  // A bump of 1.3 g for 30 ms is not a take-off; nor is 1.05 g for a second.
  p.run(Mode::full, climbing(1.3), sticks(400, 100, -100), 30);
  p.run(Mode::full, climbing(1.05), sticks(400, 100, -100), 1000);
  p.run(Mode::full, sample_at(0, 0), sticks(400, 100, -100), 100);
  EXPECT_TRUE(p.chain.landed());
  EXPECT_EQ(p.chain.roll_integral_e3(), 0);
  // Climbing at 1.2 g: flying 50 ms after the (20 Hz low-passed) reading passes 1.1 g, and the
  // integrals work.
  int ticks = 0;
  while (p.chain.landed() && ticks < 1000) {
    p.tick(Mode::full, climbing(1.2), sticks(600, 100, -100));
    ++ticks;
  }
  EXPECT_GE(ticks, 50);
  EXPECT_LE(ticks, 75);
  p.run(Mode::full, sample_at(0, 0), sticks(600, 100, -100), 500);
  EXPECT_FALSE(p.chain.landed());
  EXPECT_GT(p.chain.roll_integral_e3(), 0);
  EXPECT_LT(p.chain.pitch_integral_e3(), 0);
  // Lift 0: landed, emptied.
  p.run(Mode::full, sample_at(0, 0), sticks(0, 100, -100), 1);
  EXPECT_TRUE(p.chain.landed());
  EXPECT_EQ(p.chain.roll_integral_e3(), 0);
  EXPECT_EQ(p.chain.pitch_integral_e3(), 0);
}

// The angle loops' feed-forwards are wired (controllers.hpp, flight_chain.hpp). Banked 0.2 rad
// and yawing at 1 rad/s (Euler) with the set-point on the estimate, the roll loop must ask for
// q = r tan(roll) (0.199 rad/s) and nothing else; in flight, the drag moment adds drag_moment x
// the expected accelerometer angle (on a stand, lag 0: the angle, 0.2 rad x 150 = 30 thrust units).
wire::ParameterValues on_a_stand(int32_t drag_moment) {
  wire::ParameterValues p = quick_estimator();
  EXPECT_EQ(p.set(static_cast<uint8_t>(wire::ParamId::accel_lag_ms), 0), wire::NackReason::none);
  EXPECT_EQ(p.set(static_cast<uint8_t>(wire::ParamId::drag_moment), drag_moment), wire::NackReason::none);
  return p;
}

TEST(FlightChain, TheAngleLoopsFeedForwardTheRatesToHoldAndTheDragMoment) {
  const double roll = 0.2, yaw_rate = 1.0;
  const SensorSample turning = sample_at(roll, 0, 0, yaw_rate * std::sin(roll), yaw_rate * std::cos(roll));
  const int16_t stick = static_cast<int16_t>(std::lround(roll / 0.524 * 1000));  // max_tilt_mrad 524
  Pilot<FixedChain> with, without;
  with.chain.set_parameters(on_a_stand(150));
  without.chain.set_parameters(on_a_stand(0));
  for (auto* p : {&with, &without}) {
    p->calibrate_level();
    p->run(Mode::full, climbing(1.3), sticks(500), 100);  // off the ground
    // 2 s: the estimator's transient after the bank's step is over (its bias loop learns at 94 %
    // of its gain in this turn, attitude_estimator.hpp; after 1 s its false bias still left 4e-3
    // rad/s on p).
    p->run(Mode::full, turning, sticks(500, stick), 2000);
    EXPECT_FALSE(p->chain.landed());
    EXPECT_NEAR(p->chain.q_setpoint_e3(), 199, 2);  // r tan(roll) = cos(0.2) tan(0.2)
    EXPECT_NEAR(p->chain.p_setpoint_e3(), 0, 2);
  }
  // 150 thrust units per rad x the estimated roll (the expected angle on a stand), in 1e-3 units.
  EXPECT_NEAR(with.chain.moments_e3().roll - without.chain.moments_e3().roll, 15 * with.chain.roll_e4(), 20);
}

// What a live plot reads of the loops (the roll_p_term, roll_d_term, roll_integral, ... rows,
// 0.1 thrust units): with no drag feed-forward, each rate loop's P, D and integral add up to the
// moment the mixer was asked for, and they agree with the log's readouts in 1e-3 units. Banked
// 0.05 rad right, rolling, with sticks asking for another angle and a yaw rate, off the ground.
TEST(FlightChain, TheObservedTermsAddUpToTheMoments) {
  Pilot<FixedChain> p;
  p.chain.set_parameters(on_a_stand(0));
  p.calibrate_level();
  p.run(Mode::full, climbing(1.3), sticks(500), 100);  // off the ground
  p.run(Mode::full, sample_at(0.05, 0, 0.1), sticks(500, 300, -300, 200), 400);
  ASSERT_FALSE(p.chain.landed());
  for (int axis = 0; axis < 2; ++axis) {
    const int32_t pt = p.chain.p_term_e1(axis), dt = p.chain.d_term_e1(axis), it = p.chain.integral_e1(axis);
    EXPECT_NE(pt, 0) << "axis " << axis;
    EXPECT_NE(it, 0) << "axis " << axis;
    EXPECT_NEAR(p.chain.moment_e1(axis), pt + dt + it, 2) << "axis " << axis << ": each part rounded to 0.1";
  }
  EXPECT_NEAR(p.chain.moment_e1(2), p.chain.p_term_e1(2) + p.chain.integral_e1(2), 1) << "yaw: P and I";
  EXPECT_NE(p.chain.p_term_e1(2), 0);
  EXPECT_NEAR(p.chain.moment_e1(0) * 100, p.chain.moments_e3().roll, 50);
  EXPECT_NEAR(p.chain.moment_e1(1) * 100, p.chain.moments_e3().pitch, 50);
  EXPECT_NEAR(p.chain.integral_e1(0) * 100, p.chain.roll_integral_e3(), 50);
  EXPECT_NEAR(p.chain.integral_e1(1) * 100, p.chain.pitch_integral_e3(), 50);
  EXPECT_EQ(p.chain.rate_setpoint_e3(0), p.chain.p_setpoint_e3());
  EXPECT_EQ(p.chain.rate_setpoint_e3(1), p.chain.q_setpoint_e3());

  // Height hold's loops: the height at entry is held (no climb asked for at once), and the thrust
  // reads as the log's vertical_thrust_e3.
  p.chain.enter_height_hold();
  p.chain.fly({chain::Tilt::angle, chain::Yaw::rate, chain::Lift::hold});
  for (int n = 0; n < 8; ++n) {
    p.chain.estimate_height();
    p.chain.control_vertical();
  }
  EXPECT_NEAR(p.chain.climb_setpoint_mm_s(), 0, 50);
  EXPECT_NEAR(p.chain.vertical_thrust_e1() * 100, p.chain.vertical_thrust_e3(), 50);
  EXPECT_GT(p.chain.vertical_thrust_e1(), 0);
}

// takeoff_mg reaches the detector: at 1500 mg a 1.3 g climb is not a take-off, 1.6 g is.
TEST(FlightChain, TakeoffThresholdIsTheParameter) {
  Pilot<FixedChain> p;
  wire::ParameterValues values;
  ASSERT_EQ(values.set(static_cast<uint8_t>(wire::ParamId::takeoff_mg), 1500), wire::NackReason::none);
  p.chain.set_parameters(values);
  p.calibrate_level();
  p.run(Mode::full, climbing(1.3), sticks(600), 500);
  EXPECT_TRUE(p.chain.landed());
  p.run(Mode::full, climbing(1.6), sticks(600), 100);
  EXPECT_FALSE(p.chain.landed());
}

TEST(FlightChain, LiftZeroKeepsTheEnginesStopped) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  EXPECT_TRUE(p.run(Mode::full, sample_at(0.3, 0.2, 1, 1, 1), sticks(0, 1000, 1000, 1000), 10).all_zero());
  EXPECT_TRUE(p.run(Mode::manual, sample_at(0, 0), sticks(0, 1000, 1000, 1000), 10).all_zero());
}

// Test mode is a scheduler context (scheduler.hpp) over any chain, as the flight is.
static_assert(SchedulerContext<ReplayContext<FixedChain>> && SchedulerContext<ReplayContext<DoubleChain>>);

// The flight build against the double reference, tick by tick over the synthetic flight (the
// same data as the replay recording). The bounds are the measured worst differences, rounded up.
TEST(FlightChain, FixedFollowsDoubleOverTheSyntheticFlight) {
  FixedChain q;
  DoubleChain d;
  ChainReplay<FixedChain> rq(q);
  ChainReplay<DoubleChain> rd(d);
  chain::synthetic::Flight<1000> flight;
  double angle = 0, rate = 0, moment = 0;
  int engine = 0, engine_differs = 0, readout = 0;
  for (uint32_t n = 0; n < chain::synthetic::Flight<1000>::kTicks; ++n) {
    const auto t = flight.next();
    const wire::Mode mq = rq.tick(t.sample, t.sticks);
    ASSERT_EQ(mq, rd.tick(t.sample, t.sticks));
    if (mq != wire::Mode::full_control) continue;
    const EngineCommand eq = q.engines(), ed = d.engines();
    const auto& xq = q.estimator();
    const auto& xd = d.estimator();
    angle = std::max({angle, std::fabs(xq.roll().to_double() - xd.roll()),
                      std::fabs(xq.pitch().to_double() - xd.pitch()), std::fabs(xq.yaw().to_double() - xd.yaw())});
    rate = std::max({rate, std::fabs(xq.p().to_double() - xd.p()), std::fabs(xq.q().to_double() - xd.q()),
                     std::fabs(xq.r().to_double() - xd.r())});
    moment = std::max({moment, std::abs(q.moments_e3().roll - d.moments_e3().roll) / 1000.0,
                       std::abs(q.moments_e3().pitch - d.moments_e3().pitch) / 1000.0,
                       std::abs(q.moments_e3().yaw - d.moments_e3().yaw) / 1000.0});
    for (int k = 0; k < 4; ++k) {
      engine = std::max(engine, std::abs(eq.value[k] - ed.value[k]));
      engine_differs += eq.value[k] != ed.value[k];
    }
    readout = std::max({readout, std::abs(q.roll_e4() - d.roll_e4()), std::abs(q.pitch_e4() - d.pitch_e4()),
                        std::abs(q.p_e3() - d.p_e3()), std::abs(q.q_e3() - d.q_e3()), std::abs(q.r_e3() - d.r_e3())});
  }
  std::printf(
      "  Q vs double over %u ticks: angles %.2e rad, rates %.2e rad/s, moments %.2e thrust units, "
      "engines %d unit (%d values differ), telemetry read-outs %d unit\n",
      chain::synthetic::Flight<1000>::kTicks, angle, rate, moment, engine, engine_differs, readout);
  EXPECT_LE(angle, 1e-6);
  EXPECT_LE(rate, 1e-6);
  EXPECT_LE(moment, 1e-3);
  EXPECT_LE(engine, 1);
  EXPECT_LE(readout, 1);
}

// The float instantiation (the RV32 speed comparison's number type) is the same code: it runs,
// and lands near the double reference (float's 24-bit mantissa, not the algorithm, sets the gap).
TEST(FlightChain, FloatInstantiationFollowsDouble) {
  FlightChain<chain::FloatNumbers> f;
  DoubleChain d;
  ChainReplay<FlightChain<chain::FloatNumbers>> rf(f);
  ChainReplay<DoubleChain> rd(d);
  chain::synthetic::Flight<1000> flight;
  double angle = 0;
  int engine = 0;
  for (uint32_t n = 0; n < chain::synthetic::Flight<1000>::kTicks; ++n) {
    const auto t = flight.next();
    const wire::Mode mf = rf.tick(t.sample, t.sticks);
    ASSERT_EQ(mf, rd.tick(t.sample, t.sticks));
    if (mf != wire::Mode::full_control) continue;
    const EngineCommand ef = f.engines(), ed = d.engines();
    angle = std::max({angle, std::fabs(double(f.estimator().roll()) - d.estimator().roll()),
                      std::fabs(double(f.estimator().pitch()) - d.estimator().pitch())});
    for (int k = 0; k < 4; ++k) engine = std::max(engine, std::abs(ef.value[k] - ed.value[k]));
  }
  std::printf("  float vs double over the synthetic flight: angles %.2e rad, engines %d unit\n", angle, engine);
  EXPECT_LE(angle, 1e-6);
  EXPECT_LE(engine, 1);
}

// The estimate against the script's truth: filter lag, accelerometer noise, and the estimator's
// small-angle kinematics (it integrates body rates as Euler rates), not arithmetic. The worst
// error is in pitch during the yaw turn with the roll swinging: q then holds psi' sin(phi) of up to
// 0.12 rad/s that is no pitch rate, until the accelerometer pulls it back with time constant C1
// samples, which is twice as long in time at 500 Hz. Since issue 29 the landed detector sees the
// script's barometer climb (0.5 m/s at 1 g: a gentle take-off) and the chain flies it, with the
// estimator's drag model on; the script's sensors have no rotor drag, so the model's expected
// accelerometer angle is an error here that a real flight's drag would cancel (measured 0.0372 rad
// at 1 kHz, 0.0265 at 500 Hz; 0.0167 and 0.0162 with that sense disabled, i.e. on the ground).
template <uint32_t Hz>
void check_truth(double bound) {
  FlightChain<chain::FixedNumbers, Hz> c;
  ChainReplay<FlightChain<chain::FixedNumbers, Hz>> replay(c);
  chain::synthetic::Flight<Hz> flight;
  double worst = 0;
  for (uint32_t n = 0; n < chain::synthetic::Flight<Hz>::kTicks; ++n) {
    const auto t = flight.next();
    if (replay.tick(t.sample, t.sticks) != wire::Mode::full_control) continue;
    worst = std::max({worst, std::fabs(c.estimator().roll().to_double() - t.truth.roll.to_double()),
                      std::fabs(c.estimator().pitch().to_double() - t.truth.pitch.to_double())});
  }
  std::printf("  %u Hz: roll/pitch estimate within %.4f rad of the truth over the synthetic flight\n",
              static_cast<unsigned>(Hz), worst);
  EXPECT_LE(worst, bound);
}

TEST(FlightChain, EstimateFollowsTheTruthAt1kHz) { check_truth<1000>(0.04); }
TEST(FlightChain, EstimateFollowsTheTruthAt500Hz) { check_truth<500>(0.03); }

TEST(FlightChain, ReadoutsSaturateInsteadOfWrapping) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  SensorSample s = sample_at(0, 0);
  s.gyro[2] = 32767;  // 8.73 rad/s: 8731 in 1e-3 rad/s, fits
  p.run(Mode::full, s, sticks(0), 100);
  EXPECT_NEAR(p.chain.r_e3(), 8731, 1);
  EXPECT_EQ(p.chain.gyro_filtered(2), 32767);
  EXPECT_EQ(p.chain.accel_filtered(2), -8192);
}

}  // namespace
}  // namespace qr
