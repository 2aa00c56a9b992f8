// The cleaning chain: a raw scan of a standing person in, a clean,
// down-sampled cloud with outward normals in the body frame out.
//
// Stages, in order (each can be switched off; defaults in the options):
//   finite             drop NaN/Inf points and coordinates beyond 1e7 mm (always on)
//   voxel_grid         down-sample to one point per leaf (scanners/clean/voxel_grid.h)
//   floor              RANSAC floor plane, removed; gives up (scanners/clean/floor.h)
//   neighbours         k nearest neighbours, once, shared by the next stages
//   statistical_outliers   mean neighbour distance test (scanners/clean/outliers.h)
//   radius_outliers    neighbours-within-radius test (scanners/clean/outliers.h)
//   largest_cluster    keep the largest Euclidean cluster (scanners/clean/euclidean_clusters.h)
//   body_frame         body_from_scanner (scanners/clean/body_frame.h; always on)
//   normals            outward normals (scanners/clean/normals.h)
// Why this order: voxelisation first (fewer points for everything after it,
// a uniform density for the outlier tests, and the same output spacing since
// later stages only remove points); the floor next (RANSAC runs on a random
// subset and does not need clean data; the floor often holds half the
// points, which the neighbour search then never sees).
//
// Input: a cloud in the scanner frame, millimetres (scanners/io converts the
// file's unit). Output: the cleaned cloud in the body frame (mm), the rigid
// body_from_scanner, per-stage counts and wall times, and flags (see
// docs/cleaning.md for every flag). Colours and scalars are averaged by the
// voxel grid and kept; normals are re-estimated (or dropped with normals off).
// Throws InputError when too few points remain to be a body.
#ifndef BESPOKE_SCANNERS_CLEAN_CLEAN_H_
#define BESPOKE_SCANNERS_CLEAN_CLEAN_H_

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scanners/clean/body_frame.h"
#include "scanners/clean/euclidean_clusters.h"
#include "scanners/clean/floor.h"
#include "scanners/clean/normals.h"
#include "scanners/clean/outliers.h"
#include "scanners/clean/voxel_grid.h"
#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

struct CleanOptions {
  bool use_voxel_grid = true;  // default on
  VoxelGridOptions voxel_grid;
  bool use_statistical_outliers = true;  // default on
  StatisticalOutlierOptions statistical_outliers;
  bool use_radius_outliers = true;  // default on
  RadiusOutlierOptions radius_outliers;
  bool use_floor = true;  // default on
  FloorOptions floor;
  bool use_largest_cluster = true;  // default on
  ClusterOptions cluster;
  bool use_normals = true;  // default on
  NormalOptions normals;
  BodyFrameOptions body_frame;
  int threads = 0;  // <= 0: all available. Default 0.
  // Checks every enabled stage's options; throws InputError.
  void Check() const;
};

struct CleanStage {
  std::string name;  // e.g. "voxel_grid"
  bool enabled = true;
  std::int64_t points_in = 0;
  std::int64_t points_out = 0;
  double time_s = 0.0;  // wall time
  double cpu_s = 0.0;   // process CPU time, all threads (wall is inflated on a busy machine)
};

struct CleanResult {
  PointCloud cloud;                                                     // body frame, mm
  Eigen::Isometry3d body_from_scanner = Eigen::Isometry3d::Identity();  // rigid, mm
  std::vector<CleanStage> stages;           // in order, disabled ones included
  std::int64_t non_finite_dropped = 0;      // by the `finite` stage
  std::optional<FloorPlane> floor;          // scanner frame, when found
  std::string floor_note;                   // why no floor, when not found
  std::vector<std::int64_t> cluster_sizes;  // all clusters, largest (kept) first
  BodyFrame frame;
  NormalReport normals;
  std::vector<std::string> flags;  // frame flags and chain flags, e.g. "no_floor"
  double total_time_s = 0.0;
};

// `scanner_cloud` is taken by value: std::move it in when it is no longer
// needed, to save a copy of the raw scan.
CleanResult CleanScan(const CleanOptions& options, PointCloud scanner_cloud,
                      Progress* progress = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_CLEAN_H_
