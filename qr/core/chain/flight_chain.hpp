// The signal chain as the firmware runs it: one object, one method per scheduler task, data
// flowing one way through a tick:
//
//   set_pilot -> filter -> (calibrate) -> (estimate_accel_angles) -> estimate -> (estimate_height)
//             -> (control_vertical) -> (control_attitude) (control_yaw) -> mix
//
// Each method reads what the ones before it left and writes its own outputs; none reaches back.
// Which of them run in a tick, and how often, is the flight's task table (qr/core/flight_tasks.hpp);
// where each axis' moment and the lift come from is the mode's row (engine_sources.hpp), given by
// fly(); what happens on entering a mode is its mode table (enter_calibration,
// enter_attitude_control), called by the transition. Nothing here counts ticks.
//
// Num is the number policy: FixedNumbers in flight (FixedChain below); the host tests also run
// FlightChain<DoubleNumbers> (qr/host/real_numbers.hpp) as the accuracy reference. SampleHz is
// the control rate the designs and time steps are made for.
//
// The read-outs are the chain's own numbers (Num's Angle in rad, Rate in rad/s, Thrust in thrust
// units: engine_mixer.hpp); what the console sees of them is their observables' readers' to
// convert (qr/core/observable_readers.hpp). The same values as decimal integers (roll_e4(), ...),
// for the replay, the chain checksum and tests, come from the base, DecimalReadouts.
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <common/units.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/attitude_estimator.hpp>
#include <qr/core/chain/controllers.hpp>
#include <qr/core/chain/decimal_readouts.hpp>
#include <qr/core/chain/engine_mixer.hpp>
#include <qr/core/chain/engine_sources.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/gyro_clip.hpp>
#include <qr/core/chain/gyro_turns.hpp>
#include <qr/core/chain/height_estimator.hpp>
#include <qr/core/chain/identification.hpp>
#include <qr/core/chain/imu_mounting.hpp>
#include <qr/core/chain/landed_detector.hpp>
#include <qr/core/chain/pilot_setpoints.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/core/chain/sensor_filters.hpp>
#include <qr/core/chain/sign_check.hpp>
#include <qr/core/chain/vertical_controller.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

template <class Num, uint32_t SampleHz = kControlHz>
class FlightChain : public chain::DecimalReadouts<FlightChain<Num, SampleHz>> {
 public:
  using Numbers = Num;
  using Rate = typename Num::Rate;
  using Accel = typename Num::Accel;
  using Angle = typename Num::Angle;
  using Thrust = typename Num::Thrust;
  static constexpr uint32_t kSampleHz = SampleHz;

  // The task table runs estimate_accel_angles() (two atan2 and a square root, about 600 RV32
  // instructions) at 250 Hz, not every tick. The angles enter through C1, seconds in free flight
  // (docs/signal-chain.md), so an angle held for 4 ms changes nothing the filter can show; the
  // accelerometer is still low-passed at the full rate, so what is sampled has no content near
  // 125 Hz for the sampling to fold down.
  static constexpr uint32_t kAccelHz = 250;
  static constexpr uint32_t kAccelDivider = SampleHz > kAccelHz ? SampleHz / kAccelHz : 1;
  // The height estimate runs at 250 Hz too (on other ticks than the accelerometer angles: the
  // task table's phase): its fastest dynamics are the baro-inertial loop's 1/tau, and the
  // accelerometer it integrates is low-passed at the full rate, as for the angles.
  static constexpr uint32_t kHeightHz = 250;
  static constexpr uint32_t kHeightDivider = SampleHz > kHeightHz ? SampleHz / kHeightHz : 1;
  static constexpr uint32_t kHeightRunHz = SampleHz / kHeightDivider;  // its time step's rate

  FlightChain() { set_parameters(wire::ParameterValues{}); }

