#include "scanners/clean/floor.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "scanners/clean/euclidean_clusters.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

struct Candidate {
  FloorPlane plane;                 // up not yet oriented
  std::vector<int> subset_inliers;  // indices into the subset
};

std::vector<Eigen::Index> RandomSubset(Eigen::Index n, int size, unsigned seed) {
  std::vector<Eigen::Index> all(static_cast<size_t>(n));
  std::iota(all.begin(), all.end(), Eigen::Index{0});
  if (n <= size) return all;
  std::mt19937 rng(seed);
  for (int i = 0; i < size; ++i) {
    std::uniform_int_distribution<Eigen::Index> pick(i, n - 1);
    std::swap(all[static_cast<size_t>(i)], all[static_cast<size_t>(pick(rng))]);
  }
  all.resize(static_cast<size_t>(size));
  return all;
}

// RANSAC planes on the subset, each on what the previous ones left.
class PlaneFinder {
 public:
  PlaneFinder(const FloorOptions& options, const Eigen::MatrixX3d& subset)
      : cloud_(new pcl::PointCloud<pcl::PointXYZ>), remaining_(new pcl::Indices) {
    cloud_->resize(static_cast<size_t>(subset.rows()));
    for (Eigen::Index i = 0; i < subset.rows(); ++i) {
      (*cloud_)[static_cast<size_t>(i)] =
          pcl::PointXYZ(static_cast<float>(subset(i, 0)), static_cast<float>(subset(i, 1)),
                        static_cast<float>(subset(i, 2)));
    }
    remaining_->resize(cloud_->size());
    std::iota(remaining_->begin(), remaining_->end(), 0);
    min_inliers_ = std::max<size_t>(
        50, static_cast<size_t>(options.min_inlier_fraction * static_cast<double>(subset.rows())));
    segmentation_.setModelType(pcl::SACMODEL_PLANE);
    segmentation_.setMethodType(pcl::SAC_RANSAC);
    segmentation_.setDistanceThreshold(options.distance_mm);
    segmentation_.setMaxIterations(options.ransac_iterations);
    segmentation_.setOptimizeCoefficients(true);
    segmentation_.setInputCloud(cloud_);
  }

  // The next plane, or false when none holds enough points.
  bool Next(Candidate* candidate) {
    if (remaining_->size() < min_inliers_) return false;
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    segmentation_.setIndices(remaining_);
    segmentation_.segment(inliers, coefficients);
    if (inliers.indices.size() < min_inliers_ || coefficients.values.size() != 4) return false;
    const Eigen::Vector3d normal(coefficients.values[0], coefficients.values[1],
                                 coefficients.values[2]);
    const double norm = normal.norm();
    if (!(norm > 0)) return false;
    candidate->plane.up = normal / norm;
    candidate->plane.offset_mm = coefficients.values[3] / norm;
    candidate->subset_inliers.assign(inliers.indices.begin(), inliers.indices.end());
    std::vector<bool> taken(cloud_->size(), false);
    for (int i : inliers.indices) taken[static_cast<size_t>(i)] = true;
    auto next = std::make_shared<pcl::Indices>();
    for (int i : *remaining_) {
      if (!taken[static_cast<size_t>(i)]) next->push_back(i);
    }
    remaining_ = next;
    return true;
  }

 private:
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud_;
  pcl::IndicesPtr remaining_;
  size_t min_inliers_ = 50;
  pcl::SACSegmentation<pcl::PointXYZ> segmentation_;
};

// The body: the largest cluster of the subset points on none of the
// candidate planes (not a chair or a pole beside it, nor stray points).
// Empty, with `why` set, when there is no such cluster.
Eigen::MatrixX3d BodyCluster(const FloorOptions& options, const Eigen::MatrixX3d& subset,
                             const std::vector<Candidate>& candidates, std::string* why) {
  std::vector<bool> on_plane(static_cast<size_t>(subset.rows()), false);
  for (const Candidate& c : candidates) {
    for (int i : c.subset_inliers) on_plane[static_cast<size_t>(i)] = true;
  }
  std::vector<Eigen::Index> off;
  for (Eigen::Index i = 0; i < subset.rows(); ++i) {
    if (!on_plane[static_cast<size_t>(i)]) off.push_back(i);
  }
  if (off.size() < 100) {
    *why = "almost all points lie on planes; no body above a floor";
    return {};
  }
  Eigen::MatrixX3d off_points(static_cast<Eigen::Index>(off.size()), 3);
  for (size_t i = 0; i < off.size(); ++i)
    off_points.row(static_cast<Eigen::Index>(i)) = subset.row(off[i]);
  ClusterOptions cluster;
  cluster.tolerance_mm = options.body_gap_mm;
  const Clusters clusters = EuclideanClusters(cluster, off_points);
  if (clusters.sizes.front() < 50) {
    *why = "the points off the planes are scattered; no body above a floor";
    return {};
  }
  Eigen::MatrixX3d body(clusters.sizes.front(), 3);
  for (Eigen::Index i = 0, row = 0; i < off_points.rows(); ++i) {
    if (clusters.label[static_cast<size_t>(i)] == 0) body.row(row++) = off_points.row(i);
  }
  return body;
}

