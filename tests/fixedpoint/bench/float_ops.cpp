// The float side of the bench: the same operations and filters as fixed_ops.cpp, in float,
// which on RV32IM means libgcc's soft-float helpers.
#include <fixedpoint/bench/float_math.hpp>
#include <fixedpoint/iir.hpp>

#include "filters.hpp"
#include "ops.hpp"
#include "samples.hpp"

namespace bench {
namespace {

struct Lowpass1 {
  fx::Iir1State<float> state;
  fx::Iir1Coefficients<float> coefficients;
};
struct Lowpass2 {
  fx::Iir2State<float> state;
  fx::Iir2Coefficients<float> coefficients;
};
constexpr float f(double v) { return static_cast<float>(v); }
constinit Lowpass1 g_lowpass1{{}, {f(kLowpass1[0]), f(kLowpass1[1]), f(kLowpass1[2])}};
constinit Lowpass2 g_lowpass2{{},
                              {f(kLowpass2[0]), f(kLowpass2[1]), f(kLowpass2[2]), f(kLowpass2[3]), f(kLowpass2[4])}};
constexpr fx::Iir2Coefficients<float> kLowpass2Const{f(kLowpass2[0]), f(kLowpass2[1]), f(kLowpass2[2]), f(kLowpass2[3]),
                                                     f(kLowpass2[4])};
constinit fx::Iir2State<float> g_lowpass2_const_state{};

[[gnu::noipa]] float add(float a, float b) { return a + b; }
[[gnu::noipa]] float mul(float a, float b) { return a * b; }
[[gnu::noipa]] float div(float a, float b) { return a / b; }
[[gnu::noipa]] float sqrt(float a, float) { return flt::sqrt(a); }
[[gnu::noipa]] float atan2(float y, float x) { return flt::atan2(y, x); }
[[gnu::noipa]] float sin(float a, float) { return flt::sin(a); }
[[gnu::noipa]] float iir1(float x, Lowpass1& s) { return fx::iir1_step(s.state, s.coefficients, x); }
[[gnu::noipa]] float iir2(float x, Lowpass2& s) { return fx::iir2_step(s.state, s.coefficients, x); }
[[gnu::noipa]] float iir2_const(float x, fx::Iir2State<float>& s) { return fx::iir2_step(s, kLowpass2Const, x); }

[[gnu::noipa]] float nothing(float a, float) { return a; }
template <typename State>
[[gnu::noipa]] float nothing_step(float x, State&) {
  return x;
}

Samples g_samples;
float g_a[kSamples], g_b[kSamples];
float g_out[kSamples];

template <auto Fn>
uint32_t net_calls() {
  return count_calls<Fn>(g_out, g_a, g_b) - count_calls<nothing>(g_out, g_a, g_b);
}
template <auto Fn, typename State>
uint32_t net_steps(State& state) {
  return count_steps<Fn>(g_out, g_a, state) - count_steps<nothing_step<State>>(g_out, g_a, state);
}

}  // namespace

uint32_t float_instructions(Op op) {
  make_samples(op, g_samples);
  for (uint32_t i = 0; i < kSamples; ++i) {
    g_a[i] = static_cast<float>(g_samples.a[i]) / static_cast<float>(kOne);
    g_b[i] = static_cast<float>(g_samples.b[i]) / static_cast<float>(kOne);
  }
  switch (op) {
    case Op::add: return net_calls<add>();
    case Op::mul: return net_calls<mul>();
    case Op::div: return net_calls<div>();
    case Op::sqrt: return net_calls<sqrt>();
    case Op::atan2: return net_calls<atan2>();
    case Op::sin: return net_calls<sin>();
    case Op::iir1: return net_steps<iir1>(g_lowpass1);
    case Op::iir2: return net_steps<iir2>(g_lowpass2);
    case Op::iir2_const: return net_steps<iir2_const>(g_lowpass2_const_state);
  }
  return 0;
}

}  // namespace bench