  // Called when a parameter changes (not per tick): the only place that divides.
  void set_parameters(const wire::ParameterValues& p) {
    using wire::ParamId;
    filters_.set_cutoff(p.get(ParamId::filter_cutoff_hz));
    const Rate per_count[3] = {Units::rate_per_count(p.get(ParamId::gyro_scale_x_ppm)),
                               Units::rate_per_count(p.get(ParamId::gyro_scale_y_ppm)),
                               Units::rate_per_count(p.get(ParamId::gyro_scale_z_ppm))};
    filters_.set_gyro_scale(per_count);
    for (int i = 0; i < 3; ++i) clip_angle_[i] = chain::product<typename Num::Scale>(per_count[i], kDt);
    calibration_.set_gyro_scale(per_count);
    gyro_turns_ = p.get(ParamId::gyro_turns);
    estimator_.set_divisors(p.get(ParamId::attitude_c1), p.get(ParamId::attitude_c2));
    estimator_.set_lag(p.get(ParamId::accel_lag_ms));
    landed_.set_takeoff(p.get(ParamId::takeoff_mg));
    touchdown_.set_descent(p.get(ParamId::panic_descent_mm_s));
    yaw_.set_gains(p.get(ParamId::yaw_p), p.get(ParamId::yaw_i));
    for (auto& axis : tilt_) {
      axis.set_gains(p.get(ParamId::roll_pitch_p1), p.get(ParamId::roll_pitch_p2), p.get(ParamId::roll_pitch_i),
                     p.get(ParamId::roll_pitch_d));
    }
    drag_moment_ = Num::template fixed<0>(p.get(ParamId::drag_moment));
    pilot_.set_max_yaw_rate(p.get(ParamId::max_yaw_rate_rad_s));
    pilot_.set_max_tilt(p.get(ParamId::max_tilt_mrad));
    mixer_.set_idle(p.get(ParamId::idle_level));
    mounting_ = chain::imu_mounting(p.get(ParamId::imu_orientation));
    mounted_as_drawn_ = p.get(ParamId::imu_orientation) == 0;
  }

  // Latest sticks -> set-points (angles, yaw rate) and open-loop moments; every tick.
  // The lift's thrust with them (the landed detector reads it every tick).
  void set_pilot(const ControlInput& c) {
    pilot_.update(c);
    pilot_thrust_ = mixer_.thrust_of_lift(pilot_.lift());
  }

  // Task "filter": one raw sample, turned from the IMU board's axes into the body's
  // (imu_mounting.hpp), through the low-pass filters.
  void filter(const SensorSample& s) {
    sample_ = mounted_as_drawn_ ? s : chain::mounted(mounting_, s);  // as drawn: no copy to turn
    filters_.update(sample_);
    for (int i = 0; i < 3; ++i) clipped_[i] += clips_[i].update(sample_.gyro[i]);
  }

  // Task "calibration": averages the samples filter() was given; true once this run is done.
  // A run starts at enter_calibration() (the calibration mode's entry action). A finished run
  // restarts the estimator from the accelerometer's angles; until the next run finishes, the
  // previous offsets stay in use. With the gyro_turns parameter set, the run goes on after the
  // average with the turns (gyro_turns.hpp), and is done when they end (take_gyro_turns()).
  bool calibrate() {
    if (turns_.running()) {
      turns_ended_ = turns_.add(sample_);
      return turns_ended_;
    }
    // At a run's first sample the filters start over: they settle on the next one (the vehicle is
    // at rest), so what they hold when the run ends is made of the run's own samples, whatever
    // ran before it. A replay of a recording that starts with the run (docs/replay.md) then
    // computes what the flight did, bit for bit. The offsets are sums of raw samples: not moved.
    if (calibration_.samples() == 0) filters_.restart();
    const bool was_done = calibration_.samples() >= chain::kCalibrationSamples;
    height_.add_calibration(sample_.pressure_pa);
    const bool done = calibration_.add(sample_);
    if (done && !was_done && calibration_.accepted()) {
      check_signs();
      estimator_.restart();
      height_.zero_reference();  // the height estimate counts from here
      if (gyro_turns_ > 0) {
        turns_.start(gyro_turns_, calibration_.gyro_offset_counts());
        return false;
      }
    }
    return done;
  }
  // When the run calibrate() has just finished measured turns: their result, once (the flight
  // writes it to the parameters and sets gyro_turns back to 0); else nullptr.
  const chain::GyroTurnsResult* take_gyro_turns() {
    if (!turns_ended_) return nullptr;
    turns_ended_ = false;
    return &turns_.result();
  }
  const chain::GyroTurns<SampleHz>& gyro_turns() const { return turns_; }
  // The attitude estimator starts over from the accelerometer's angles, with no bias, at its next
  // run (for a vehicle at rest: its divisors or the IMU's mounting changed on the ground); the
  // filters start over too, so those angles are the new mounting's, not a mix of the old.
  void restart_estimator() {
    filters_.restart();
    estimator_.restart();
  }
  void enter_calibration() {
    turns_.cancel();
    turns_ended_ = false;
    calibration_.restart();
    height_.restart_calibration();
  }
  // Offsets exist (some calibration run has finished since start-up).
  bool calibrated() const { return calibration_.done(); }
  // The last run ended without taking its offsets: the accelerometer read gravity off body z on
  // this axis (sensor_calibration.hpp); none once a run is taken.
  chain::CalibrationAxis calibration_refused() const { return calibration_.refused(); }
  // The sign check's verdict (sign_check.hpp): the probe's at the last calibration, or the
  // wrong-way monitor's in the flight after it; none until either finds an axis.
  chain::SignAxis wrong_sign() const { return wrong_sign_; }