// A standing body is taller along `up` than it is wide across it (A-pose
// ~1.6x; a floor with a body on it seen from a wall is not).
bool StandsAlong(const Eigen::MatrixX3d& body, const Eigen::Vector3d& up) {
  const Eigen::Vector3d e1 = up.unitOrthogonal(), e2 = up.cross(e1);
  auto span = [&](const Eigen::Vector3d& axis) {
    std::vector<double> t(static_cast<size_t>(body.rows()));
    for (Eigen::Index i = 0; i < body.rows(); ++i)
      t[static_cast<size_t>(i)] = axis.dot(body.row(i).transpose());
    std::sort(t.begin(), t.end());
    return t[t.size() * 99 / 100] - t[t.size() / 100];
  };
  const double across =
      std::max({span(e1), span(e2), span((e1 + e2).normalized()), span((e1 - e2).normalized())});
  return span(up) >= 1.2 * across;
}

Eigen::Vector3d MajorAxis(const Eigen::MatrixX3d& points) {
  const Eigen::RowVector3d mean = points.colwise().mean();
  const Eigen::MatrixX3d centred = points.rowwise() - mean;
  const Eigen::Matrix3d covariance = centred.transpose() * centred;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  return solver.eigenvectors().col(2);
}

// Orients candidate.plane.up towards the body and says whether it passes.
bool Accept(const FloorOptions& options, const Eigen::MatrixX3d& body, const Eigen::Vector3d& axis,
            FloorPlane* plane, std::string* why) {
  const double angle_deg = std::acos(std::min(1.0, std::abs(plane->up.dot(axis)))) * 180.0 / kPi;
  if (angle_deg > options.max_axis_angle_deg) {
    *why = "plane normal " + std::to_string(static_cast<int>(angle_deg)) +
           " deg from the body's long axis";
    return false;
  }
  std::vector<double> height;
  std::int64_t above = 0, below = 0;
  for (Eigen::Index i = 0; i < body.rows(); ++i) {
    const double h = plane->Height(body.row(i).transpose());
    if (h > options.distance_mm) ++above;
    if (h < -options.distance_mm) ++below;
    height.push_back(h);
  }
  if (below > above) {
    plane->up = -plane->up;
    plane->offset_mm = -plane->offset_mm;
    std::swap(above, below);
    for (double& h : height) h = -h;
  }
  const double one_side = above + below > 0 ? static_cast<double>(above) / (above + below) : 0.0;
  if (one_side < options.min_one_side_fraction) {
    *why = "only " + std::to_string(static_cast<int>(100 * one_side)) +
           " % of the other points on one side of the plane";
    return false;
  }
  const auto q = height.begin() + static_cast<std::ptrdiff_t>(0.99 * (height.size() - 1));
  std::nth_element(height.begin(), q, height.end());
  if (*q < options.min_body_height_mm) {
    *why = "the points above the plane reach only " + std::to_string(static_cast<int>(*q)) + " mm";
    return false;
  }
  return true;
}

// Least-squares plane through the points within distance_mm of `plane`,
// keeping its orientation. Unchanged when there are fewer than 3.
FloorPlane Refit(const Eigen::MatrixX3d& points, const FloorPlane& plane, double distance_mm) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  std::int64_t count = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose();
    if (std::abs(plane.Height(p)) > distance_mm) continue;
    sum += p;
    outer += p * p.transpose();
    ++count;
  }
  if (count < 3) return plane;
  const Eigen::Vector3d centroid = sum / count;
  const Eigen::Matrix3d covariance = outer / count - centroid * centroid.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  FloorPlane refit;
  refit.up = solver.eigenvectors().col(0).normalized();
  if (refit.up.dot(plane.up) < 0) refit.up = -refit.up;
  refit.offset_mm = -refit.up.dot(centroid);
  return refit;
}

}  // namespace

