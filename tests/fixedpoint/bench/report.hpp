// JSON output on the devboard console: one object a line, numbers with two decimals.
#pragma once

#include <qr/boards/rv32virt/devboard.hpp>

#include "ops.hpp"
#include "samples.hpp"

namespace bench {

// "key":num/den, or null when den is 0.
inline void put_ratio_field(const char* key, uint32_t num, uint32_t den) {
  rv32virt::puts(",\"");
  rv32virt::puts(key);
  rv32virt::puts("\":");
  if (den == 0) {
    rv32virt::puts("null");
  } else {
    rv32virt::put_ratio(num, den);
  }
}

// {"op":"mul","fixed_instr":N[,"float_instr":M,"float_over_fixed":M/N]} with N and M per call.
inline void put_op_line(Op op, uint32_t fixed_total, const uint32_t* float_total) {
  rv32virt::puts("{\"op\":\"");
  rv32virt::puts(kOps[static_cast<int>(op)].name);
  rv32virt::putc('"');
  put_ratio_field("fixed_instr", fixed_total, kSamples);
  if (float_total != nullptr) {
    put_ratio_field("float_instr", *float_total, kSamples);
    put_ratio_field("float_over_fixed", *float_total, fixed_total);
  }
  rv32virt::puts("}\n");
}

}  // namespace bench
