#include "scanners/clean/normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/clean/voxel_grid.h"

namespace bespoke {
namespace {

using testing::MakeSyntheticScene;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

// Fraction of `normals` agreeing in sign with the true normal of the nearest
// of `truth_points`.
double OutwardFraction(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::MatrixX3d& truth_points,
                       const Eigen::MatrixX3d& truth_normals) {
  const std::vector<int> nearest = NearestPointIndices(truth_points, points);
  double outward = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (normals.row(i).dot(truth_normals.row(nearest[static_cast<size_t>(i)])) > 0) outward += 1;
  }
  return outward / static_cast<double>(points.rows());
}

// A sphere of radius 100 mm with its bottom cap missing (open like a body
// scan at the soles) and a 40 mm hole on the side.
TEST(NormalsTest, SphereWithHolesPointsOut) {
  std::mt19937 rng(1);
  std::normal_distribution<double> g;
  std::vector<Eigen::Vector3d> kept;
  while (kept.size() < 20000) {
    const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    if (d.z() < -0.9) continue;                                        // open bottom
    if ((100 * d - Eigen::Vector3d(100, 0, 0)).norm() < 20) continue;  // side hole
    kept.push_back(d);
  }
  Eigen::MatrixX3d points(static_cast<Eigen::Index>(kept.size()), 3), truth(points.rows(), 3);
  for (size_t i = 0; i < kept.size(); ++i) {
    truth.row(static_cast<Eigen::Index>(i)) = kept[i].transpose();
    points.row(static_cast<Eigen::Index>(i)) =
        (Eigen::Vector3d(0, 0, 100) + 100 * kept[i]).transpose();
  }
  NormalOptions options;
  const OrientedNormals normals =
      EstimateOutwardNormals(options, points, FindNearestNeighbours(points, options.k));
  EXPECT_EQ(OutwardFraction(points, normals.normals, points, truth), 1.0);
  EXPECT_GT(normals.report.by_exterior, 0.9 * points.rows());
  // Plane-fit directions on a 100 mm sphere are within a few degrees.
  double worst = 1;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    worst = std::min(worst, normals.normals.row(i).dot(truth.row(i)));
  EXPECT_GT(worst, std::cos(10.0 * M_PI / 180.0));
}

// A body-sized closed surface (a capsule, 300 mm across) with a 70 mm hole in
// the side: wider than the 20 mm closing seals (about 40 mm), so the inside
// is flooded as "outside" and both probe directions leave the shell at the
// same distance. The inside check sees the torso's inside flooded and closes
// wider (30 mm, then 40 mm); every normal then points out.
TEST(NormalsTest, WideHoleIntoTheInsideIsClosedAndNormalsPointOut) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0, 1);
  const double r = 150, h = 1000;  // radius, height of the straight part
  std::vector<Eigen::Vector3d> points, truth;
  while (points.size() < 60000) {
    const double a = 2 * M_PI * u(rng), z = -r + (h + 2 * r) * u(rng);
    Eigen::Vector3d n(std::cos(a), std::sin(a), 0);
    Eigen::Vector3d p =
        Eigen::Vector3d(0, 0, r) + r * n + Eigen::Vector3d(0, 0, std::clamp(z, 0.0, h));
    if (z < 0 || z > h) {  // the caps: a hemisphere below and above
      const double c = z < 0 ? 0 : h, lat = std::asin(std::clamp((z - c) / r, -1.0, 1.0));
      n = Eigen::Vector3d(std::cos(lat) * std::cos(a), std::cos(lat) * std::sin(a), std::sin(lat));
      p = Eigen::Vector3d(0, 0, r + c) + r * n;
    }
    if ((p - Eigen::Vector3d(r, 0, r + 0.6 * h)).norm() < 35)
      continue;  // the hole, at torso height
    points.push_back(p), truth.push_back(n);
  }
  Eigen::MatrixX3d cloud(static_cast<Eigen::Index>(points.size()), 3),
      normals_true(cloud.rows(), 3);
  for (size_t i = 0; i < points.size(); ++i) {
    cloud.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    normals_true.row(static_cast<Eigen::Index>(i)) = truth[i].transpose();
  }
  NormalOptions options;
  const OrientedNormals normals =
      EstimateOutwardNormals(options, cloud, FindNearestNeighbours(cloud, options.k));
  EXPECT_GT(normals.report.closing_mm, options.hole_close_mm);
  double outward = 0;
  for (Eigen::Index i = 0; i < cloud.rows(); ++i)
    outward += normals.normals.row(i).dot(normals_true.row(i)) > 0;
  EXPECT_GT(outward / static_cast<double>(cloud.rows()), 0.999);
}

// The synthetic person (body frame), voxelised as the chain does, with a gap
// at each wrist: thin hands, the crotch, armpits, feet tops, the crown.
TEST(NormalsTest, BodyNormalsPointOut) {
  SyntheticSceneOptions options;
  options.floor = false;
  options.second_object = false;
  options.isolated_outliers = 0;
  options.outlier_clumps = 0;
  options.wrist_gap_mm = 20.0;
  const SyntheticScene scene = MakeSyntheticScene(options);
  const PointCloud cloud = VoxelGridDownsample(VoxelGridOptions{}, scene.cloud);
  NormalOptions normal_options;
  const OrientedNormals normals =
      EstimateOutwardNormals(normal_options, cloud.points, FindNearestNeighbours(cloud.points, 16));
  const double outward =
      OutwardFraction(cloud.points, normals.normals, scene.cloud.points, scene.true_normals);
  EXPECT_GT(outward, 0.995);
  EXPECT_GT(normals.report.by_exterior, 0.9 * cloud.size());
  EXPECT_EQ(normals.report.by_exterior + normals.report.by_propagation +
                normals.report.by_fallback + normals.report.degenerate,
            cloud.size());
  std::cout << "outward " << outward << " exterior " << normals.report.by_exterior << " propagated "
            << normals.report.by_propagation << " fallback " << normals.report.by_fallback << "\n";
}

}  // namespace
}  // namespace bespoke
