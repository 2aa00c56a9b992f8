// The k nearest neighbours of every point of a cloud, found once and shared by
// the cleaning stages (statistical and radius outlier tests, normal estimation,
// normal orientation).
//
// One FLANN k-d tree query for all points, run on `threads` threads. Measured
// on this project's 2-core machine (docs/cleaning.md): 160k points, k = 16,
// 0.28 s with FLANN's batch query against 0.85 s through PCL's KdTreeFLANN
// wrapper point by point, and PCL's StatisticalOutlierRemoval,
// RadiusOutlierRemoval and NormalEstimationOMP each repeat that query. Sharing
// one query is what keeps `bespoke clean` inside its time budget.
//
// Input: points, #P x 3, any frame, mm. Output: for point i, up to k other
// points (never i itself), nearest first, with their distances in mm. After
// points are removed, Restrict() re-indexes the lists to the survivors.
#ifndef BESPOKE_SCANNERS_CLEAN_NEIGHBOURS_H_
#define BESPOKE_SCANNERS_CLEAN_NEIGHBOURS_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke {

struct NeighbourLists {
  int k = 0;  // slots per point
  // Row-major #P x k. Slot j of point i: index[i * k + j], or -1 when empty
  // (fewer than k other points, or removed by Restrict). Nearest first.
  std::vector<int> index;
  std::vector<float> distance_mm;  // same layout; +inf in empty slots

  Eigen::Index num_points() const {
    return k > 0 ? static_cast<Eigen::Index>(index.size()) / k : 0;
  }
  int at(Eigen::Index i, int j) const { return index[static_cast<size_t>(i) * k + j]; }
  float distance(Eigen::Index i, int j) const {
    return distance_mm[static_cast<size_t>(i) * k + j];
  }
  // Number of filled slots of point i (filled slots come first).
  int count(Eigen::Index i) const;

  // The lists of the points `kept` (indices into this cloud, increasing),
  // re-indexed so that kept[m] becomes m; neighbours that were not kept are
  // dropped (remaining ones stay nearest first).
  NeighbourLists Restrict(const std::vector<Eigen::Index>& kept) const;
};

// The k nearest other points of every point. `points` #P x 3 (mm), finite.
// k >= 1. threads <= 0: all available. Throws InputError when k < 1.
NeighbourLists FindNearestNeighbours(const Eigen::MatrixX3d& points, int k, int threads = 0);

// For each query row, the index of the nearest point of `points` (-1 when
// `points` is empty). Used by tests and reports to match clouds.
std::vector<int> NearestPointIndices(const Eigen::MatrixX3d& points,
                                     const Eigen::MatrixX3d& queries, int threads = 0);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_NEIGHBOURS_H_