void FloorOptions::Check() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("floor option out of range: " + what);
  };
  require(distance_mm > 0 && distance_mm <= 200, "distance_mm must be in (0, 200]");
  require(max_planes >= 1 && max_planes <= 10, "max_planes must be 1..10");
  require(min_inlier_fraction > 0 && min_inlier_fraction < 1,
          "min_inlier_fraction must be in (0, 1)");
  require(max_axis_angle_deg > 0 && max_axis_angle_deg <= 90,
          "max_axis_angle_deg must be in (0, 90]");
  require(min_one_side_fraction > 0.5 && min_one_side_fraction <= 1,
          "min_one_side_fraction must be in (0.5, 1]");
  require(min_body_height_mm >= 0, "min_body_height_mm must be >= 0");
  require(ransac_sample >= 100, "ransac_sample must be >= 100");
  require(body_gap_mm > 0 && body_gap_mm <= 1000, "body_gap_mm must be in (0, 1000]");
  require(ransac_iterations >= 10, "ransac_iterations must be >= 10");
}

FloorResult RemoveFloor(const FloorOptions& options, const Eigen::MatrixX3d& points) {
  options.Check();
  FloorResult result;
  result.keep.assign(static_cast<size_t>(points.rows()), true);
  if (points.rows() < 100) {
    result.note = "too few points to look for a floor";
    return result;
  }
  const std::vector<Eigen::Index> subset_rows =
      RandomSubset(points.rows(), options.ransac_sample, options.seed);
  Eigen::MatrixX3d subset(static_cast<Eigen::Index>(subset_rows.size()), 3);
  for (size_t i = 0; i < subset_rows.size(); ++i) {
    subset.row(static_cast<Eigen::Index>(i)) = points.row(subset_rows[i]);
  }
  // Candidate planes. The first is usually the floor: when it clearly is
  // (body on one side, along its normal and standing tall on it) the other
  // RANSAC runs, which would cost 10x more, are skipped.
  PlaneFinder finder(options, subset);
  std::vector<Candidate> candidates;
  int best = -1;
  for (Candidate c; static_cast<int>(candidates.size()) < options.max_planes && finder.Next(&c);) {
    candidates.push_back(c);
    if (candidates.size() > 1) continue;
    std::string why;
    const Eigen::MatrixX3d body = BodyCluster(options, subset, candidates, &why);
    if (body.rows() == 0) continue;
    FloorPlane plane = c.plane;
    if (Accept(options, body, MajorAxis(body), &plane, &why) && StandsAlong(body, plane.up)) {
      candidates.front().plane = plane;
      best = 0;
      break;
    }
  }
  result.candidates = static_cast<int>(candidates.size());
  if (candidates.empty()) {
    result.note = "RANSAC found no plane holding enough points";
    return result;
  }
  if (best < 0) {
    // All candidates against the body left by all of them.
    std::string reasons;
    const Eigen::MatrixX3d body = BodyCluster(options, subset, candidates, &reasons);
    if (body.rows() == 0) {
      result.note = reasons;
      return result;
    }
    const Eigen::Vector3d axis = MajorAxis(body);
    for (size_t c = 0; c < candidates.size(); ++c) {
      std::string why;
      if (Accept(options, body, axis, &candidates[c].plane, &why)) {
        if (best < 0 || candidates[c].subset_inliers.size() >
                            candidates[static_cast<size_t>(best)].subset_inliers.size()) {
          best = static_cast<int>(c);
        }
      } else {
        reasons += (reasons.empty() ? "" : "; ") + ("plane " + std::to_string(c + 1) + ": " + why);
      }
    }
    if (best < 0) {
      result.note = "no plane qualifies as the floor (" + reasons + ")";
      return result;
    }
  }

  FloorPlane plane = candidates[static_cast<size_t>(best)].plane;
  for (int pass = 0; pass < 2; ++pass) plane = Refit(points, plane, options.distance_mm);
  result.found = true;
  result.plane = plane;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double h = plane.Height(points.row(i).transpose());
    if (h < -options.distance_mm) {
      ++result.below_points;
      result.keep[static_cast<size_t>(i)] = false;
    } else if (h <= options.distance_mm) {
      ++result.floor_points;
      result.keep[static_cast<size_t>(i)] = false;
    }
  }
  return result;
}

}  // namespace bespoke
