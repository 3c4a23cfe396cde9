// One low-pass filter on one signal: the state of a 1st- or 2nd-order IIR filter (direct form I,
// with the state and coefficient types of fixedpoint/iir.hpp) and the coefficients it runs with.
// Generic over the signal type T and the coefficient type C: Q formats in flight, double on the
// host as the accuracy reference, float on the target as the speed comparison.
//
// ButterworthStage is the state alone, stepped with coefficients given by the caller (the sensor
// filters share one set); ButterworthLowpass is a stage with a pointer to its own. In flight the
// coefficients live in the compile-time design table (read-only memory), and changing the
// cut-off is repointing, not copying. The state stays in the signal's own units, so a new cut-off
// takes over smoothly from the old one's state.
#pragma once

#include <fixedpoint/iir.hpp>
#include <fixedpoint/q.hpp>
#include <qr/core/chain/butterworth_design.hpp>

namespace qr::chain {

// The direct-form-I sums of each order, so the filter below is written once for both. All
// products go into one wide accumulator (fx::mul_wide): no internal node can overflow, and the
// only rounding is the one narrow() per step.
template <int Order>
struct IirOfOrder;

template <>
struct IirOfOrder<1> {
  template <class T>
  using State = fx::Iir1State<T>;
  template <class C>
  using Coefficients = fx::Iir1Coefficients<C>;
  // b0 x + b1 x1 - a1 y1
  template <class T, class C>
  static constexpr auto sum(const State<T>& s, const Coefficients<C>& c, T x) {
    return fx::mul_wide(c.b0, x) + fx::mul_wide(c.b1, s.x1) - fx::mul_wide(c.a1, s.y1);
  }
  template <class T>
  static constexpr void shift(State<T>& s, T x, T y) {
    s.x1 = x;
    s.y1 = y;
  }
  template <class T>
  static constexpr void settle(State<T>& s, T x) {
    s.x1 = s.y1 = x;
  }
};

// A Butterworth low-pass's numerator is symmetric, b2 = b0, exactly in every number type (the
// design writes one value to both, and quantising rounds that one value twice): four coefficients
// are kept, not five, which is 1000 bytes of the flight table at 1 kHz.
template <class C>
struct SymmetricIir2Coefficients {
  C b0, b1, a1, a2;
  constexpr C b2() const { return b0; }
};

template <>
struct IirOfOrder<2> {
  template <class T>
  using State = fx::Iir2State<T>;
  template <class C>
  using Coefficients = SymmetricIir2Coefficients<C>;
  // b0 x + b1 x1 + b2 x2 - a1 y1 - a2 y2
  template <class T, class C>
  static constexpr auto sum(const State<T>& s, const Coefficients<C>& c, T x) {
    return fx::mul_wide(c.b0, x) + fx::mul_wide(c.b1, s.x1) + fx::mul_wide(c.b2(), s.x2) - fx::mul_wide(c.a1, s.y1) -
           fx::mul_wide(c.a2, s.y2);
  }
  // The same sum with the outer taps folded, b0 (x + x2) + b1 x1 - a1 y1 - a2 y2: one product
  // fewer. The same integers exactly when x + x2 does not wrap in T (b2 is b0 itself); only the
  // caller knows its input's range (ButterworthStage's InputBound).
  template <class T, class C>
  static constexpr auto folded_sum(const State<T>& s, const Coefficients<C>& c, T x) {
    return fx::mul_wide(c.b0, x + s.x2) + fx::mul_wide(c.b1, s.x1) - fx::mul_wide(c.a1, s.y1) -
           fx::mul_wide(c.a2, s.y2);
  }
  template <class T>
  static constexpr void shift(State<T>& s, T x, T y) {
    s.x2 = s.x1;
    s.x1 = x;
    s.y2 = s.y1;
    s.y1 = y;
  }
  template <class T>
  static constexpr void settle(State<T>& s, T x) {
    s.x1 = s.x2 = s.y1 = s.y2 = x;
  }
};

template <class C>
constexpr C coefficient_from_raw(int64_t raw, int frac_bits) {
  if constexpr (fx::is_q<C>) {
    return C::from_raw(static_cast<typename C::raw_type>(raw));
  } else {
    return static_cast<C>(static_cast<double>(raw) * design::pow2(-frac_bits));
  }
}

// A design in coefficient type C. A Q format gets the quantised integers of its own fractional
// bits (butterworth_design.hpp: DC gain exactly 1); a floating type gets the design itself, which
// is what makes the double filter the accuracy reference.
template <class C, int Order>
constexpr typename IirOfOrder<Order>::template Coefficients<C> coefficients_of(const ButterworthDesign& d) {
  if constexpr (fx::is_q<C>) {
    const QuantisedDesign q = quantise(d, C::frac_bits);
    if constexpr (Order == 1) {
      return {coefficient_from_raw<C>(q.b[0], q.frac_bits), coefficient_from_raw<C>(q.b[1], q.frac_bits),
              coefficient_from_raw<C>(q.a[1], q.frac_bits)};
    } else {
      return {coefficient_from_raw<C>(q.b[0], q.frac_bits), coefficient_from_raw<C>(q.b[1], q.frac_bits),
              coefficient_from_raw<C>(q.a[1], q.frac_bits), coefficient_from_raw<C>(q.a[2], q.frac_bits)};
    }
  } else {
    if constexpr (Order == 1) {
      return {static_cast<C>(d.b[0]), static_cast<C>(d.b[1]), static_cast<C>(d.a[1])};
    } else {
      return {static_cast<C>(d.b[0]), static_cast<C>(d.b[1]), static_cast<C>(d.a[1]), static_cast<C>(d.a[2])};
    }
  }
}

// Direct form I with first-order error feedback: what narrow() rounds away in one step is added
// back into the next step's sum. Plain direct form I feeds its rounding error e through 1/A(z),
// whose gain near DC is huge when the poles sit near z = 1 (low cut-offs): that is the dead band
// of fixed-point low-passes, where a steady input leaves the output stuck some way off. With the
// error fed back, the output error is (1 - z^-1)/A(z) e instead: no gain at DC, so no dead band,
// and the measured worst error against the double filter with the same coefficients drops 450x
// at 1 Hz and 13x at the default 20 Hz (order 2, 1 kHz; docs/signal-chain.md). Near fs/4, where
// there is no dead band, (1 - z^-1) doubles the error instead, to about one lsb. In fixed point
// the residual is less than half an lsb of the output, in the sum's units: for 30-bit coefficients
// it is within +-2^29, so it is kept in 32 bits, biased by half an output lsb so that it is never
// negative: adding it is an unsigned add, the rounding of the sum becomes a plain floor, and the
// next residual is the low bits the floor drops (one mask), not two 64-bit operations. In
// floating point the residual is always 0 and this is the plain direct form I.
//
// A stage is the state alone: the coefficients come with each step, so filters that share a
// cut-off (the six sensor axes) load them once per tick, not once per filter. InputBound, when
// given, is the largest magnitude of an input's raw value (Q formats only): when twice it fits the
// raw type, x + x2 cannot wrap and the order-2 sum folds its outer taps (IirOfOrder<2>::folded_sum),
// the same integers with one product fewer. Floating point never folds: b0 (x + x2) rounds
// differently from b0 x + b0 x2, and the double filter is the reference.
inline constexpr int64_t kUnboundedInput = -1;

template <class T, class C, int Order, int64_t InputBound = kUnboundedInput>
class ButterworthStage {
  static_assert(Order == 1 || Order == 2, "Butterworth low-pass of order 1 or 2");
  using Iir = IirOfOrder<Order>;

