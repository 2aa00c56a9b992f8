// Floor detection and removal: the large plane the body stands on, which also
// gives the up direction.
//
// Method:
//  1. Candidate planes: PCL's RANSAC plane segmentation (SACSegmentation,
//     SACMODEL_PLANE) on a random subset of at most `ransac_sample` points,
//     repeated on the remainder up to `max_planes` times (a floor and the
//     walls of a booth), stopping at a plane with fewer inliers than
//     `min_inlier_fraction` of the subset.
//  2. The body: the largest Euclidean cluster (gap `body_gap_mm`) of the
//     subset points that lie on none of the candidate planes, so a chair or
//     a pole beside the person does not count; its long axis is its major
//     principal axis.
//  3. The floor is the candidate with the most inliers whose normal is within
//     `max_axis_angle_deg` of that axis, with at least `min_one_side_fraction`
//     of the body's points on one side (that side is "up") reaching at
//     least `min_body_height_mm` above it. So a wall (normal across the body)
//     or a flat patch of the body itself (e.g. the back) is never taken for
//     the floor.
//     When the first candidate passes (3) and the body stands tall along its
//     normal (height >= 1.2 x width), the further RANSAC runs are skipped:
//     they cost ~10x the first (eval/bench/clean_bench.cc, BM_Floor).
//  4. The plane is refitted by least squares to its inliers among all points;
//     the points within `distance_mm` of it and all points below it are
//     removed.
// No candidate passing (3) means "no floor": nothing is removed and the
// caller falls back to the body's principal axis for up.
//
// Failure modes: a floor holding only a few per cent of the points can be
// missed by RANSAC (then treated as no floor, and the floor fragments around
// the feet are usually dropped by the largest-cluster stage); a person lying
// down is rejected by (3) on purpose.
//
// Input: points #P x 3, mm, scanner frame. Deterministic for a given seed.
#ifndef BESPOKE_SCANNERS_CLEAN_FLOOR_H_
#define BESPOKE_SCANNERS_CLEAN_FLOOR_H_

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace bespoke {

// The plane {x : up . x + offset_mm = 0}; up . x + offset_mm is the signed
// height above it (mm), positive on the body's side.
struct FloorPlane {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // unit normal, towards the body
  double offset_mm = 0.0;
  double Height(const Eigen::Vector3d& x) const { return up.dot(x) + offset_mm; }
};

struct FloorOptions {
  double distance_mm = 10.0;            // RANSAC inlier band, also the removal band. Default 10 mm.
  int max_planes = 3;                   // candidate planes tried. Default 3.
  double min_inlier_fraction = 0.02;    // of the subset, for a candidate. Default 0.02.
  double max_axis_angle_deg = 30.0;     // floor normal vs body long axis. Default 30 deg.
  double min_one_side_fraction = 0.95;  // off-plane points on the up side. Default 0.95.
  double min_body_height_mm = 500.0;    // 99th percentile height above it. Default 500 mm.
  double body_gap_mm = 60.0;     // cluster gap on the subset (~20 mm spacing). Default 60 mm.
  int ransac_sample = 10000;     // points RANSAC runs on (then refitted to all). Default 10000.
  int ransac_iterations = 1000;  // per candidate plane. Default 1000.
  unsigned seed = 1;             // subset selection. Default 1.
  // Throws InputError when a value is out of range.
  void Check() const;
};

struct FloorResult {
  bool found = false;
  FloorPlane plane;               // valid when found (scanner frame)
  std::vector<bool> keep;         // #P: false for floor inliers and points below it
  std::int64_t floor_points = 0;  // removed as within distance_mm
  std::int64_t below_points = 0;  // removed as below the floor
  int candidates = 0;             // candidate planes found by RANSAC
  std::string note;               // why no floor was accepted, when !found
};

FloorResult RemoveFloor(const FloorOptions& options, const Eigen::MatrixX3d& points);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_FLOOR_H_
