#include "scanners/clean/clean.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <string>

#include "scanners/clean/neighbours.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kMaxCoordinateMm = 1e7;
constexpr int kStages = 9;

std::vector<Eigen::Index> Kept(const std::vector<bool>& keep) {
  std::vector<Eigen::Index> kept;
  for (size_t i = 0; i < keep.size(); ++i) {
    if (keep[i]) kept.push_back(static_cast<Eigen::Index>(i));
  }
  return kept;
}

// Runs the stages in order, recording counts and times.
class Chain {
 public:
  Chain(CleanResult* result, Progress* progress) : result_(result), progress_(progress) {
    ProgressBegin(progress_, "cleaning", kStages);
  }
  ~Chain() { ProgressEnd(progress_); }

  template <typename F>
  void Run(const char* name, bool enabled, PointCloud* cloud, F&& stage) {
    CleanStage record;
    record.name = name;
    record.enabled = enabled;
    record.points_in = cloud->size();
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    if (enabled) stage();
    record.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    record.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    record.points_out = cloud->size();
    result_->stages.push_back(record);
    ProgressUpdate(progress_, static_cast<std::int64_t>(result_->stages.size()));
  }

 private:
  CleanResult* result_;
  Progress* progress_;
};

void RequirePoints(const PointCloud& cloud, const char* after) {
  if (cloud.size() < 100) {
    throw InputError("only " + std::to_string(cloud.size()) + " points left after " + after +
                     "; too few to be a body scan");
  }
}

}  // namespace

void CleanOptions::Check() const {
  if (use_voxel_grid) voxel_grid.Check();
  if (use_statistical_outliers) statistical_outliers.Check();
  if (use_radius_outliers) radius_outliers.Check();
  if (use_floor) floor.Check();
  if (use_largest_cluster) cluster.Check();
  if (use_normals) normals.Check();
  body_frame.Check();
}

CleanResult CleanScan(const CleanOptions& options, PointCloud scanner_cloud, Progress* progress) {
  options.Check();
  scanner_cloud.CheckShapes();
  const auto start = std::chrono::steady_clock::now();
  CleanResult result;
  Chain chain(&result, progress);
  PointCloud cloud;

  const Eigen::Index points_in = scanner_cloud.size();
  chain.Run("finite", true, &cloud, [&] {
    // |x| < 1e7 is false for NaN, so one test covers NaN, Inf and absurd values.
    const Eigen::Array<bool, Eigen::Dynamic, 1> ok =
        (scanner_cloud.points.array().abs() < kMaxCoordinateMm).rowwise().all();
    result.non_finite_dropped = points_in - ok.count();
    if (result.non_finite_dropped == 0) {
      cloud = std::move(scanner_cloud);
      return;
    }
    std::vector<Eigen::Index> kept;
    kept.reserve(static_cast<size_t>(ok.count()));
    for (Eigen::Index i = 0; i < points_in; ++i) {
      if (ok(i)) kept.push_back(i);
    }
    cloud = scanner_cloud.Select(kept);
  });
  result.stages.back().points_in = points_in;
  RequirePoints(cloud, "dropping non-finite points");

  chain.Run("voxel_grid", options.use_voxel_grid, &cloud,
            [&] { cloud = VoxelGridDownsample(options.voxel_grid, cloud); });

  NeighbourLists neighbours;  // computed after the floor is gone

  auto keep_only = [&](const std::vector<bool>& keep) {
    const std::vector<Eigen::Index> kept = Kept(keep);
    if (static_cast<Eigen::Index>(kept.size()) == cloud.size()) return;
    cloud = cloud.Select(kept);
    if (neighbours.k > 0) neighbours = neighbours.Restrict(kept);
  };
  chain.Run("floor", options.use_floor, &cloud, [&] {
    FloorResult floor = RemoveFloor(options.floor, cloud.points);
    if (floor.found) {
      result.floor = floor.plane;
      keep_only(floor.keep);
    } else {
      result.floor_note = floor.note;
      result.flags.push_back("no_floor");
    }
  });
  RequirePoints(cloud, "floor removal");

  int k = 0;
  if (options.use_statistical_outliers) k = std::max(k, options.statistical_outliers.mean_k);
  if (options.use_radius_outliers) k = std::max(k, options.radius_outliers.min_neighbors);
  if (options.use_normals) k = std::max(k, options.normals.k);
  chain.Run("neighbours", k > 0, &cloud,
            [&] { neighbours = FindNearestNeighbours(cloud.points, k, options.threads); });

  chain.Run("statistical_outliers", options.use_statistical_outliers, &cloud,
            [&] { keep_only(StatisticalOutliers(options.statistical_outliers, neighbours).keep); });
  chain.Run("radius_outliers", options.use_radius_outliers, &cloud,
            [&] { keep_only(RadiusOutliers(options.radius_outliers, neighbours).keep); });
  RequirePoints(cloud, "outlier removal");

  chain.Run("largest_cluster", options.use_largest_cluster, &cloud, [&] {
    const Clusters clusters = EuclideanClusters(options.cluster, cloud.points);
    result.cluster_sizes = clusters.sizes;
    std::vector<bool> keep(clusters.label.size());
    for (size_t i = 0; i < keep.size(); ++i) keep[i] = clusters.label[i] == 0;
    const double before = static_cast<double>(cloud.size());
    keep_only(keep);
    // A big second cluster may be a piece of the body cut off by a wide gap.
    if (clusters.sizes.size() > 1 && clusters.sizes[1] > 0.02 * before) {
      result.flags.push_back("large_cluster_dropped");
    }
  });
  RequirePoints(cloud, "keeping the largest cluster");

  chain.Run("body_frame", true, &cloud, [&] {
    result.frame = EstimateBodyFrame(options.body_frame, cloud.points, result.floor);
    result.body_from_scanner = result.frame.body_from_scanner;
    TransformInPlace(Eigen::Affine3d(result.body_from_scanner.matrix()), &cloud);
  });
  for (const std::string& flag : result.frame.flags) result.flags.push_back(flag);

  chain.Run("normals", options.use_normals, &cloud, [&] {
    NormalOptions normal_options = options.normals;
    normal_options.threads = options.threads;
    OrientedNormals normals = EstimateOutwardNormals(normal_options, cloud.points, neighbours);
    cloud.normals = std::move(normals.normals);
    result.normals = normals.report;
  });

  result.cloud = std::move(cloud);
  result.total_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace bespoke
