// The scenario files of sim/scenarios/, compiled into qrsim at configure time
// (builtin_scenarios.cpp.in), so `qrsim --scenario NAME` and `qrsim --list` work without the
// source tree. BuiltinScenarios.* keeps them equal to the files.
#pragma once

#include <span>

namespace qrsim {

struct BuiltinScenario {
  const char* name;  // the file's name without .txt
  const char* text;  // the file, byte for byte
};

std::span<const BuiltinScenario> builtin_scenarios();

}  // namespace qrsim
