// Devboard half of the host/target bit-identity check; see cross_check.hpp. Exits 0 only when
// the RV32 build reaches the checksum the host test asserts.
#include <qr/boards/rv32virt/devboard.hpp>

#include "cross_check.hpp"

int main() {
  const uint32_t sum = fxcheck::checksum();
  rv32virt::puts("fixedpoint cross-check: checksum ");
  rv32virt::put_u32(sum);
  rv32virt::puts(sum == fxcheck::kExpected ? " matches the host\n" : " differs from the host's\n");
  return sum == fxcheck::kExpected ? 0 : 1;
}
