// An illegal instruction must end the run with a failure status, never hang or pass.
#include <qr/boards/rv32virt/devboard.hpp>

int main() {
  asm volatile(".word 0");  // all-zero word: always an illegal instruction on RISC-V
  return 0;
}