 public:
  using Coefficients = typename Iir::template Coefficients<C>;

  constexpr T step(const Coefficients& c, T x) {
    if constexpr (kNarrowResidual) {
      // The residual r is kept biased by half an output lsb, r + 2^(shift-1), in [0, 2^shift):
      // with the bias in the sum, rounding sum + r half up is the floor of the biased sum, and
      // what that floor drops, its low shift bits, is the next biased residual. The same y and
      // r as narrow() and sum - y 2^shift, with an unsigned add and no rounding bit.
      const Sum biased = input_sum(c, x) + Sum::from_raw(static_cast<int64_t>(residual_));
      const T y = T::from_raw(fx::detail::wrap<typename T::raw_type>(biased.raw() >> kResidualShift));
      residual_ = static_cast<uint32_t>(biased.raw()) & kResidualMask;
      Iir::shift(state_, x, y);
      return y;
    } else {
      const Sum sum = input_sum(c, x) + residual_;
      const T y = fx::narrow<T>(sum);
      residual_ = sum - fx::mul_wide(kOne, y);  // exactly what the rounding dropped
      Iir::shift(state_, x, y);
      return y;
    }
  }
  // As if x had been the input forever: starts the filter without a transient from zero.
  constexpr void settle(T x) {
    Iir::settle(state_, x);
    residual_ = kNoResidual;
  }
  // The last output is the state's y1: kept once, not twice.
  constexpr T output() const { return state_.y1; }

