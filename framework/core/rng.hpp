#pragma once
// Random numbers that reproduce bit for bit on every platform.
//
// The engine is std::mt19937_64, whose output sequence the C++ standard fixes.
// The distributions are written here from raw 64-bit integers because the
// standard library's distributions are implementation-defined.
#include <cstdint>
#include <random>
#include <string_view>

namespace hystbench {

// One step of SplitMix64: a bijective 64-bit mixer, used to derive seeds.
std::uint64_t splitmix64(std::uint64_t x);

// 64-bit FNV-1a hash of a string (stable across platforms and runs).
std::uint64_t fnv1a64(std::string_view text);

// Seed of one trial, from (experiment seed, algorithm label, trial index).
// It does not depend on when or on which thread the trial runs.
std::uint64_t trial_seed(std::uint64_t experiment_seed, std::string_view label,
                         std::uint64_t trial_index);

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t next() { return engine_(); }
  // U(0,1) with 53 random bits: values in [0, 1).
  double uniform();
  // U(a,b) in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Uniform integer in {lo, ..., hi} (inclusive), without modulo bias.
  std::int64_t integer(std::int64_t lo, std::int64_t hi);
  // Standard normal N(0,1) by the Marsaglia polar method.
  double normal();
  double normal(double mean, double sd) { return mean + sd * normal(); }
  // Cauchy(x0, g) = x0 + g tan(pi (U - 1/2)).
  double cauchy(double x0, double g);

 private:
  std::mt19937_64 engine_;
  double spare_normal_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace hystbench
