// Every cut-off the parameter table allows (filter_cutoff, 1..250 Hz in whole Hz), designed at
// compile time for the control rate and stored as coefficients of type C. A parameter change
// selects an entry; nothing is designed at run time, so the flight build needs no trigonometry
// and no division for it, and the design is the one qrfilter prints.
//
// Cost: one entry per Hz. At 1 kHz, 250 entries of 4 int32 coefficients (order 2, b2 = b0) are
// 4000 bytes of read-only data. Cut-offs must stay below fs/2: at 500 Hz the table ends at 249 Hz and larger
// requests take the last entry.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <qr/core/chain/butterworth_lowpass.hpp>

namespace qr::chain {

inline constexpr int32_t kMaxCutoffParameterHz = 250;

// The cut-offs a table for this sample rate holds: whole Hz from 1 to the largest below fs/2, at
// most what the parameter allows.
template <uint32_t SampleHz>
struct CutoffRange {
  static constexpr int32_t kLowestHz = 1;
  static constexpr int32_t kHighestHz = static_cast<int32_t>((SampleHz - 1) / 2) < kMaxCutoffParameterHz
                                            ? static_cast<int32_t>((SampleHz - 1) / 2)
                                            : kMaxCutoffParameterHz;
  static_assert(kHighestHz >= kLowestHz, "sample rate too low for the cut-off table");
  static constexpr size_t kSize = static_cast<size_t>(kHighestHz - kLowestHz + 1);

  static constexpr int32_t clamp(int32_t requested_hz) {
    return requested_hz < kLowestHz ? kLowestHz : requested_hz > kHighestHz ? kHighestHz : requested_hz;
  }
  static constexpr double hz_at(size_t i) { return static_cast<double>(kLowestHz) + static_cast<double>(i); }
};

template <class C, int Order, uint32_t SampleHz>
struct ButterworthEntries {
  typename IirOfOrder<Order>::template Coefficients<C> at[CutoffRange<SampleHz>::kSize];
};

template <class C, int Order, uint32_t SampleHz>
constexpr ButterworthEntries<C, Order, SampleHz> build_butterworth_entries() {
  using Range = CutoffRange<SampleHz>;
  ButterworthEntries<C, Order, SampleHz> e{};
  for (size_t i = 0; i < Range::kSize; ++i) {
    e.at[i] = coefficients_of<C, Order>(design_butterworth(Order, Range::hz_at(i), static_cast<double>(SampleHz)));
  }
  return e;
}

// Every quantised design fits its format (a Q coefficient that did not would wrap), and its
// numerator is symmetric (b2 = b0: the table keeps b0 for both, butterworth_lowpass.hpp).
template <class C, int Order, uint32_t SampleHz>
constexpr bool butterworth_entries_fit() {
  using Range = CutoffRange<SampleHz>;
  if constexpr (fx::is_q<C>) {
    for (size_t i = 0; i < Range::kSize; ++i) {
      const auto d = design_butterworth(Order, Range::hz_at(i), static_cast<double>(SampleHz));
      const QuantisedDesign q = quantise(d, C::frac_bits);
      if (!q.fits_int32() || (Order == 2 && q.b[2] != q.b[0])) return false;
    }
  }
  return true;
}

template <class C, int Order, uint32_t SampleHz>
struct ButterworthTable {
  using Range = CutoffRange<SampleHz>;
  using Coefficients = typename IirOfOrder<Order>::template Coefficients<C>;
  static_assert(butterworth_entries_fit<C, Order, SampleHz>(),
                "a designed coefficient does not fit the coefficient format, or b2 != b0");

  static constexpr ButterworthEntries<C, Order, SampleHz> kEntries = build_butterworth_entries<C, Order, SampleHz>();

  // The cut-off actually used for a requested one, and its coefficients.
  static constexpr int32_t cutoff_used(int32_t requested_hz) { return Range::clamp(requested_hz); }
  static constexpr const Coefficients& for_cutoff(int32_t requested_hz) {
    return kEntries.at[static_cast<size_t>(Range::clamp(requested_hz) - Range::kLowestHz)];
  }
};

}  // namespace qr::chain
