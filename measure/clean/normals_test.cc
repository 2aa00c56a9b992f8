#include "measure/clean/normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "measure/clean/voxel_grid.h"
#include "tests/support/synthetic_scene.h"

namespace bespoke {
namespace {

using testing::MakeSyntheticScene;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

// Fraction of `normals` agreeing in sign with the true normal of the nearest
// of `truth_points`.
double OutwardFraction(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::MatrixX3d& truth_points, const Eigen::MatrixX3d& truth_normals) {
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
    if (d.z() < -0.9) continue;                                            // open bottom
    if ((100 * d - Eigen::Vector3d(100, 0, 0)).norm() < 20) continue;      // side hole
    kept.push_back(d);
  }
  Eigen::MatrixX3d points(static_cast<Eigen::Index>(kept.size()), 3), truth(points.rows(), 3);
  for (size_t i = 0; i < kept.size(); ++i) {
    truth.row(static_cast<Eigen::Index>(i)) = kept[i].transpose();
    points.row(static_cast<Eigen::Index>(i)) = (Eigen::Vector3d(0, 0, 100) + 100 * kept[i]).transpose();
  }
  NormalOptions options;
  const OrientedNormals normals =
      EstimateOutwardNormals(options, points, FindNearestNeighbours(points, options.k));
  EXPECT_EQ(OutwardFraction(points, normals.normals, points, truth), 1.0);
  EXPECT_GT(normals.report.by_exterior, 0.9 * points.rows());
  // Plane-fit directions on a 100 mm sphere are within a few degrees.
  double worst = 1;
  for (Eigen::Index i = 0; i < points.rows(); ++i) worst = std::min(worst, normals.normals.row(i).dot(truth.row(i)));
  EXPECT_GT(worst, std::cos(10.0 * M_PI / 180.0));
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
  const double outward = OutwardFraction(cloud.points, normals.normals, scene.cloud.points, scene.true_normals);
  EXPECT_GT(outward, 0.995);
  EXPECT_GT(normals.report.by_exterior, 0.9 * cloud.size());
  EXPECT_EQ(normals.report.by_exterior + normals.report.by_propagation + normals.report.by_fallback +
                normals.report.degenerate,
            cloud.size());
  std::cout << "outward " << outward << " exterior " << normals.report.by_exterior << " propagated "
            << normals.report.by_propagation << " fallback " << normals.report.by_fallback << "\n";
}

}  // namespace
}  // namespace bespoke
