#include "samples.hpp"

namespace bench {
namespace {

// Numerical Recipes' 32-bit LCG: plenty for spreading operands over a range.
struct Lcg {
  uint32_t state;
  uint32_t next() { return state = state * 1664525u + 1013904223u; }
  int32_t in(int32_t lo, int32_t hi) {
    const uint32_t span = static_cast<uint32_t>(hi - lo);
    return lo + static_cast<int32_t>(next() % span);
  }
};

}  // namespace

void make_samples(Op op, Samples& out) {
  const Operands& r = kOps[static_cast<int>(op)].operands;
  Lcg rng{0x5EED0000u + static_cast<uint32_t>(op)};
  for (uint32_t i = 0; i < kSamples; ++i) {
    out.a[i] = rng.in(r.a_lo, r.a_hi);
    const int32_t b = rng.in(r.b_lo, r.b_hi);
    out.b[i] = (r.either_sign && (rng.next() & 0x100u) != 0) ? -b : b;
  }
}

}  // namespace bench