  // Task "accel angles": calibrated filtered accelerometer -> its roll and pitch angles, which
  // the estimator corrects towards until they are taken again.
  void estimate_accel_angles() {
    Accel accel[3];
    for (int i = 0; i < 3; ++i) accel[i] = filters_.accel(i) - calibration_.accel_offset(i);
    estimator_.update_accel(accel);
  }

  // Task "estimator": calibrated filtered sensors -> attitude, bias-corrected rates, and whether
  // the vehicle is on the ground (landed_detector.hpp: from the thrust, the accelerometer and the
  // height estimate; a landing's touchdown only near the ground).
  void estimate() {
    Rate rate[3];
    for (int i = 0; i < 3; ++i) rate[i] = filters_.rate(i) - calibration_.gyro_offset(i);
    // The whole specific force only for a (re)start; every tick needs just its z.
    if (!estimator_.started()) {
      Accel accel[3];
      for (int i = 0; i < 3; ++i) accel[i] = filters_.accel(i) - calibration_.accel_offset(i);
      estimator_.start(accel);
    }
    estimator_.update_rates(rate, landed_.landed());  // on the ground (last tick's verdict): no drag lag
    if (monitor_.watching() || kick_.pushed_axes() != 0) watch_signs();
    if ((clipped_[0] | clipped_[1] | clipped_[2]) != 0) take_clipped_turns();
    // The thrust the mixer is asked for: the pilot's lift, or the vertical loops' (height hold, a
    // landing) from their last run.
    const Accel accel_z = filters_.accel(2) - calibration_.accel_offset(2);
    const Thrust thrust = sources_.lift == chain::Lift::stick ? pilot_thrust_ : vertical_.thrust();
    landed_.update({thrust, accel_z, height_.height(), height_.climb()});
    if (sources_.lift == chain::Lift::descend && touchdown_.impact(accel_z)) landed_.touch_down(height_.height());
  }

  // What the gyro missed at full scale (gyro_clip.hpp), counts x samples -> angles, into the
  // estimate once.
  void take_clipped_turns() {
    Angle missed[3];
    for (int i = 0; i < 3; ++i) {
      missed[i] = chain::product_sat<Angle>(Num::template fixed<0>(clipped_[i]), clip_angle_[i]);
      clipped_[i] = 0;
    }
    estimator_.turn(missed);
  }

  // Task "height": calibrated filtered accelerometer, the attitude estimate and the barometer ->
  // height and vertical speed (height_estimator.hpp).
  void estimate_height() {
    Accel accel[3];
    for (int i = 0; i < 3; ++i) accel[i] = filters_.accel(i) - calibration_.accel_offset(i);
    height_.update(accel, estimator_.roll(), estimator_.pitch(), sample_.pressure_pa);
  }

