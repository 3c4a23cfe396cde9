// The low-pass filters on the six sensor axes: counts to units, then one Butterworth low-pass per
// axis, all with the cut-off of the filter_cutoff parameter. The outputs are not calibrated:
// offsets are subtracted downstream (sensor_calibration.hpp), so the filters never see the step
// a finished calibration would otherwise put into their input.
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/chain/butterworth_table.hpp>
#include <qr/core/chain/chain_parameters.hpp>
#include <qr/core/chain/sensor_units.hpp>

namespace qr::chain {

inline constexpr int kSensorFilterOrder = 2;

template <class N, uint32_t SampleHz, int Order = kSensorFilterOrder>
class SensorFilters {
 public:
  using Rate = typename N::Rate;
  using Accel = typename N::Accel;
  using Table = ButterworthTable<typename N::Coefficient, Order, SampleHz>;
  using Units = SensorUnits<N>;

  explicit SensorFilters(int32_t cutoff_hz) { set_cutoff(cutoff_hz); }

  void set_cutoff(int32_t hz) {
    cutoff_hz_ = Table::cutoff_used(hz);
    coefficients_ = &Table::for_cutoff(hz);
  }
  int32_t cutoff_hz() const { return cutoff_hz_; }

  // The rate of one count per gyro axis (SensorUnits::rate_per_count, the gyro_scale_*_ppm
  // parameters): the scale is corrected where counts become units, in the multiply that is there.
  void set_gyro_scale(const Rate (&per_count)[3]) {
    for (int i = 0; i < 3; ++i) per_count_[i] = per_count[i];
  }

  // One sample. The first one settles the filters on itself, so start-up has no transient from
  // zero (the accelerometer reads -1 g on z at rest). Out of line: the log's packing steps a copy
  // of the filters too (FlightChain::FilterCopy), and the QR keeps one body for both.
  [[gnu::noinline]] void update(const SensorSample& s) {
    if (!started_) {
      for (int i = 0; i < 3; ++i) {
        gyro_[i].settle(Units::rate_of(s.gyro[i], per_count_[i]));
        accel_[i].settle(Units::accel_of(s.accel[i]));
      }
      started_ = true;
      return;
    }
    const auto c = *coefficients_;  // one cut-off for all six: a copy, so the state stores cannot alias it
    // One sensor after the other: the two kinds of stage (the accelerometer's fold its outer taps)
    // interleaved cost registers and spills (filter 320 -> 317 instructions a tick).
    for (int i = 0; i < 3; ++i) gyro_[i].step(c, Units::rate_of(s.gyro[i], per_count_[i]));
    for (int i = 0; i < 3; ++i) accel_[i].step(c, Units::accel_of(s.accel[i]));
  }

  // The next sample settles the filters again, as the first one did.
  void restart() { started_ = false; }

  Rate rate(int axis) const { return gyro_[axis].output(); }
  Accel accel(int axis) const { return accel_[axis].output(); }

 private:
  // The largest raw magnitude a filter input takes: the counts' full scale (int16) in the
  // signal's units. The accelerometer's, 2^29 in Q<27> (4 g), lets its filters fold the outer
  // taps (ButterworthStage); the gyro's, 1.30e9 (9.7 rad/s at the largest scale correction the
  // parameters allow), is more than half the Q<27> range.
  template <class T, T (*ToUnits)(int32_t)>
  static constexpr int64_t input_bound() {
    if constexpr (fx::is_q<T>) {
      const int64_t low = ToUnits(INT16_MIN).raw(), high = ToUnits(INT16_MAX).raw();
      return -low > high ? -low : high;
    } else {
      return kUnboundedInput;
    }
  }
  static constexpr Rate largest_rate_of(int32_t counts) {
    return Units::rate_of(counts, Units::rate_per_count(chain::parameter_spec(wire::ParamId::gyro_scale_x_ppm).min));
  }
  static constexpr int64_t kRateBound = input_bound<Rate, &largest_rate_of>();
  static constexpr int64_t kAccelBound = input_bound<Accel, &Units::template accel_of<0>>();
  using RateFilter = ButterworthStage<Rate, typename N::Coefficient, Order, kRateBound>;
  using AccelFilter = ButterworthStage<Accel, typename N::Coefficient, Order, kAccelBound>;

  const typename Table::Coefficients* coefficients_ = &Table::for_cutoff(1);
  Rate per_count_[3] = {Units::rate_per_count(0), Units::rate_per_count(0), Units::rate_per_count(0)};
  RateFilter gyro_[3] = {};
  AccelFilter accel_[3] = {};
  int32_t cutoff_hz_ = 0;
  bool started_ = false;
};

}  // namespace qr::chain
