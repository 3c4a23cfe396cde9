// Host half of the host/target bit-identity check; see cross_check.hpp.
#include <gtest/gtest.h>

#include "cross_check.hpp"

TEST(CrossCheck, HostArrivesAtTheChecksumTheDevboardMustMatch) {
  EXPECT_EQ(fxcheck::checksum(), fxcheck::kExpected) << std::hex << "0x" << fxcheck::checksum();
}
