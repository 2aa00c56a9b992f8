// Euclidean (single-linkage) clustering: two points are in the same cluster
// when a chain of points joins them with no step longer than `tolerance_mm`.
// The cleaning chain keeps the largest cluster, which drops stray objects
// (a chair, a pole, the scanner's frame) and loose fragments once the floor
// that joined them to the body is gone.
//
// The clusters are exactly those of pcl::EuclideanClusterExtraction with
// the same tolerance (the tests compare the two), computed on a grid instead
// of one k-d tree radius search per point: cells of tolerance/sqrt(3), so
// the points of one cell are always joined; a union-find over cells then
// tests point pairs only between neighbouring cells not yet joined, which is
// much faster than a radius search per point (docs/cleaning.md).
//
// Choosing the tolerance: a body scan has holes (under the arms, between the
// legs, the top of the head) and a part can come out separated from the rest
// by a thin unscanned band, e.g. a hand at the wrist. Every gap narrower than
// the tolerance is bridged; every object farther than it from the body is
// dropped. The default 30 mm keeps a hand behind a 25 mm unscanned band and
// still drops a chair a hand's width away; an object touching the body (a
// hand on a chair) cannot be separated by any tolerance.
//
// Input: points #P x 3 (mm). Output: a label per point, 0 = largest cluster,
// 1 = next, ...; and the cluster sizes, largest first.
#ifndef BESPOKE_SCANNERS_CLEAN_EUCLIDEAN_CLUSTERS_H_
#define BESPOKE_SCANNERS_CLEAN_EUCLIDEAN_CLUSTERS_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace bespoke {

struct ClusterOptions {
  double tolerance_mm = 30.0;  // largest gap bridged. Default 30 mm (see above).
  // Throws InputError unless 0 < tolerance_mm <= 1000.
  void Check() const;
};

struct Clusters {
  std::vector<int> label;           // #P, 0 = largest cluster
  std::vector<std::int64_t> sizes;  // points per cluster, descending
};

Clusters EuclideanClusters(const ClusterOptions& options, const Eigen::MatrixX3d& points);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_EUCLIDEAN_CLUSTERS_H_