 private:
  template <class U>
  static constexpr bool folds() {
    if constexpr (fx::is_q<U>) {
      return Order == 2 && InputBound >= 0 && 2 * InputBound <= fx::detail::RawTraits<typename U::raw_type>::max;
    } else {
      return false;
    }
  }

 public:
  static constexpr bool kFoldOuterTaps = folds<T>();

 private:
  using Sum = decltype(fx::mul_wide(C{}, T{}));
  static constexpr C kOne = C(1.0);

  constexpr Sum input_sum(const Coefficients& c, T x) const {
    if constexpr (kFoldOuterTaps) {
      return Iir::folded_sum(state_, c, x);
    } else {
      return Iir::sum(state_, c, x);
    }
  }

  // The rounding residual: an int32 raw in the sum's units for Q formats whose output lsb is at
  // most 2^31 of the sum's (the residual is within half of it), else the sum type itself.
  template <class U, class Cf>
  static constexpr int residual_shift() {
    if constexpr (fx::is_q<U>) {
      return decltype(fx::mul_wide(Cf{}, U{}))::frac_bits - U::frac_bits;
    } else {
      return 64;
    }
  }
  static constexpr int kResidualShift = residual_shift<T, C>();
  static constexpr bool kNarrowResidual = kResidualShift >= 1 && kResidualShift <= 31;
  template <bool Narrow, class Wide>
  struct ResidualOf {
    using type = Wide;
  };
  template <class Wide>
  struct ResidualOf<true, Wide> {
    using type = uint32_t;  // biased: r + 2^(shift-1)
  };
  using Residual = typename ResidualOf<kNarrowResidual, Sum>::type;
  static constexpr uint32_t kResidualMask = kNarrowResidual ? (uint32_t{1} << kResidualShift) - 1 : 0;
  static constexpr Residual no_residual() {
    if constexpr (kNarrowResidual) {
      return uint32_t{1} << (kResidualShift - 1);
    } else {
      return Residual{};
    }
  }
  static constexpr Residual kNoResidual = no_residual();

  typename Iir::template State<T> state_{};
  Residual residual_ = kNoResidual;
};

// One filter with coefficients of its own: a stage and where its coefficients are.
template <class T, class C, int Order>
class ButterworthLowpass {
 public:
  using Coefficients = typename ButterworthStage<T, C, Order>::Coefficients;

  constexpr explicit ButterworthLowpass(const Coefficients& c) : c_(&c) {}

  // The coefficients must outlive the filter (the design table does).
  constexpr void use(const Coefficients& c) { c_ = &c; }
  constexpr const Coefficients& coefficients() const { return *c_; }

  constexpr T step(T x) { return stage_.step(*c_, x); }
  constexpr void settle(T x) { stage_.settle(x); }
  constexpr T output() const { return stage_.output(); }

 private:
  const Coefficients* c_;
  ButterworthStage<T, C, Order> stage_;
};

}  // namespace qr::chain