  // ---- where the engines' command comes from (engine_sources.hpp): the mode's row ----
  // Set by the flight's one door for mode changes (flight.hpp), for the tasks and the mixer that
  // follow; the vertical loops' starts below are entry actions of their own.
  void fly(chain::EngineSources sources) { sources_ = sources; }
  chain::EngineSources sources() const { return sources_; }
  // Entry action of the autotune: its identification sequence from the start (identification.hpp).
  void enter_identification() { identification_.start(); }
  bool identification_over() const { return identification_.done(); }
  // Entry action of height hold: the height now is held, starting from the thrust the pilot's
  // lift gave.
  void enter_height_hold() { vertical_.start(mixer_.thrust_of_lift(pilot_.lift()), height_.height()); }
  // Entry action of a panic that lands: level, descending at panic_descent_mm_s from the hover
  // thrust the landed detector learnt, or before any was learnt from the thrust of `flying_lift`
  // (engine units: the mean of the last quarter second, which an upset that held one engine full
  // and its opposite at idle puts far above the hover), until touchdown. A lift stick let go just
  // before the panic made the landed detector say "landed"; the vehicle is flying until the
  // touchdown says not.
  void start_descent(uint16_t flying_lift) {
    vertical_.start(landed_.hover_known() ? landed_.hover() : mixer_.thrust_of_lift(flying_lift), height_.height());
    touchdown_.start();
    landed_.take_off();
  }

  // Task "vertical": after the height estimate, at its rate: the thrust the vertical loops ask
  // for, and in a landing the touchdown.
  void control_vertical() {
    if (sources_.lift == chain::Lift::stick) return;
    const Climb want = sources_.lift == chain::Lift::hold ? vertical_.climb_to_hold(height_.height())
                                                          : -touchdown_.descent();
    vertical_.update(want, height_.climb(), !landed_.landed());
    if (sources_.lift == chain::Lift::descend && touchdown_.update(height_.climb()))
      landed_.touch_down(height_.height());
  }

  // Entry action of yaw and full control: the yaw loop's integral starts empty.
  void enter_yaw_control() {
    yaw_.reset();
    yaw_entered_ = true;
  }

  // Task "yaw control": the yaw moment from the yaw rate loop. (Roll and pitch stay with the
  // sticks unless the attitude controller runs in the same tick.) The integral stays empty while
  // the lift stick is at 0 and holds while the mixer had to scale the last moments down, as the
  // attitude loops' do.
  void control_yaw() {
    if (landed_.landed()) yaw_.reset();
    // The integral learns only while the loop flies the yaw (not in manual's open loop).
    const bool integrate = !landed_.landed() && sources_.yaw != chain::Yaw::stick &&
                           (yaw_entered_ || !mixer_.limited());
    yaw_entered_ = false;
    yaw_moment_ = yaw_.moment(yaw_rate_target(), estimator_.r(), integrate);
  }

  // Entry action of full control: the rate loops' integrals start empty, and the first tick
  // integrates whatever the mixer did in the mode before.
  void enter_attitude_control() {
    for (auto& axis : tilt_) axis.reset();
    attitude_entered_ = true;
  }

  // Task "attitude control": the roll and pitch moments from the angle/rate cascades, with two
  // feed-forwards: the body rates that hold the angles while yawing, and the moment against the
  // rotors' drag. That drag acts at the hubs, above the centre of mass, and tilts a moving
  // vehicle back toward level; it grows with the speed, so in a held bank it ramps up for
  // seconds, faster than the integral follows (a 30 degree bank sagged 1.3 degrees). The
  // accelerometer reads the same drag (docs/signal-chain.md): the moment is mass x hub height x
  // the drag's specific force, i.e. drag_moment (m g h in thrust units) x the accelerometer angle
  // the estimator's drag model expects (smooth, where the reading itself carries vibration).
  // The rate loops' integrals stay
  // empty while the vehicle is on the ground (the landed detector: from lift 0 until it climbs
  // off), hold while the mixer had to scale the last moments down, and learn only while the loops
  // fly roll and pitch (in yaw control the task runs, for a panic's landing to find fresh moments,
  // but the sticks fly). Acro (Tilt::rate) runs the rate loops alone, to the sticks' rates.
  void control_attitude() {
    if (landed_.landed()) {
      for (auto& axis : tilt_) axis.reset();
    }
    const bool integrate = !landed_.landed() && sources_.tilt != chain::Tilt::stick &&
                           (attitude_entered_ || !mixer_.limited());
    attitude_entered_ = false;
    if (sources_.tilt == chain::Tilt::rate) {
      roll_moment_ = tilt_[0].rate_moment(pilot_.roll_rate(), estimator_.p(), integrate);
      pitch_moment_ = tilt_[1].rate_moment(pilot_.pitch_rate(), estimator_.q(), integrate);
      return;
    }
    // On the ground nothing moves, so there is no drag (and the expected angle is the tilt).
    const auto drag = landed_.landed() ? typename Num::template Fixed<0>{} : drag_moment_;
    roll_moment_ = tilt_[0].moment(roll_target(), estimator_.roll(), estimator_.p(), integrate, estimator_.p_to_hold(),
                                   chain::product_sat<Thrust>(drag, estimator_.roll_expected()));
    pitch_moment_ = tilt_[1].moment(pitch_target(), estimator_.pitch(), estimator_.q(), integrate,
                                    estimator_.q_to_hold(),
                                    chain::product_sat<Thrust>(drag, estimator_.pitch_expected()));
  }

