// The host half of the host/devboard bit-identity check (chain_checksum.hpp): the synthetic
// flight through FixedChain must fold to the checksum the devboard program also asserts.
#include <gtest/gtest.h>

#include <qr/core/chain/flight_chain.hpp>

#include "chain_checksum.hpp"

namespace qr::chain {
namespace {

TEST(ChainChecksum, SyntheticFlightFoldsToTheRecordedChecksum) {
  FixedChain chain;
  const uint32_t sum = checksum::fly(chain);
  std::printf("  synthetic flight checksum %u\n", sum);
  EXPECT_EQ(sum, checksum::kExpected);
}

TEST(ChainChecksum, SameInputSameChecksum) {
  FixedChain a, b;
  EXPECT_EQ(checksum::fly(a), checksum::fly(b));
  FlightChain<FixedNumbers, 500> c, d;
  EXPECT_EQ(checksum::fly(c), checksum::fly(d));
}

}  // namespace
}  // namespace qr::chain
