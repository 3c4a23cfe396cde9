// The autotune's identification sequence (qr/core/chain/identification.hpp): a maximal-length
// PRBS, each axis in turn after a quiet half second, two levels of the axis' amplitude, over after
// its 9.1 s; and the flight chain adds it to the one axis in turn only in the autotune's row.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/flight_chain.hpp>
#include <qr/core/chain/identification.hpp>

namespace qr::chain {
namespace {

using N = FixedNumbers;
using Thrust = N::Thrust;
using Sequence = IdentificationSequence<Thrust, 1000>;

TEST(Identification, EachAxisInTurnAQuietHalfSecondThenAWholePrbsPeriod) {
  Sequence sequence{Thrust(40.0), Thrust(150.0)};
  EXPECT_TRUE(sequence.done()) << "not started";
  EXPECT_EQ(sequence.step(), Thrust{});
  sequence.start();
  const Thrust amplitude[3] = {Thrust(40.0), Thrust(40.0), Thrust(150.0)};
  for (uint8_t axis = 0; axis < 3; ++axis) {
    std::vector<int> bits;
    for (uint32_t t = 0; t < Sequence::kAxisTicks; ++t) {
      ASSERT_EQ(sequence.axis(), axis) << t;
      const Thrust e = sequence.step();
      if (t < Sequence::kQuietTicks) {
        ASSERT_EQ(e, Thrust{}) << "quiet, axis " << int(axis) << " tick " << t;
        continue;
      }
      ASSERT_TRUE(e == amplitude[axis] || e == -amplitude[axis]) << "two levels";
      const uint32_t into = t - Sequence::kQuietTicks;
      if (into % Sequence::kBitTicks == 0) {
        bits.push_back(e == amplitude[axis] ? 1 : 0);
      } else {
        ASSERT_EQ(e == amplitude[axis] ? 1 : 0, bits.back()) << "a bit holds " << Sequence::kBitTicks << " ticks";
      }
    }
    ASSERT_EQ(bits.size(), Sequence::kBits);
    // A maximal-length sequence of a 7-bit register: 64 ones and 63 zeros, and every 7-bit window
    // but all-zero once over the period (read cyclically).
    int ones = 0;
    for (int b : bits) ones += b;
    EXPECT_EQ(ones, 64) << "axis " << int(axis);
    std::set<int> windows;
    for (size_t i = 0; i < bits.size(); ++i) {
      int w = 0;
      for (size_t k = 0; k < 7; ++k) w = w * 2 + bits[(i + k) % bits.size()];
      windows.insert(w);
    }
    EXPECT_EQ(windows.size(), 127u) << "axis " << int(axis);
    EXPECT_EQ(windows.count(0), 0u);
  }
  EXPECT_TRUE(sequence.done());
  EXPECT_EQ(sequence.axis(), Sequence::kAxes);
  EXPECT_EQ(sequence.step(), Thrust{}) << "over";
  EXPECT_EQ(Sequence::kTicks, 9120u) << "9.12 s at 1 kHz";
}

// The chain mixes the sequence into the one axis in turn, only when its sources say so.
TEST(Identification, TheChainExcitesOnlyInTheAutotunesRowAndOneAxisAtATime) {
  FixedChain chain;
  chain.set_parameters(wire::ParameterValues{});
  ControlInput sticks;
  sticks.lift = 500;
  chain.set_pilot(sticks);
  const EngineSources full{Tilt::angle, Yaw::rate, Lift::stick};
  const EngineSources autotune{Tilt::angle, Yaw::rate, Lift::stick, Excite::prbs};
  chain.enter_identification();
  EXPECT_FALSE(chain.identification_over());
  chain.mix(full);
  const Moments<Thrust> quiet = chain.moments();
  for (int i = 0; i < 3000; ++i) chain.mix(full);
  EXPECT_FALSE(chain.identification_over()) << "full control's row does not run the sequence";
  uint32_t moved[3] = {};
  for (uint32_t t = 0; t < Sequence::kTicks; ++t) {
    chain.mix(autotune);
    const Moments<Thrust> m = chain.moments();
    const bool differs[3] = {m.roll != quiet.roll, m.pitch != quiet.pitch, m.yaw != quiet.yaw};
    ASSERT_LE(int(differs[0]) + int(differs[1]) + int(differs[2]), 1) << "one axis at a time, tick " << t;
    for (int a = 0; a < 3; ++a) moved[a] += differs[a] ? 1u : 0u;
  }
  for (int a = 0; a < 3; ++a) EXPECT_EQ(moved[a], Sequence::kBits * Sequence::kBitTicks) << "axis " << a;
  EXPECT_TRUE(chain.identification_over());
}

}  // namespace
}  // namespace qr::chain