  // Task "mixer": lift and moments -> engines, each from where the sources say (the mode's row):
  // the sticks' moments or the loops', the pilot's lift or the vertical loops'. Every mode whose
  // sources name a loop runs that loop's task in its set, and so does every set a transition into
  // it can start from (flight_tasks.hpp), so a moment read here is this tick's. Always inlined, as
  // the mixer's own steps are (engine_mixer.hpp says why).
  [[gnu::always_inline]] inline EngineCommand mix(chain::EngineSources from) {
    const bool sticks = from.tilt == chain::Tilt::stick;
    moments_.roll = sticks ? pilot_.roll_moment() : roll_moment_;
    moments_.pitch = sticks ? pilot_.pitch_moment() : pitch_moment_;
    moments_.yaw = from.yaw == chain::Yaw::stick ? pilot_.yaw_moment() : yaw_moment_;
    if (from.excite == chain::Excite::prbs) excite();
    if (kick_.kicking()) kick();
    if (from.lift != chain::Lift::stick) return engines_ = mixer_.mix_thrust(vertical_.thrust(), moments_);
    return engines_ = mixer_.mix(pilot_.lift(), moments_);
  }
  [[gnu::always_inline]] inline EngineCommand mix() { return mix(sources_); }

  // ---- read-outs, in the chain's own numbers ----
  // The attitude estimate and the bias-corrected rates.
  Angle roll() const { return estimator_.roll(); }
  Angle pitch() const { return estimator_.pitch(); }
  Angle yaw() const { return estimator_.yaw(); }
  Rate p() const { return estimator_.p(); }
  Rate q() const { return estimator_.q(); }
  Rate r() const { return estimator_.r(); }
  // What the loops fly to: the pilot's sticks, or level and not turning in a landing.
  Angle roll_setpoint() const { return roll_target(); }
  Angle pitch_setpoint() const { return pitch_target(); }
  Rate yaw_rate_setpoint() const { return yaw_rate_target(); }
  uint16_t lift() const { return pilot_.lift(); }
  // On the ground (landed_detector.hpp): the controllers' integrals are held empty.
  bool landed() const { return landed_.landed(); }
  // The hover lift the landed detector learnt in flight, engine units (0: not learnt yet), at most
  // full lift. The detector learns the thrust asked for, which near full lift passes what the
  // engines give (1100 asked at 1 g teaches 1049), and engine_of_thrust holds only up to full
  // thrust as the mixer calls it (past 1048.6 its root's seed table ends: on the host a division
  // by zero); telemetry_height's 0..1000 refuses more (docs/protocol.md).
  uint16_t hover_lift() const {
    const Thrust hover = landed_.hover();
    const Thrust full = chain::EngineMixer<Num>::kFullThrust;
    return static_cast<uint16_t>(mixer_.engine_of_thrust(hover < full ? hover : full));
  }
  // The larger of |roll| and |pitch|: the tilt from level.
  Angle tilt() const {
    const Angle roll = chain::magnitude(estimator_.roll());
    const Angle pitch = chain::magnitude(estimator_.pitch());
    return pitch < roll ? roll : pitch;
  }
  // The safety machine's, in its parameters' unit (it reads it every tick): one conversion of the
  // larger magnitude, which scaling and rounding keep the larger of the two converted.
  int32_t tilt_mrad() const { return Num::round_to_int(fx::mul_wide(tilt(), kThousand)); }

