#include "scanners/clean/outliers.h"

#include <gtest/gtest.h>
#include <pcl/filters/radius_outlier_removal.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/point_types.h>

#include <random>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/clean/voxel_grid.h"

namespace bespoke {
namespace {

using testing::MakeSyntheticScene;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

struct Kept {
  double body = 0, isolated = 0, clumped = 0;  // fractions kept
};

// Fractions of body points, isolated stray points and clumped stray points
// (those with another stray point within 10 mm) that `keep` keeps.
Kept Fractions(const SyntheticScene& scene, const std::vector<bool>& keep) {
  const Eigen::MatrixX3d stray = scene.PointsMm(ScenePart::kOutlier);
  double n[3] = {0, 0, 0}, k[3] = {0, 0, 0};
  Eigen::Index s = 0;
  for (size_t i = 0; i < scene.part.size(); ++i) {
    int kind = 0;
    if (scene.part[i] == ScenePart::kOutlier) {
      const Eigen::RowVector3d p = stray.row(s++);
      kind = 1;
      for (Eigen::Index j = 0; j < stray.rows(); ++j) {
        if (j != s - 1 && (stray.row(j) - p).norm() < 10) kind = 2;
      }
    } else if (scene.part[i] != ScenePart::kBody) {
      continue;
    }
    n[kind] += 1;
    k[kind] += keep[i] ? 1 : 0;
  }
  return {k[0] / n[0], k[1] / n[1], k[2] / n[2]};
}

SyntheticScene BodyWithStrayPoints() {
  SyntheticSceneOptions options;
  options.floor = false;
  options.second_object = false;
  options.isolated_outliers = 1000;
  options.outlier_clumps = 100;
  return MakeSyntheticScene(options);
}

// As in the chain, on the voxelised cloud (uniform density). The voxel grid
// keeps stray points where they are (alone in their cells); the labels
// follow them.
SyntheticScene Voxelised(const SyntheticScene& scene) {
  SyntheticScene out = scene;
  out.cloud = VoxelGridDownsample(VoxelGridOptions{}, scene.cloud);
  const std::vector<int> nearest = NearestPointIndices(scene.cloud.points, out.cloud.points);
  out.part.resize(static_cast<size_t>(out.cloud.size()));
  for (size_t i = 0; i < out.part.size(); ++i)
    out.part[i] = scene.part[static_cast<size_t>(nearest[i])];
  return out;
}

TEST(OutliersTest, StatisticalTestRemovesStrayPointsAndKeepsTheBody) {
  const SyntheticScene scene = Voxelised(BodyWithStrayPoints());
  const NeighbourLists nn = FindNearestNeighbours(scene.cloud.points, 16);
  const OutlierTest test = StatisticalOutliers(StatisticalOutlierOptions{}, nn);
  const Kept kept = Fractions(scene, test.keep);
  EXPECT_GT(kept.body, 0.999);
  EXPECT_EQ(kept.isolated, 0.0);
  EXPECT_EQ(kept.clumped, 0.0);
  // mm; the median score on a 4 mm voxel grid is ~7.6 mm, a stray point's
  // (>= 40 mm from any surface) is far above.
  EXPECT_GT(test.threshold, 8.0);
  EXPECT_LT(test.threshold, 15.0);
}

// PCL's mean + 3 stddev threshold is dragged up by the outliers themselves;
// with 10 % stray points it keeps many of them, the median/MAD threshold
// does not.
TEST(OutliersTest, RobustThresholdBeatsMeanAndStddev) {
  SyntheticSceneOptions options;
  options.floor = false;
  options.second_object = false;
  options.spacing_mm = 8.0;
  options.isolated_outliers = 3000;
  const SyntheticScene scene = MakeSyntheticScene(options);
  const NeighbourLists nn = FindNearestNeighbours(scene.cloud.points, 16);
  const Kept robust = Fractions(scene, StatisticalOutliers(StatisticalOutlierOptions{}, nn).keep);

  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (Eigen::Index i = 0; i < scene.cloud.size(); ++i) {
    cloud->push_back(pcl::PointXYZ(scene.cloud.points(i, 0), scene.cloud.points(i, 1),
                                   scene.cloud.points(i, 2)));
  }
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> sor;
  sor.setInputCloud(cloud);
  sor.setMeanK(16);
  sor.setStddevMulThresh(3.0);
  pcl::Indices inliers;
  sor.filter(inliers);
  std::vector<bool> keep(scene.part.size(), false);
  for (int i : inliers) keep[static_cast<size_t>(i)] = true;
  const Kept pcl_kept = Fractions(scene, keep);
  EXPECT_LT(robust.isolated, 0.01);
  EXPECT_GT(pcl_kept.isolated, 10 * robust.isolated + 0.05);
  EXPECT_GT(robust.body, 0.99);
}

TEST(OutliersTest, RadiusTestRemovesClumpsOfThree) {
  const SyntheticScene scene = Voxelised(BodyWithStrayPoints());
  const NeighbourLists nn = FindNearestNeighbours(scene.cloud.points, 16);
  const OutlierTest test = RadiusOutliers(RadiusOutlierOptions{}, nn);
  const Kept kept = Fractions(scene, test.keep);
  EXPECT_GT(kept.body, 0.999);
  EXPECT_EQ(kept.isolated, 0.0);
  EXPECT_EQ(kept.clumped, 0.0);
}

// Decided from sorted k-lists, the radius test is exactly PCL's.
TEST(OutliersTest, RadiusTestEqualsPclRadiusOutlierRemoval) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 300.0);
  Eigen::MatrixX3d points(5000, 3);
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const pcl::PointXYZ p(static_cast<float>(u(rng)), static_cast<float>(u(rng)),
                          static_cast<float>(u(rng) / 10));
    cloud->push_back(p);
    points.row(i) << p.x, p.y, p.z;
  }
  RadiusOutlierOptions options;
  options.radius_mm = 9.0;
  options.min_neighbors = 3;
  const OutlierTest ours = RadiusOutliers(options, FindNearestNeighbours(points, 3));
  pcl::RadiusOutlierRemoval<pcl::PointXYZ> ror;
  ror.setInputCloud(cloud);
  ror.setRadiusSearch(options.radius_mm);
  ror.setMinNeighborsInRadius(options.min_neighbors);
  pcl::Indices inliers;
  ror.filter(inliers);
  std::vector<bool> theirs(points.rows(), false);
  for (int i : inliers) theirs[static_cast<size_t>(i)] = true;
  int differ = 0, kept = 0;
  for (size_t i = 0; i < theirs.size(); ++i)
    differ += theirs[i] != ours.keep[i], kept += ours.keep[i];
  EXPECT_EQ(differ, 0);
  EXPECT_GT(kept, 500);  // the test is not trivially all-in or all-out
  EXPECT_LT(kept, 4500);
}

}  // namespace
}  // namespace bespoke
