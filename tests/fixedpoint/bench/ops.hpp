// The operations the bench measures, their operands, and the two sides that measure them: the
// Q path (fixed_ops.cpp) and the same operation in float (float_ops.cpp, soft-float).
#pragma once

#include <stdint.h>

namespace bench {

enum class Op : uint8_t { add, mul, div, sqrt, atan2, sin, iir1, iir2, iir2_const };
inline constexpr int kOpCount = 9;

// Operands are drawn uniformly from [lo, hi) (in units of 1/65536, i.e. Q<16> raw); a `b` with
// `either_sign` gets a random sign on top, so divisors stay away from zero.
struct Operands {
  int32_t a_lo, a_hi, b_lo, b_hi;
  bool either_sign;
};

struct OpInfo {
  const char* name;
  Operands operands;
};

inline constexpr int32_t kOne = 65536;

// Indexed by Op. Ranges are what the flight code sees: a few hundred at most, angles of a few
// turns, divisors of either sign, filter input as noise around zero.
inline constexpr OpInfo kOps[kOpCount] = {
    {"add", {-100 * kOne, 100 * kOne, -100 * kOne, 100 * kOne, false}},
    {"mul", {-100 * kOne, 100 * kOne, -100 * kOne, 100 * kOne, false}},
    {"div", {-100 * kOne, 100 * kOne, kOne / 2, 100 * kOne, true}},
    {"sqrt", {0, 1000 * kOne, 0, 1, false}},
    {"atan2", {-100 * kOne, 100 * kOne, -100 * kOne, 100 * kOne, false}},
    {"sin", {-20 * kOne, 20 * kOne, 0, 1, false}},
    {"iir1", {-10 * kOne, 10 * kOne, 0, 1, false}},
    {"iir2", {-10 * kOne, 10 * kOne, 0, 1, false}},
    {"iir2_const", {-10 * kOne, 10 * kOne, 0, 1, false}},
};

// Instructions retired by kSamples calls of the operation, minus those of the same loop calling
// an empty function of the same signature: the operation's own cost, call and loop excluded.
uint32_t fixed_instructions(Op op);
uint32_t float_instructions(Op op);

}  // namespace bench