  // For the sensor log: filtered (not calibrated) sensors in counts. The last engine values.
  int16_t gyro_filtered(int axis) const { return Units::gyro_counts(filters_.rate(axis)); }
  int16_t accel_filtered(int axis) const { return Units::accel_counts(filters_.accel(axis)); }

  // The mounting and the filters as they are now, for the log's packing to run on the logged raw
  // samples: what it computes is what filter() computed from them, so the filtered counts it
  // predicts are the log's, bit for bit, while the copy stays in step (qr/core/log_pack).
  class FilterCopy {
   public:
    FilterCopy() = default;
    FilterCopy(const chain::SensorFilters<Num, SampleHz>& f, const drivers::ChipToBody& m, bool as_drawn)
        : filters_(f), mounting_(m), as_drawn_(as_drawn) {}
    // One raw sample through; the filtered gyro then accelerometer counts.
    void step(const SensorSample& raw, int16_t (&counts)[6]) {
      filters_.update(as_drawn_ ? raw : chain::mounted(mounting_, raw));
      output(counts);
    }
    [[gnu::noinline]] void output(int16_t (&counts)[6]) const {
      for (int i = 0; i < 3; ++i) {
        counts[i] = Units::gyro_counts(filters_.rate(i));
        counts[3 + i] = Units::accel_counts(filters_.accel(i));
      }
    }

   private:
    chain::SensorFilters<Num, SampleHz> filters_{1};
    drivers::ChipToBody mounting_ = chain::kImuMountings[0];
    bool as_drawn_ = true;
  };
  FilterCopy filter_copy() const { return {filters_, mounting_, mounted_as_drawn_}; }
  const EngineCommand& engines() const { return engines_; }
  int32_t cutoff_hz() const { return filters_.cutoff_hz(); }

  // The height estimate, up, relative to the height at the last calibration: height in m (in mm
  // for the safety machine) and vertical speed in m/s; the estimator itself has the rest
  // (height_estimator()). All 0 while there is no barometer reference (height_valid() false: no
  // calibration yet, or no barometer in it).
  bool height_valid() const { return height_.has_reference(); }
  typename Num::Height height() const { return height_.height(); }
  int32_t height_mm() const { return Num::round_to_int(fx::mul_wide(height_.height(), kThousand)); }
  typename Num::Climb climb() const { return height_.climb(); }

  // ---- the controllers' terms as they were last formed, for live plots (observables) ----
  // Read by the stream task, never per tick: the loops only store them. In thrust units; axis 0
  // roll, 1 pitch, 2 yaw (which has no derivative and no rate set-point).
  Rate rate_setpoint(int axis) const { return tilt_[axis].rate_setpoint(); }
  Thrust p_term(int axis) const { return axis < 2 ? tilt_[axis].p_term() : yaw_.p_term(); }
  Thrust d_term(int axis) const { return tilt_[axis].d_term(); }
  Thrust integral(int axis) const { return axis < 2 ? tilt_[axis].integral() : yaw_.integral(); }
  // What the last mix was asked for (the controllers' outputs, or the sticks' where none ran),
  // all three, and what the mixer realised of them.
  Thrust moment(int axis) const { return axis == 0 ? moments_.roll : axis == 1 ? moments_.pitch : moments_.yaw; }
  const chain::Moments<Thrust>& moments() const { return moments_; }
  const chain::Moments<Thrust>& applied_moments() const { return mixer_.applied(); }
  // The vertical loops' last run (height hold, a landing): climb set-point in m/s, the speed
  // loop's P term and integral in m/s², the per-engine thrust.
  typename Num::Climb climb_setpoint() const { return vertical_.climb_setpoint(); }
  typename Num::VerticalAccel vertical_p_term() const { return vertical_.p_term(); }
  typename Num::VerticalAccel vertical_integral() const { return vertical_.integral(); }
  Thrust vertical_thrust() const { return vertical_.thrust(); }

