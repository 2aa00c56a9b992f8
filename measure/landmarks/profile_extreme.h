// Sub-step extreme of a sampled profile (internal to measure/landmarks).
//
// The detector samples profiles (girth, front depth, ...) on slices 5 mm
// apart. Taking the best sample puts a level on that grid, and where the
// profile is flat near its extreme the scan's noise picks any sample of the
// flat stretch: the level then jumps from scan to scan of the same body.
// The vertex of a least-squares parabola through the samples around the best
// one is continuous and averages the noise of several slices.
#ifndef BESPOKE_MEASURE_LANDMARKS_PROFILE_EXTREME_H_
#define BESPOKE_MEASURE_LANDMARKS_PROFILE_EXTREME_H_

#include <cstddef>
#include <vector>

namespace bespoke::landmarks {

struct ProfileExtremeOptions {
  bool minimum = true;  // default true: refine a minimum (false: a maximum)
  int half_window = 3;  // default 3: samples each side of the best one fitted
  int min_samples = 4;  // default 4: fewer finite samples in the window keep the best sample
};

// The abscissa of the profile's extreme near sample `best`.
// - `at`: #S abscissae (mm), increasing; `value`: #S samples (any unit;
//   non-finite entries are ignored).
// - Fits value = a at^2 + b at + c to the finite samples within
//   `half_window` of `best` and returns the vertex -b / 2a, clamped between
//   the best sample's neighbours (the extreme lies nearer the best sample
//   than any other). Returns at[best] when the fit does not bend the right way
//   (a <= 0 for a minimum) or has too few samples.
// Throws InternalError when `best` is out of range or the sizes differ.
double ProfileExtreme(const ProfileExtremeOptions& options, const std::vector<double>& at,
                      const std::vector<double>& value, size_t best);

// The weighted centre of a profile's top: the mean abscissa of the finite
// samples within `depth` of the extreme, each weighted by how far it passes
// that line (value - (max - depth) for a maximum). On a rounded extreme the
// profile is flat over several samples and the noise picks any of them as
// the best (and then jumps between two near-equal bumps); the centre moves
// continuously with the samples. Returns NaN when no sample is finite.
// - `at`, `value`: #S each (mm; any unit for value, `depth` in it, > 0).
// Throws InternalError when the sizes differ or depth <= 0.
double TopCentre(const ProfileExtremeOptions& options, const std::vector<double>& at,
                 const std::vector<double>& value, double depth);

// A profile smoothed across gaps: at each sample the mean of the finite
// samples within `half` of it (#S); NaN where fewer than `min_count` are
// finite or the window runs off either end.
std::vector<double> WindowMean(const std::vector<double>& value, size_t half, int min_count);

// The index of the best sample (smallest for options.minimum, else the
// largest; the first of equals) among the finite `value`s whose `eligible`
// entry is true (#S each); value.size() when there is none. Throws
// InternalError when the sizes differ.
size_t BestSample(const ProfileExtremeOptions& options, const std::vector<double>& value,
                  const std::vector<bool>& eligible);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_PROFILE_EXTREME_H_
