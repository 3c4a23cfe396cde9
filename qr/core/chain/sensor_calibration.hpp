// Sensor calibration in safe/calibration mode, with the vehicle level and still: the average of
// kSamples raw samples gives the gyro zero-rate offsets and the accelerometer offsets that make
// a level vehicle read (0, 0, -1 g). The sums are integers (exact, the same in every number type);
// the power-of-two sample count makes the average a shift, so the offsets keep 9 fractional bits
// of a count instead of rounding to whole counts.
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/chain/sensor_units.hpp>

namespace qr::chain {

inline constexpr int kCalibrationShift = 9;

// The accelerometer axis whose mean read gravity where a level vehicle does not (docs/safety.md
// rule 21), or none.
enum class CalibrationAxis : uint8_t { none = 0, x, y, z };
inline constexpr const char* kCalibrationAxisNames[] = {"", "x", "y", "z"};

// The largest accelerometer offset a run takes: 0.25 g. The MPU-6050's zero-g offset is within
// +-50 mg on x and y and +-80 mg on z (product specification 6.2); a vehicle 10 degrees off level
// adds 0.17 g. More is gravity where the calibration does not expect it: a vehicle on its side,
// an IMU mounted turned or upside down, an axis read backwards. Taken, such an offset would make
// the estimate read level whatever the vehicle does: the vehicle would fly on a lie.
inline constexpr int32_t kCalibrationSamples = int32_t{1} << kCalibrationShift;  // 0.5 s at 1 kHz

template <class N>
class SensorCalibration {
 public:
  using Rate = typename N::Rate;
  using Accel = typename N::Accel;
  using Units = SensorUnits<N>;

  // Forgets the sums (not the offsets in use) and starts counting again.
  void restart() {
    for (int i = 0; i < 3; ++i) gyro_sum_[i] = accel_sum_[i] = 0;
    count_ = 0;
  }

  // Adds one raw sample; true once kSamples have been averaged (further samples are ignored
  // until restart()).
  bool add(const SensorSample& s) {
    if (count_ >= kCalibrationSamples) return true;
    for (int i = 0; i < 3; ++i) {
      gyro_sum_[i] += s.gyro[i];
      accel_sum_[i] += s.accel[i];
    }
    // Level reads -1 g on z: the offset is what is read beyond that.
    accel_sum_[2] += Units::kCountsPerGInt;
    if (++count_ < kCalibrationSamples) return false;
    refused_ = CalibrationAxis::none;
    for (int i = 0; i < 3; ++i) {
      const int32_t sum = accel_sum_[i];
      if (sum > kMaxAccelOffsetSum || sum < -kMaxAccelOffsetSum) {
        refused_ = static_cast<CalibrationAxis>(i + 1);
        return true;  // the run is over; the offsets in use stay
      }
    }
    for (int i = 0; i < 3; ++i) {
      gyro_offset_counts_[i] = gyro_sum_[i];
      accel_offset_[i] = Units::template accel_of<kCalibrationShift>(accel_sum_[i]);
    }
    done_ = true;
    convert_gyro_offsets();
    return true;
  }

  // The rate of one count per gyro axis (SensorUnits::rate_per_count): the offsets in use are
  // converted again, so a scale that changes after a calibration leaves no offset behind.
  void set_gyro_scale(const Rate (&per_count)[3]) {
    for (int i = 0; i < 3; ++i) per_count_[i] = per_count[i];
    convert_gyro_offsets();
  }

  // At least one calibration has finished since start-up.
  bool done() const { return done_; }
  // The last finished run took its offsets; refused(): the axis that made it refuse them.
  bool accepted() const { return refused_ == CalibrationAxis::none; }
  CalibrationAxis refused() const { return refused_; }
  int32_t samples() const { return count_; }

  Rate gyro_offset(int axis) const { return gyro_offset_[axis]; }
  // The gyro offsets in raw counts with kCalibrationShift fractional bits (the sums themselves).
  const int32_t (&gyro_offset_counts() const)[3] { return gyro_offset_counts_; }
  Accel accel_offset(int axis) const { return accel_offset_[axis]; }

 private:
  void convert_gyro_offsets() {
    if (!done_) return;
    for (int i = 0; i < 3; ++i) {
      gyro_offset_[i] = Units::template rate_of<kCalibrationShift>(gyro_offset_counts_[i], per_count_[i]);
    }
  }

  // 512 int16 samples: |sum| < 2^24, far inside int32.
  int32_t gyro_sum_[3] = {0, 0, 0};
  int32_t accel_sum_[3] = {0, 0, 0};
  int32_t count_ = 0;
  bool done_ = false;
  CalibrationAxis refused_ = CalibrationAxis::none;
  // 0.25 g over a run's samples, in the sums' units (counts x samples).
  static constexpr int32_t kMaxAccelOffsetSum = (Units::kCountsPerGInt / 4) * kCalibrationSamples;
  int32_t gyro_offset_counts_[3] = {0, 0, 0};
  Rate per_count_[3] = {Units::rate_per_count(0), Units::rate_per_count(0), Units::rate_per_count(0)};
  Rate gyro_offset_[3] = {};
  Accel accel_offset_[3] = {};
};

}  // namespace qr::chain