  // The blocks themselves, for tests and tools that look inside.
  const chain::AttitudeEstimator<Num, SampleHz>& estimator() const { return estimator_; }
  const chain::SensorCalibration<Num>& calibration() const { return calibration_; }
  const chain::HeightEstimator<Num, kHeightRunHz>& height_estimator() const { return height_; }

 private:
  using Units = chain::SensorUnits<Num>;
  using Count = typename Num::template Fixed<0>;
  using Climb = typename Num::Climb;

  // The sign check's probe on copies of the loops and the mixer, and the monitor armed for the
  // next flight (sign_check.hpp), at the end of every calibration that is taken.
  void check_signs() {
    struct Loops {
      chain::AttitudeController<Num, SampleHz> roll, pitch;
      chain::YawRateController<Num, SampleHz> yaw;
      chain::Moments<Thrust> answer(int axis) {
        constexpr Angle kOff = chain::kProbeAngle<Angle>;
        constexpr Rate kTurning = chain::kProbeYawRate<Rate>;
        if (axis == 0) return {roll.moment(Angle{}, kOff, Rate{}), {}, {}};
        if (axis == 1) return {{}, pitch.moment(Angle{}, kOff, Rate{}), {}};
        return {{}, {}, yaw.moment(Rate{}, kTurning)};
      }
    } loops{tilt_[0], tilt_[1], yaw_};
    loops.roll.reset();
    loops.pitch.reset();
    loops.yaw.reset();
    chain::EngineMixer<Num> mixer = mixer_;
    wrong_sign_ = chain::probe_signs(loops, mixer, mixer_.thrust_of_lift(chain::kProbeLift));
    monitor_.arm();
    kick_.arm();
  }
  // The identification's moment this tick, added to its axis' (out of line: the autotune's only).
  [[gnu::noinline]] void excite() {
    const uint8_t axis = identification_.axis();
    const Thrust added = identification_.step();
    if (axis == 0) moments_.roll = moments_.roll + added;
    if (axis == 1) moments_.pitch = moments_.pitch + added;
    if (axis == 2) moments_.yaw = moments_.yaw + added;
  }
  // One tick of the wrong-way monitor, in its units: the last mix's moments, the rates now. Judged
  // only with the engines turning and the sticks asking for no motion (a rate the pilot asked
  // for, braked as the stick comes back, is no wrong answer: sign_check.hpp); the conversions
  // only then.
  [[gnu::noinline]] void watch_signs() {
    const bool still = chain::magnitude(roll_target()) < kStillAngle &&
                       chain::magnitude(pitch_target()) < kStillAngle &&
                       chain::magnitude(yaw_rate_target()) < kStillRate;
    const int32_t angle[2] = {Num::round_to_int(fx::mul_wide(estimator_.roll(), kThousand)),
                              Num::round_to_int(fx::mul_wide(estimator_.pitch(), kThousand))};
    const bool quiet = still && !engines_.all_zero() && sources_.tilt == chain::Tilt::angle;
    const chain::SignAxis answered = kick_.update(quiet, landed_.lifting(), angle);
    if (answered != chain::SignAxis::none) wrong_sign_ = answered;
    if (!still || engines_.all_zero()) return;
    const int32_t moment[3] = {Num::round_to_int(moments_.roll), Num::round_to_int(moments_.pitch),
                               Num::round_to_int(moments_.yaw)};
    const int32_t rate[3] = {Num::round_to_int(fx::mul_wide(estimator_.p(), kThousand)),
                             Num::round_to_int(fx::mul_wide(estimator_.q(), kThousand)),
                             Num::round_to_int(fx::mul_wide(estimator_.r(), kThousand))};
    // An axis the kick pushes is not the monitor's: a push reversed, with the rate it made still
    // growing, is what the monitor looks for.
    const uint8_t loops = static_cast<uint8_t>(
        ((sources_.tilt != chain::Tilt::stick ? 3u : 0u) | (sources_.yaw != chain::Yaw::stick ? 4u : 0u)) &
        ~kick_.pushed_axes());
    const chain::SignAxis found = monitor_.update(moment, rate, loops, landed_.landed(), true);
    if (found != chain::SignAxis::none) wrong_sign_ = found;
  }
  // The lift-off kick's push this tick, added to the tilt loops' moments (sign_check.hpp).
  [[gnu::noinline]] void kick() {
    moments_.roll = moments_.roll + kKick * kick_.push(0);
    moments_.pitch = moments_.pitch + kKick * kick_.push(1);
  }

