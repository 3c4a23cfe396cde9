// The bench's Q paths without the float ones. Built to be inspected with nm (see
// check_soft_float.cmake): whatever soft-float helper this ELF holds, Q code pulled it in.
#include "ops.hpp"
#include "report.hpp"

int main() {
  for (int i = 0; i < bench::kOpCount; ++i) {
    const auto op = static_cast<bench::Op>(i);
    bench::put_op_line(op, bench::fixed_instructions(op), nullptr);
  }
  return 0;
}
