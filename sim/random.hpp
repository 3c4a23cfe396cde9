// Seeded randomness that gives the same numbers on every platform and standard library:
// xoshiro256** (Blackman and Vigna, 2018) for bits, seeded through splitmix64, and our own normal
// deviate (Marsaglia's polar method). std::normal_distribution is not used because its algorithm
// is the library's choice, so the same seed would fly differently with libstdc++ and libc++.
#pragma once

#include <stdint.h>

namespace sim {

class Random {
 public:
  explicit Random(uint64_t seed);

  uint64_t next();
  double uniform();  // [0, 1), 53 random bits
  double uniform(double low, double high);
  double normal();  // mean 0, standard deviation 1

  // An independent generator for one part of the world (an IMU, a battery sensor), derived from
  // the seed and a stream number: adding a draw to one part does not change what another gets.
  Random stream(uint64_t id) const;

 private:
  uint64_t seed_;
  uint64_t s_[4] = {};
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace sim
