// Instructions per operation, Q format against float, on the RV32IM devboard (QEMU -icount, so
// minstret is exact). One JSON object a line per operation, then a summary line. The targets
// are reported, met or not; the run fails only if something crashes.
#include <qr/boards/rv32virt/devboard.hpp>

#include "ops.hpp"
#include "report.hpp"
#include "samples.hpp"

namespace {

constexpr uint32_t kIir2TargetInstructions = 40;
constexpr uint32_t kFloatTargetFactor = 10;

void put_bool_field(const char* key, bool value) {
  rv32virt::puts(",\"");
  rv32virt::puts(key);
  rv32virt::puts("\":");
  rv32virt::puts(value ? "true" : "false");
}

}  // namespace

int main() {
  using bench::Op;
  uint32_t fixed[bench::kOpCount];
  uint32_t flt[bench::kOpCount];
  for (int i = 0; i < bench::kOpCount; ++i) {
    const Op op = static_cast<Op>(i);
    fixed[i] = bench::fixed_instructions(op);
    flt[i] = bench::float_instructions(op);
    bench::put_op_line(op, fixed[i], &flt[i]);
  }

  const int iir1 = static_cast<int>(Op::iir1);
  const int iir2 = static_cast<int>(Op::iir2);
  const bool iir2_fast = fixed[iir2] <= kIir2TargetInstructions * bench::kSamples;
  const bool float_slow = flt[iir1] >= kFloatTargetFactor * fixed[iir1] &&
                          flt[iir2] >= kFloatTargetFactor * fixed[iir2];

  rv32virt::puts("{\"summary\":\"iir2 step (coefficients in RAM) ");
  rv32virt::put_ratio(fixed[iir2], bench::kSamples);
  rv32virt::puts(" instructions in Q<16>/Q<30>, target <= 40 ");
  rv32virt::puts(iir2_fast ? "met" : "missed");
  rv32virt::puts("; float slower by ");
  rv32virt::put_ratio(flt[iir1], fixed[iir1]);
  rv32virt::puts("x (iir1) and ");
  rv32virt::put_ratio(flt[iir2], fixed[iir2]);
  rv32virt::puts("x (iir2), target >= 10x ");
  rv32virt::puts(float_slow ? "met" : "missed");
  rv32virt::puts("\"");
  bench::put_ratio_field("iir2_ratio", flt[iir2], fixed[iir2]);
  bench::put_ratio_field("iir1_ratio", flt[iir1], fixed[iir1]);
  bench::put_ratio_field("iir2_fixed_instr", fixed[iir2], bench::kSamples);
  put_bool_field("iir2_target_met", iir2_fast);
  put_bool_field("float_10x_target_met", float_slow);
  rv32virt::puts("}\n");
  return 0;
}
