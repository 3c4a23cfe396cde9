// Operands for the measured loops, the same for both number types, and the loop that counts.
#pragma once

#include <stdint.h>
#include <qr/boards/rv32virt/devboard.hpp>

#include "ops.hpp"

namespace bench {

inline constexpr uint32_t kSamples = 256;

struct Samples {
  int32_t a[kSamples];
  int32_t b[kSamples];
};

// Deterministic: every run and both number types see the same operands.
void make_samples(Op op, Samples& out);

// Retired instructions of `kSamples` calls fn(a[i], b[i]). Not inlined, so the loop around the
// operation and the one around its baseline compile to the same code.
template <auto Fn, typename Out, typename A, typename B>
[[gnu::noinline]] uint32_t count_calls(Out* out, const A* a, const B* b) {
  const uint32_t start = rv32virt::instret();
  for (uint32_t i = 0; i < kSamples; ++i) out[i] = Fn(a[i], b[i]);
  return rv32virt::instret() - start;
}

// Filter steps: fn(x[i], state), the state in memory as a tick would have it.
template <auto Fn, typename Out, typename A, typename State>
[[gnu::noinline]] uint32_t count_steps(Out* out, const A* x, State& state) {
  const uint32_t start = rv32virt::instret();
  for (uint32_t i = 0; i < kSamples; ++i) out[i] = Fn(x[i], state);
  return rv32virt::instret() - start;
}

}  // namespace bench
