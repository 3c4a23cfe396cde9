// Each FX_MISUSE_* case must fail to compile, with the diagnostic the CMake test names; with
// none defined the file must compile, which proves the failures come from the misuse alone.
#include <fixedpoint/fixedpoint.hpp>

double run_time_value();

int main() {
  [[maybe_unused]] fx::Q<16> q(1.5);
#if defined(FX_MISUSE_CONSTANT_OUT_OF_RANGE)
  [[maybe_unused]] constexpr fx::Q<15, int16_t> one(1.0);  // Q<15, int16_t> stops below 1
#elif defined(FX_MISUSE_CONSTANT_NAN)
  [[maybe_unused]] constexpr fx::Q<16> nan(__builtin_nan(""));
#elif defined(FX_MISUSE_RUN_TIME_DOUBLE)
  [[maybe_unused]] fx::Q<16> from_double(run_time_value());
#elif defined(FX_MISUSE_IMPLICIT_INT)
  [[maybe_unused]] fx::Q<16> from_int = 3;
#elif defined(FX_MISUSE_INT_ARITHMETIC)
  [[maybe_unused]] auto sum = q + 1;
#elif defined(FX_MISUSE_IMPLICIT_PRECISION_CHANGE)
  [[maybe_unused]] fx::Q<16> narrower = fx::Q<30>(0.5);
#elif defined(FX_MISUSE_MIXED_FORMATS)
  [[maybe_unused]] auto sum = q + fx::Q<17>(0.5);
#elif defined(FX_MISUSE_IMPLICIT_TO_DOUBLE)
  [[maybe_unused]] double d = q;
#endif
  return 0;
}
