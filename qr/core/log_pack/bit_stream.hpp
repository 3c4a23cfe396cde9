// Bits written to and read from a byte area, least significant bit first, a byte's worth at a time.
// Both ends are bounded by the area: a writer that runs out says so and writes nothing of that
// value; a reader past the end reads zeros and ok() turns false, so a damaged or foreign area never
// reads out of bounds.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace qr::log_pack {

class BitWriter {
 public:
  BitWriter(uint8_t* area, size_t bytes, size_t bit = 0) : area_(area), bits_(bytes * 8u), bit_(bit) {}

  // The low `count` bits of `value` (count at most 32); false, and nothing written, when they do
  // not fit.
  bool put(uint32_t value, uint8_t count) {
    if (bit_ > bits_ || count > bits_ - bit_) return false;
    while (count > 0) {
      const uint8_t offset = static_cast<uint8_t>(bit_ & 7u);
      const uint8_t take = static_cast<uint8_t>(count < 8u - offset ? count : 8u - offset);
      const uint8_t mask = static_cast<uint8_t>(((1u << take) - 1u) << offset);
      uint8_t& byte = area_[bit_ >> 3];
      byte = static_cast<uint8_t>((byte & ~mask) | ((value << offset) & mask));
      value = take < 32u ? value >> take : 0u;
      count = static_cast<uint8_t>(count - take);
      bit_ += take;
    }
    return true;
  }

  size_t bit() const { return bit_; }
  size_t capacity_bits() const { return bits_; }

 private:
  uint8_t* area_;
  size_t bits_;
  size_t bit_;
};

class BitReader {
 public:
  BitReader(const uint8_t* area, size_t bytes, size_t bit = 0) : area_(area), bits_(bytes * 8u), bit_(bit) {}

  uint32_t get(uint8_t count) {
    if (bit_ > bits_ || count > bits_ - bit_) {
      ok_ = false;
      bit_ = bits_;
      return 0;
    }
    uint32_t value = 0;
    uint8_t got = 0;
    while (got < count) {
      const uint8_t offset = static_cast<uint8_t>(bit_ & 7u);
      const uint8_t left = static_cast<uint8_t>(count - got);
      const uint8_t take = static_cast<uint8_t>(left < 8u - offset ? left : 8u - offset);
      const uint32_t bits = (static_cast<uint32_t>(area_[bit_ >> 3]) >> offset) & ((1u << take) - 1u);
      value |= bits << got;
      got = static_cast<uint8_t>(got + take);
      bit_ += take;
    }
    return value;
  }

  bool ok() const { return ok_; }
  size_t bit() const { return bit_; }

 private:
  const uint8_t* area_;
  size_t bits_;
  size_t bit_;
  bool ok_ = true;
};

}  // namespace qr::log_pack
