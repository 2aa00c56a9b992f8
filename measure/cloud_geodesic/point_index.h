// Nearest-neighbour search over a fixed set of 3-D points (a scan), with
// FLANN's single k-d tree (exact search; FLANN stays inside point_index.cc).
//
// The thesis used ANN (Arya et al. 1998); nanoflann is not packaged by Debian,
// FLANN is. Inputs and outputs are in the points' units (mm in Bespoke);
// distances returned are SQUARED distances, as FLANN computes them.
//
// State reused across calls (hence a class): the tree. Queries are const and
// allocate nothing shared, so one index may be queried from several threads.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_INDEX_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_INDEX_H_

#include <memory>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

class PointIndex {
 public:
  // Copies `points` (#P x 3, finite; InputError when empty or not finite) and
  // builds the tree, O(#P log #P).
  explicit PointIndex(const Eigen::MatrixX3d& points);
  ~PointIndex();
  PointIndex(const PointIndex&) = delete;
  PointIndex& operator=(const PointIndex&) = delete;

  Eigen::Index size() const { return points_.rows(); }
  const Eigen::MatrixX3d& points() const { return points_; }
  Eigen::Vector3d point(Eigen::Index i) const { return points_.row(i).transpose(); }

  // Index of the point nearest `query`; its squared distance in
  // `*squared_distance` when not null. `query` must be finite.
  int Nearest(const Eigen::Vector3d& query, double* squared_distance = nullptr) const;

  // The k points nearest `query`, nearest first: indices and squared
  // distances (resized to min(k, size())). Returns the count.
  int Knn(const Eigen::Vector3d& query, int k, std::vector<int>* indices,
          std::vector<double>* squared_distances) const;

  // The median distance from a point to its nearest other point, estimated on
  // up to `max_samples` evenly spread points (mm): the scan's sample spacing.
  double MedianSpacing(int max_samples = 4000) const { return SpacingQuantile(0.5, max_samples); }
  // The same distance's `quantile` (0..1): 0.9 describes the sparse parts of
  // an unevenly sampled scan (grazing angles, single-sensor areas).
  double SpacingQuantile(double quantile, int max_samples = 4000) const;

 private:
  struct Impl;
  Eigen::MatrixX3d points_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_INDEX_H_
