#include "resize/designs/body_variants.h"

#include <iterator>
#include <random>

#include "resize/designs/designs.h"

namespace bespoke {

MeasurementSet VariedMeasurements(const std::string& design, std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 12345);
  std::uniform_real_distribution<double> girth(0.85, 1.35), length(0.90, 1.12), jitter(0.94, 1.06);
  double g = girth(rng);
  while (g > 0.92 && g < 1.08) g = girth(rng);
  const double l = length(rng);
  MeasurementSet m = BaseMeasurements(design);
  for (auto it = m.begin(); it != m.end();)  // derived ones are recomputed below, not drawn
    it = IsDerivedMeasurement(it->first) ? m.erase(it) : std::next(it);
  for (auto& [name, value] : m) {
    const bool is_girth = name.find("_girth") != std::string::npos || name == "back_width" ||
                          name == "armhole_length";
    value *= (is_girth ? g : l) * jitter(rng);
  }
  AddDerivedMeasurements(&m, "varied measurements for " + design);
  return m;
}

}  // namespace bespoke
