// Lift and moments to engine commands through the inverse of the quadratic rotor model.
//
// Model (docs/conventions.md): thrust and reaction torque go with rotor speed squared, and the
// engine command is proportional to speed. In thrust units, engine i with command ae_i gives
// w_i = ae_i^2 / 1000 (1000 = one engine at full speed), and
//   lift   Z = w0 + w1 + w2 + w3
//   roll   L = w3 - w1                 (left up, right down rolls right)
//   pitch  M = w0 - w2                 (front up pitches nose up)
//   yaw    N = w1 + w3 - w0 - w2       (the counter-clockwise pair speeds up: yaws right)
// (the constants b l and d of the model are folded into the controllers' gains). Inverted:
//   w_i = Z/4 + m_i,  m = (M/2 - N/4, -L/2 + N/4, -M/2 - N/4, L/2 + N/4)  for engines 0..3,
//   ae_i = sqrt(1000 w_i).
//
// Saturation. While lift > 0 every engine stays within [idle, 1000], i.e. w_i in
// [idle^2/1000, 1000]. The moment parts m_i sum to zero, so:
//   1. if their spread (max - min) exceeds what the engines can span, all moments are scaled
//      down by one factor: the realised moments keep the ratios asked for;
//   2. if the largest part does not fit above the lift, the lift gives way (moved down): near
//      full throttle attitude control wins over climb;
//   3. if the smallest part does not fit below the lift, the moments are scaled down again: at
//      low lift the pilot's lift wins, so a controller never lifts the vehicle off by itself,
//      and at idle the engines just idle.
// The division each scaling needs happens only when saturating. What was realised is readable
// (applied()), so a log shows when and how much the mixer limited the controllers.
#pragma once

#include <stdint.h>

#include <common/units.hpp>
#include <fixedpoint/sqrt.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/numeric.hpp>

namespace qr::chain {

template <class Thrust>
struct Moments {
  Thrust roll{}, pitch{}, yaw{};
};

template <class N>
class EngineMixer {
 public:
  using Thrust = typename N::Thrust;

  static constexpr Thrust kFullThrust = Thrust(1000.0);

  // idle_level parameter (engine units): one division, at parameter changes only.
  void set_idle(int32_t idle) {
    if (idle < 0) idle = 0;
    if (idle > int32_t{wire::kEngineMax}) idle = wire::kEngineMax;
    idle_ = static_cast<uint16_t>(idle);
    idle_thrust_ = N::template ratio<Thrust>(int32_t{idle_} * idle_, wire::kEngineMax);
  }
  uint16_t idle() const { return idle_; }

  // Per-engine thrust for a lift stick value: lift^2 / 1000, so ae_i = lift with no moments.
  static Thrust thrust_of_lift(uint16_t lift) {
    return product<Thrust>(N::template fixed<0>(int32_t{lift} * lift), kPerMille);
  }

  [[gnu::always_inline]] inline EngineCommand mix(uint16_t lift, const Moments<Thrust>& wanted) {
    if (lift == 0) {
      applied_ = {};
      limited_ = false;
      return {};
    }
    return mix_thrust(thrust_of_lift(lift), wanted);
  }

  // The mapping itself, from a per-engine thrust (Z/4) > 0. It, mix() and FlightChain::mix() are
  // always inlined: each has two callers, and GCC's inlining limits flip with edits elsewhere in
  // the tick (a cheaper fx::narrow_sat left them called, mixer row 290 -> 328 instructions a
  // tick; inlined, 285).
  [[gnu::always_inline]] inline EngineCommand mix_thrust(Thrust per_engine, const Moments<Thrust>& wanted) {
    const Thrust low = idle_thrust_;
    Thrust base = clamp(per_engine, low, kFullThrust);

    Thrust m[4];
    moment_parts(wanted, m);
    // Each pair sorted by one compare, then the larger of the tops and the smaller of the bottoms.
    const bool front_high = m[2] < m[0], left_high = m[1] < m[3];
    Thrust peak = max_of(front_high ? m[0] : m[2], left_high ? m[3] : m[1]);
    Thrust trough = min_of(front_high ? m[2] : m[0], left_high ? m[1] : m[3]);

    const Thrust room = kFullThrust - low;
    limited_ = false;
    if (room < peak - trough) {  // 1.
      scale(m, peak, trough, room, peak - trough);
      limited_ = true;
    }
    if (kFullThrust < base + peak) base = kFullThrust - peak;  // 2.
    if (base + trough < low) {                                 // 3.
      scale(m, peak, trough, base - low, -trough);
      limited_ = true;
    }

    EngineCommand out;
    for (int i = 0; i < 4; ++i) {
      const Thrust w = clamp(base + m[i], low, kFullThrust);  // only rounding can step outside
      const int32_t ae = engine_of_thrust(w);
      out.value[i] = static_cast<uint16_t>(ae < idle_ ? idle_ : ae > wire::kEngineMax ? wire::kEngineMax : ae);
    }
    applied_.roll = m[3] - m[1];
    applied_.pitch = m[0] - m[2];
    applied_.yaw = m[1] + m[3] - m[0] - m[2];
    return out;
  }

  // The moments the last mix realised (before rounding to whole engine units).
  const Moments<Thrust>& applied() const { return applied_; }
  // The last mix had to scale the moments down (step 1 or 3): the engines could not give what
  // the controllers asked for, so an integral must not grow on the difference.
  bool limited() const { return limited_; }

