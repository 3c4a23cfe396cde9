#include <common/parameter_table.hpp>

namespace wire {
namespace {

// Ids are 1..kParameterCount in table order (tests/common/parameter_table_test.cpp checks it), so
// an id finds its row by subtraction.
size_t row_of(uint8_t id) { return id >= 1 && id <= kParameterCount ? size_t{id} - 1 : kParameterCount; }

}  // namespace

const ParameterSpec* find_parameter(uint8_t id) {
  const size_t row = row_of(id);
  return row < kParameterCount ? &kParameterTable[row] : nullptr;
}

ParameterValues::ParameterValues() {
  for (size_t i = 0; i < kParameterCount; ++i) values_[i] = kParameterLimits[i].default_value;
}

int32_t ParameterValues::get(ParamId id) const {
  const size_t row = row_of(static_cast<uint8_t>(id));
  return row < kParameterCount ? values_[row] : 0;
}

NackReason ParameterValues::set(uint8_t id, int32_t raw) {
  const size_t row = row_of(id);
  if (row >= kParameterCount) return NackReason::unknown_parameter;
  if (!in_range(kParameterLimits[row], raw)) return NackReason::bad_value;
  values_[row] = raw;
  return NackReason::none;
}

}  // namespace wire
