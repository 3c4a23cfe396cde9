// The low-pass filters on the six sensor axes: counts to units, then one Butterworth low-pass per
// axis, all with the cut-off of the filter_cutoff parameter. The outputs are not calibrated:
// offsets are subtracted downstream (sensor_calibration.hpp), so the filters never see the step
// a finished calibration would otherwise put into their input.
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/chain/butterworth_table.hpp>
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
    const auto& c = Table::for_cutoff(hz);
    for (int i = 0; i < 3; ++i) {
      gyro_[i].use(c);
      accel_[i].use(c);
    }
  }
  int32_t cutoff_hz() const { return cutoff_hz_; }

  // One sample. The first one settles the filters on itself, so start-up has no transient from
  // zero (the accelerometer reads -1 g on z at rest).
  void update(const SensorSample& s) {
    for (int i = 0; i < 3; ++i) {
      const Rate r = Units::rate_of(s.gyro[i]);
      const Accel a = Units::accel_of(s.accel[i]);
      if (started_) {
        gyro_[i].step(r);
        accel_[i].step(a);
      } else {
        gyro_[i].settle(r);
        accel_[i].settle(a);
      }
    }
    started_ = true;
  }

  // The next sample settles the filters again, as the first one did.
  void restart() { started_ = false; }

  Rate rate(int axis) const { return gyro_[axis].output(); }
  Accel accel(int axis) const { return accel_[axis].output(); }

 private:
  using RateFilter = ButterworthLowpass<Rate, typename N::Coefficient, Order>;
  using AccelFilter = ButterworthLowpass<Accel, typename N::Coefficient, Order>;
  static constexpr const auto& kStart = Table::for_cutoff(1);

  RateFilter gyro_[3] = {RateFilter(kStart), RateFilter(kStart), RateFilter(kStart)};
  AccelFilter accel_[3] = {AccelFilter(kStart), AccelFilter(kStart), AccelFilter(kStart)};
  int32_t cutoff_hz_ = 0;
  bool started_ = false;
};

}  // namespace qr::chain