  // round(sqrt(1000 w)): the engine value for a per-engine thrust w in [0, 1000]. Exact (the
  // rounding of the true root) for the Q formats, in 32-bit integer arithmetic: the value needs
  // 10 bits, so a 64-bit square root of the Q<16> thrust would compute 22 bits only to throw 12
  // away. With x = 1000 w and k = floor(2 sqrt(x)),
  // round(sqrt(x)) = (k + 1) / 2 (the root's first fractional bit decides), and
  // k = isqrt(floor(4 x)) because isqrt(floor(y)) = floor(sqrt(y)) for every real y >= 0.
  static int32_t engine_of_thrust(Thrust w) {
    if constexpr (fx::is_q<Thrust>) {
      static_assert(Thrust::frac_bits == 16, "4000 w = raw x 125 / 2^11 below assumes Q<16>");
      if (w.raw() <= 0) return 0;
      const uint32_t raw = static_cast<uint32_t>(w.raw());
      // floor(4000 w) = floor(raw x 125 / 2^11) = the high word of raw x (125 x 2^21): one mulhu
      // (a constant multiplier the compiler would otherwise unfold into shifts and adds).
      const uint32_t four_x = static_cast<uint32_t>((static_cast<uint64_t>(raw) * (125u << 21)) >> 32);
      return static_cast<int32_t>((isqrt_below_4_pow_11(four_x) + 1) >> 1);
    } else {
      return N::round_to_int(fx::mul_wide(N::sqrt(w), kRootOf1000));
    }
  }

 private:
  // m_i = roll x L + pitch x M + yaw x N, one row per engine (0 front, 1 right, 2 back, 3 left).
  struct Row {
    Thrust roll, pitch, yaw;
  };
  static constexpr Row kRows[4] = {
      {Thrust(0.0), Thrust(0.5), Thrust(-0.25)},
      {Thrust(-0.5), Thrust(0.0), Thrust(0.25)},
      {Thrust(0.0), Thrust(-0.5), Thrust(-0.25)},
      {Thrust(0.5), Thrust(0.0), Thrust(0.25)},
  };
  static constexpr typename N::Scale kPerMille = typename N::Scale(0.001);
  static constexpr Thrust kRootOf1000 = Thrust(31.62277660168379332);

  // floor(sqrt(n)) for n < 4^11 (4000 w <= 4e6: the clamp to [low, 1000] before the call keeps n
  // there). In flight n is at least 2^16 (a thrust of 16.4 units, an engine at 128), and its top
  // eight bits k = n / 2^14 seed the root from above with ceil(sqrt((k + 1) 2^14)): at most 12 %
  // high (k = 4), under 1 % from k = 64 (a thrust of 262, about hover). One Newton step and a
  // check finish it (fixedpoint/sqrt.hpp).
  static constexpr uint32_t isqrt_below_4_pow_11(uint32_t n) {
    if (n < (1u << 16)) return fx::detail::isqrt(n).root;
    return fx::detail::root_from_above<1>(n, fx::detail::kRootSeeds<uint16_t, 256, 14>.of[n >> 14]);
  }
  // m_i = roll x L + pitch x M + yaw x N of row i. The rows hold halves and quarters, so in the
  // Q formats each part is (+-2 L or +-2 M +- N) / 4, rounded half up as narrow() rounds the
  // exact sum of the products: the same value in a few 32-bit operations, where the three
  // 64-bit products cost the mixer about a quarter of its instructions. The bound keeps
  // 2 |L| + |N| inside 32 bits; every source of moments clamps far inside it (the controllers at
  // +-1000, the sticks' open loop below).
  static void moment_parts(const Moments<Thrust>& wanted, Thrust (&m)[4]) {
    if constexpr (fx::is_q<Thrust>) {
      static_assert(Thrust::frac_bits == 16, "the bound below assumes Q<16>");
      constexpr Thrust kBound = Thrust(8192.0);  // 2^29 raw: 3 x 2^29 < 2^31
      const int32_t l = clamp(wanted.roll, -kBound, kBound).raw();
      const int32_t p = clamp(wanted.pitch, -kBound, kBound).raw();
      const int32_t n = clamp(wanted.yaw, -kBound, kBound).raw();
      const auto quarter = [](int32_t x) { return Thrust::from_raw((x + 2) >> 2); };
      m[0] = quarter(2 * p - n);
      m[1] = quarter(n - 2 * l);
      m[2] = quarter(-2 * p - n);
      m[3] = quarter(2 * l + n);
    } else {
      for (int i = 0; i < 4; ++i) {
        const Row& row = kRows[i];
        m[i] = fx::narrow<Thrust>(fx::mul_wide(row.roll, wanted.roll) + fx::mul_wide(row.pitch, wanted.pitch) +
                                  fx::mul_wide(row.yaw, wanted.yaw));
      }
    }
  }

  // num / den for 0 <= num < den: the saturation's scale factor, in Q<30> (a Thrust quotient
  // would be quantised to 1.5e-5, and the realised moments with it: up to 0.008 thrust units
  // off the ratio asked for). A 64-bit division, taken only when saturating.
  using Factor = typename N::Coefficient;
  static Factor fraction(Thrust num, Thrust den) {
    if constexpr (fx::is_q<Thrust>) {
      return N::template ratio<Factor>(num.raw(), den.raw());
    } else {
      return num / den;
    }
  }

  // Every part, the peak and the trough times num / den. Out of line: it runs only when
  // saturating, and inlined its registers would cost every mix a longer prologue.
  [[gnu::noinline]] static void scale(Thrust (&m)[4], Thrust& peak, Thrust& trough, Thrust num, Thrust den) {
    const Factor factor = fraction(num, den);
    for (Thrust& v : m) v = product<Thrust>(v, factor);
    peak = product<Thrust>(peak, factor);
    trough = product<Thrust>(trough, factor);
  }

  uint16_t idle_ = 0;
  Thrust idle_thrust_{};
  Moments<Thrust> applied_{};
  bool limited_ = false;
};

}  // namespace qr::chain
