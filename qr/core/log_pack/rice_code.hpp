// Adaptive Rice codes of prediction residuals (the log's packing, docs/protocol.md section 8): a
// residual r is folded to z = 2|r| (- 1 when negative), split at k bits into a unary quotient and k
// plain bits, k following the running mean of z, so small residuals cost few bits and a burst of
// large ones raises k within a few values. A quotient of kEscape or more is written as kEscape ones
// and z's 32 bits: any residual has a code of at most 56 bits, whatever the mean says.
#pragma once

#include <stdint.h>

#include <qr/core/log_pack/bit_stream.hpp>

namespace qr::log_pack {

inline constexpr uint32_t kEscape = 24;

// Out of line: a line codes some 15 values, and the QR keeps one copy of each (flash is short).
class RiceCode {
 public:
  [[gnu::noinline]] bool put(BitWriter& out, int32_t residual) {
    const uint32_t z = fold(residual);
    const uint8_t k = parameter();
    const uint32_t quotient = z >> k;
    bool ok;
    if (quotient < kEscape) {
      // the quotient's ones and their zero in one write (at most 25 bits), then k plain bits
      ok = out.put((1u << quotient) - 1u, static_cast<uint8_t>(quotient + 1u)) && out.put(z & ((1u << k) - 1u), k);
    } else {
      ok = out.put((1u << kEscape) - 1u, static_cast<uint8_t>(kEscape)) && out.put(z, 32);
    }
    learn(z);
    return ok;
  }

  [[gnu::cold, gnu::noinline]] int32_t get(BitReader& in) {
    const uint8_t k = parameter();
    uint32_t quotient = 0;
    while (quotient < kEscape && in.get(1) == 1u) ++quotient;
    const uint32_t z = quotient < kEscape ? (quotient << k) | in.get(k) : in.get(32);
    learn(z);
    return unfold(z);
  }

 private:
  static constexpr uint32_t fold(int32_t r) {
    const uint32_t u = static_cast<uint32_t>(r);
    return (u << 1) ^ (r < 0 ? 0xFFFFFFFFu : 0u);
  }
  static constexpr int32_t unfold(uint32_t z) {
    const uint32_t u = (z >> 1) ^ (0u - (z & 1u));
    return static_cast<int32_t>(u);
  }
  // k: the bits of the mean of z (the mean kept times 16); a mean of m gives k with 2^k <= m + 1.
  uint8_t parameter() const {
    const uint32_t m = (mean16_ >> 4) + 1u;
    const auto k = static_cast<uint8_t>(31 - __builtin_clz(m));
    return k > 24u ? 24u : k;
  }
  // A mean over about 16 values; z is capped so that an escaped one cannot overflow it.
  void learn(uint32_t z) {
    const uint32_t capped = z > (1u << 24) ? (1u << 24) : z;
    mean16_ = mean16_ + capped - (mean16_ >> 4);
  }

  uint32_t mean16_ = 16u << 4;
};

}  // namespace qr::log_pack
