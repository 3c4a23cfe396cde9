// The log packing's model of the chain's filters (qr/core/log_pack/line_coder.hpp): a copy of the
// chain's mounting and filters (FlightChain::FilterCopy), taken at each keyframe and stepped with
// the logged raw samples, so that at a log divider of 1 the filtered counts cost one bit a line.
// Taken, its first prediction is the chain's output as it was taken: the logger runs after the
// filter task, which has already stepped the chain with the line's sample. A chain without a
// filter copy (a test's scripted one) predicts zeros: its filtered counts are coded in full.
#pragma once

#include <stdint.h>

#include <common/log_records.hpp>
#include <qr/core/board.hpp>

namespace qr {

template <class Chain>
concept CopiesItsFilters = requires(const Chain& c) {
  c.filter_copy();
};

struct NoFilterCopy {
  void step(const SensorSample&, int16_t (&counts)[6]) { output(counts); }
  void output(int16_t (&counts)[6]) const {
    for (int16_t& c : counts) c = 0;
  }
};

template <class Chain>
class ChainFilterModel {
 public:
  void take(const Chain& chain) {
    if constexpr (CopiesItsFilters<Chain>) copy_ = chain.filter_copy();
    taken_ = true;
  }
  // Out of line: one copy of the filters' step for the packing and the unpacking.
  [[gnu::noinline]] void predict(const wire::SensorLogRecord& raw, int16_t (&counts)[6]) {
    if (taken_) {
      copy_.output(counts);
      taken_ = false;
      return;
    }
    SensorSample s;
    for (int i = 0; i < 3; ++i) {
      s.gyro[i] = raw.gyro[i];
      s.accel[i] = raw.accel[i];
    }
    copy_.step(s, counts);
  }

 private:
  template <class C>
  static auto copy_type() {
    if constexpr (CopiesItsFilters<C>) {
      return typename C::FilterCopy{};
    } else {
      return NoFilterCopy{};
    }
  }
  decltype(copy_type<Chain>()) copy_{};
  bool taken_ = false;
};

}  // namespace qr
