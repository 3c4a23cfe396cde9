// The Q side of the bench. Every operation sits in its own function that no caller can see
// into (noipa), so nothing is folded into the loop and each call does the whole work.
#include <fixedpoint/atan2.hpp>
#include <fixedpoint/iir.hpp>
#include <fixedpoint/q.hpp>
#include <fixedpoint/sincos.hpp>
#include <fixedpoint/sqrt.hpp>

#include "filters.hpp"
#include "ops.hpp"
#include "samples.hpp"

namespace bench {
namespace {

using Signal = fx::Q<16>;       // ±32768 with 1.5e-5 resolution
using Coefficient = fx::Q<30>;  // ±2 with 9.3e-10 resolution: enough for poles near z = 1
using Angle = fx::Q<29>;        // ±4 rad
using Unit = fx::Q<30>;         // sin and cos

// A filter as the flight code keeps it: coefficients and state side by side in RAM, so the
// step reaches all of them from one base register.
struct Lowpass1 {
  fx::Iir1State<Signal> state;
  fx::Iir1Coefficients<Coefficient> coefficients;
};
struct Lowpass2 {
  fx::Iir2State<Signal> state;
  fx::Iir2Coefficients<Coefficient> coefficients;
};
constinit Lowpass1 g_lowpass1{{}, {Coefficient(kLowpass1[0]), Coefficient(kLowpass1[1]), Coefficient(kLowpass1[2])}};
constinit Lowpass2 g_lowpass2{{},
                              {Coefficient(kLowpass2[0]), Coefficient(kLowpass2[1]), Coefficient(kLowpass2[2]),
                               Coefficient(kLowpass2[3]), Coefficient(kLowpass2[4])}};

// The other way a filter can be written: a design fixed at compile time, coefficients as
// immediates in the code, only the state in RAM.
constexpr fx::Iir2Coefficients<Coefficient> kLowpass2Const{Coefficient(kLowpass2[0]), Coefficient(kLowpass2[1]),
                                                           Coefficient(kLowpass2[2]), Coefficient(kLowpass2[3]),
                                                           Coefficient(kLowpass2[4])};
constinit fx::Iir2State<Signal> g_lowpass2_const_state{};

[[gnu::noipa]] Signal add(Signal a, Signal b) { return a + b; }
[[gnu::noipa]] Signal mul(Signal a, Signal b) { return a * b; }
[[gnu::noipa]] Signal div(Signal a, Signal b) { return a / b; }
[[gnu::noipa]] Signal sqrt(Signal a, Signal) { return fx::sqrt(a); }
[[gnu::noipa]] Angle atan2(Signal y, Signal x) { return fx::atan2<Angle>(y, x); }
[[gnu::noipa]] Unit sin(Signal a, Signal) { return fx::sin<Unit>(a); }
[[gnu::noipa]] Signal iir1(Signal x, Lowpass1& f) { return fx::iir1_step(f.state, f.coefficients, x); }
[[gnu::noipa]] Signal iir2(Signal x, Lowpass2& f) { return fx::iir2_step(f.state, f.coefficients, x); }
[[gnu::noipa]] Signal iir2_const(Signal x, fx::Iir2State<Signal>& s) { return fx::iir2_step(s, kLowpass2Const, x); }

// Baselines: the same signatures doing nothing (the result is already in a0).
template <typename Out>
[[gnu::noipa]] Out nothing(Signal a, Signal) {
  return Out::from_raw(a.raw());
}
template <typename State>
[[gnu::noipa]] Signal nothing_step(Signal x, State&) {
  return x;
}

Samples g_samples;
Signal g_a[kSamples], g_b[kSamples];
Signal g_out[kSamples];
Angle g_out_angle[kSamples];
Unit g_out_unit[kSamples];

template <auto Fn, typename Out>
uint32_t net_calls(Out* out) {
  return count_calls<Fn>(out, g_a, g_b) - count_calls<nothing<Out>>(out, g_a, g_b);
}
template <auto Fn, typename State>
uint32_t net_steps(State& state) {
  return count_steps<Fn>(g_out, g_a, state) - count_steps<nothing_step<State>>(g_out, g_a, state);
}

}  // namespace

uint32_t fixed_instructions(Op op) {
  make_samples(op, g_samples);
  for (uint32_t i = 0; i < kSamples; ++i) {
    g_a[i] = Signal::from_raw(g_samples.a[i]);
    g_b[i] = Signal::from_raw(g_samples.b[i]);
  }
  switch (op) {
    case Op::add: return net_calls<add>(g_out);
    case Op::mul: return net_calls<mul>(g_out);
    case Op::div: return net_calls<div>(g_out);
    case Op::sqrt: return net_calls<sqrt>(g_out);
    case Op::atan2: return net_calls<atan2>(g_out_angle);
    case Op::sin: return net_calls<sin>(g_out_unit);
    case Op::iir1: return net_steps<iir1>(g_lowpass1);
    case Op::iir2: return net_steps<iir2>(g_lowpass2);
    case Op::iir2_const: return net_steps<iir2_const>(g_lowpass2_const_state);
  }
  return 0;
}

}  // namespace bench
