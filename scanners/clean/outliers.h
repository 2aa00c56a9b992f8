// Outlier tests on shared nearest-neighbour lists (scanners/clean/neighbours.h).
//
// Statistical: a point's score is its mean distance to its `mean_k` nearest
// neighbours (PCL's StatisticalOutlierRemoval score). PCL then rejects scores
// above mean + mul * stddev of all scores; those moments are dragged up by the
// very outliers being sought (a scan with 5 % stray points doubles the
// stddev). Bespoke uses the robust equivalents instead: median and
// 1.4826 * MAD (both equal mean and stddev for normally distributed scores).
//
// Radius: a point is kept when at least `min_neighbors` other points lie
// within `radius_mm` (PCL's RadiusOutlierRemoval), decided exactly from the
// sorted lists: the min_neighbors-th nearest neighbour is within the radius.
//
// Both return keep[i] (true = inlier) for every point of the lists. They need
// lists with k >= mean_k (resp. min_neighbors); otherwise InternalError.
#ifndef BESPOKE_SCANNERS_CLEAN_OUTLIERS_H_
#define BESPOKE_SCANNERS_CLEAN_OUTLIERS_H_

#include <vector>

#include "scanners/clean/neighbours.h"

namespace bespoke {

struct StatisticalOutlierOptions {
  int mean_k = 16;  // neighbours averaged per point. Default 16.
  // Reject score > median + stddev_mul * 1.4826 * MAD: high enough to keep
  // open scan borders (the soles' rim scores above the median), low enough to
  // drop a point well off any surface. Default 5.
  double stddev_mul = 5.0;
  // Throws InputError unless 1 <= mean_k <= 100 and stddev_mul > 0.
  void Check() const;
};

struct RadiusOutlierOptions {
  // Radius of the neighbour count, mm: a few voxel leaves, so a point on a
  // scanned surface has many neighbours within it and a stray point none.
  // Default 15 mm.
  double radius_mm = 15.0;
  int min_neighbors = 4;  // other points required within the radius. Default 4.
  // Throws InputError unless radius_mm > 0 and 1 <= min_neighbors <= 100.
  void Check() const;
};

struct OutlierTest {
  std::vector<bool> keep;  // #P
  double threshold = 0.0;  // statistical: score threshold, mm; radius: radius_mm
};

OutlierTest StatisticalOutliers(const StatisticalOutlierOptions& options,
                                const NeighbourLists& neighbours);
OutlierTest RadiusOutliers(const RadiusOutlierOptions& options, const NeighbourLists& neighbours);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_OUTLIERS_H_
