// SplitMix64: a small, fully specified generator, so a seed gives the same
// MakeHuman body with any standard library.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_RANDOM_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_RANDOM_H_

#include <cmath>
#include <cstdint>

namespace bespoke {

class MakeHumanRandom {
 public:
  explicit MakeHumanRandom(std::uint64_t seed) : state_(seed ^ 0x6a09e667f3bcc909ULL) {}
  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(Next() >> 11) * 0x1.0p-53;
  }
  // Gaussian (Box-Muller).
  double Normal(double mean, double sd) {
    const double u1 = Uniform(1e-12, 1.0), u2 = Uniform(0.0, 1.0);
    return mean + sd * std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }

 private:
  std::uint64_t state_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_RANDOM_H_