  // What the loops fly to: the pilot's sticks, or level and not turning in a landing.
  Angle roll_target() const { return sources_.tilt == chain::Tilt::level ? Angle{} : pilot_.roll_angle(); }
  Angle pitch_target() const { return sources_.tilt == chain::Tilt::level ? Angle{} : pilot_.pitch_angle(); }
  Rate yaw_rate_target() const { return sources_.yaw == chain::Yaw::still ? Rate{} : pilot_.yaw_rate(); }

  static constexpr Count kThousand = Count(1000.0);
  static constexpr Angle kStillAngle = Angle(0.05);  // 3 degrees of stick
  static constexpr Rate kStillRate = Rate(0.1);

  static constexpr typename Num::Scale kDt = typename Num::Scale(1.0 / SampleHz);

  chain::SensorFilters<Num, SampleHz> filters_{chain::parameter_spec(wire::ParamId::filter_cutoff_hz).default_value};
  chain::SensorCalibration<Num> calibration_;
  chain::GyroTurns<SampleHz> turns_;
  int32_t gyro_turns_ = 0;  // the parameter: turns the next calibration run measures after its average
  bool turns_ended_ = false;
  chain::ClipBridge clips_[3];              // per gyro axis: the turn it missed at full scale
  int32_t clipped_[3] = {};                 // ... counts x samples, not yet in the estimate
  typename Num::Scale clip_angle_[3] = {};  // rad per count x sample: the gyro's scale x dt
  chain::AttitudeEstimator<Num, SampleHz> estimator_;
  chain::HeightEstimator<Num, kHeightRunHz> height_;
  chain::PilotSetpoints<Num> pilot_;
  chain::YawRateController<Num, SampleHz> yaw_;
  chain::AttitudeController<Num, SampleHz> tilt_[2];  // roll, pitch
  chain::EngineMixer<Num> mixer_;
  chain::LandedDetector<Num, SampleHz> landed_;
  chain::VerticalController<Num, kHeightRunHz> vertical_;
  chain::TouchdownDetector<Num, kHeightRunHz, SampleHz> touchdown_;
  chain::EngineSources sources_ = chain::kOpenLoop;       // the mode's row (fly())
  Thrust pilot_thrust_{};                                 // thrust_of_lift(pilot_.lift()), made when the sticks change
  typename Num::template Fixed<0> drag_moment_{};         // thrust units per rad of expected accelerometer angle
  Thrust roll_moment_{}, pitch_moment_{}, yaw_moment_{};  // the controllers' latest outputs
  chain::Moments<Thrust> moments_{};                      // what the last mix asked for
  EngineCommand engines_{};
  SensorSample sample_{};
  bool attitude_entered_ = false;  // full control entered: the next control_attitude() integrates
  bool yaw_entered_ = false;       // yaw or full control entered: the next control_yaw() integrates
  drivers::ChipToBody mounting_ = chain::kImuMountings[0];  // imu_orientation's row
  bool mounted_as_drawn_ = true;
  chain::WrongWayMonitor monitor_;
  chain::LiftOffKick kick_;
  // The lift-off kick's push (sign_check.hpp): 150 thrust units (15 % of an engine's full thrust;
  // about 30 rad/s^2 on the simulator's vehicle).
  static constexpr Thrust kKick = Thrust(150.0);
  chain::SignAxis wrong_sign_ = chain::SignAxis::none;
  // The autotune's moments: 40 thrust units on roll and pitch (about 0.09 N m on the simulator's
  // vehicle, 8 rad/s^2: the loops hold the vehicle within about 2 degrees), 150 on yaw, whose
  // moment per thrust unit is 14 times smaller (the rotors' drag, not the arm).
  chain::IdentificationSequence<Thrust, SampleHz> identification_{Thrust(40.0), Thrust(150.0)};
};

using FixedChain = FlightChain<chain::FixedNumbers>;

}  // namespace qr
