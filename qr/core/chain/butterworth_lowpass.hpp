// One low-pass filter on one signal: the state of a 1st- or 2nd-order IIR step (direct form I,
// fixedpoint/iir.hpp) and the coefficients it runs with. Generic over the signal type T and the
// coefficient type C: Q formats in flight, double on the host as the accuracy reference, float
// on the target as the speed comparison.
//
// The coefficients are held by pointer: in flight they live in the compile-time design table
// (read-only memory), and changing the cut-off is repointing, not copying. The state stays in the
// signal's own units, so a new cut-off takes over smoothly from the old one's state.
#pragma once

#include <fixedpoint/iir.hpp>
#include <fixedpoint/q.hpp>
#include <qr/core/chain/butterworth_design.hpp>

namespace qr::chain {

// The IIR step of each order, so the filter below is written once for both.
template <int Order>
struct IirOfOrder;

template <>
struct IirOfOrder<1> {
  template <class T>
  using State = fx::Iir1State<T>;
  template <class C>
  using Coefficients = fx::Iir1Coefficients<C>;
  template <class T, class C>
  static constexpr T step(State<T>& s, const Coefficients<C>& c, T x) {
    return fx::iir1_step(s, c, x);
  }
  template <class T>
  static constexpr void settle(State<T>& s, T x) {
    s.x1 = s.y1 = x;
  }
};

template <>
struct IirOfOrder<2> {
  template <class T>
  using State = fx::Iir2State<T>;
  template <class C>
  using Coefficients = fx::Iir2Coefficients<C>;
  template <class T, class C>
  static constexpr T step(State<T>& s, const Coefficients<C>& c, T x) {
    return fx::iir2_step(s, c, x);
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
              coefficient_from_raw<C>(q.b[2], q.frac_bits), coefficient_from_raw<C>(q.a[1], q.frac_bits),
              coefficient_from_raw<C>(q.a[2], q.frac_bits)};
    }
  } else {
    if constexpr (Order == 1) {
      return {static_cast<C>(d.b[0]), static_cast<C>(d.b[1]), static_cast<C>(d.a[1])};
    } else {
      return {static_cast<C>(d.b[0]), static_cast<C>(d.b[1]), static_cast<C>(d.b[2]), static_cast<C>(d.a[1]),
              static_cast<C>(d.a[2])};
    }
  }
}

template <class T, class C, int Order>
class ButterworthLowpass {
  static_assert(Order == 1 || Order == 2, "Butterworth low-pass of order 1 or 2");
  using Iir = IirOfOrder<Order>;

 public:
  using Coefficients = typename Iir::template Coefficients<C>;

  constexpr explicit ButterworthLowpass(const Coefficients& c) : c_(&c) {}

  // The coefficients must outlive the filter (the design table does).
  constexpr void use(const Coefficients& c) { c_ = &c; }
  constexpr const Coefficients& coefficients() const { return *c_; }

  constexpr T step(T x) { return y_ = Iir::step(state_, *c_, x); }
  // As if x had been the input forever: starts the filter without a transient from zero.
  constexpr void settle(T x) {
    Iir::settle(state_, x);
    y_ = x;
  }
  constexpr T output() const { return y_; }

 private:
  const Coefficients* c_;
  typename Iir::template State<T> state_{};
  T y_{};
};

}  // namespace qr::chain
