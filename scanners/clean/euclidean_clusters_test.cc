#include "scanners/clean/euclidean_clusters.h"

#include <gtest/gtest.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <map>
#include <random>

#include "oracle/scene/synthetic_scene.h"

namespace bespoke {
namespace {

using testing::MakeSyntheticScene;
using testing::ScenePart;
using testing::SyntheticScene;
using testing::SyntheticSceneOptions;

// Clumps of points at random places: many clusters, some touching.
Eigen::MatrixX3d Clumps(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> centre(0.0, 600.0);
  std::normal_distribution<double> spread(0.0, 8.0);
  Eigen::MatrixX3d points(6000, 3);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();  // set at i = 0
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (i % 60 == 0) c = Eigen::Vector3d(centre(rng), centre(rng), centre(rng) / 4);
    points.row(i) = (c + Eigen::Vector3d(spread(rng), spread(rng), spread(rng))).transpose();
  }
  return points;
}

// Exactly the partition of pcl::EuclideanClusterExtraction.
TEST(EuclideanClustersTest, SamePartitionAsPcl) {
  for (double tolerance : {6.0, 15.0, 40.0}) {
    const Eigen::MatrixX3d points = Clumps(static_cast<unsigned>(tolerance));
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      cloud->push_back(pcl::PointXYZ(points(i, 0), points(i, 1), points(i, 2)));
    }
    pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
    pcl::EuclideanClusterExtraction<pcl::PointXYZ> extraction;
    extraction.setClusterTolerance(tolerance);
    extraction.setMinClusterSize(1);
    extraction.setMaxClusterSize(1 << 30);
    extraction.setSearchMethod(tree);
    extraction.setInputCloud(cloud);
    std::vector<pcl::PointIndices> theirs;
    extraction.extract(theirs);

    ClusterOptions options;
    options.tolerance_mm = tolerance;
    const Clusters ours = EuclideanClusters(options, points);
    ASSERT_EQ(ours.sizes.size(), theirs.size()) << "tolerance " << tolerance;
    // Same partition: every PCL cluster maps onto exactly one of ours, of the same size.
    for (const pcl::PointIndices& cluster : theirs) {
      const int label = ours.label[static_cast<size_t>(cluster.indices.front())];
      for (int i : cluster.indices) ASSERT_EQ(ours.label[static_cast<size_t>(i)], label);
      EXPECT_EQ(ours.sizes[static_cast<size_t>(label)],
                static_cast<std::int64_t>(cluster.indices.size()));
    }
    EXPECT_GT(theirs.size(), 3u);
    EXPECT_LT(theirs.size(), 6000u);
  }
}

// A hand behind a 20 mm unscanned band at the wrist stays with the body at
// the default 30 mm tolerance; the pole 150 mm away does not.
TEST(EuclideanClustersTest, KeepsAHandBehindAGapAndDropsThePole) {
  SyntheticSceneOptions options;
  options.floor = false;
  options.isolated_outliers = 0;
  options.outlier_clumps = 0;
  options.wrist_gap_mm = 20.0;
  options.spacing_mm = 5.0;
  const SyntheticScene scene = MakeSyntheticScene(options);
  const Clusters clusters = EuclideanClusters(ClusterOptions{}, scene.cloud.points);
  ASSERT_EQ(clusters.sizes.size(), 2u);
  for (size_t i = 0; i < scene.part.size(); ++i) {
    ASSERT_EQ(clusters.label[i], scene.part[i] == ScenePart::kBody ? 0 : 1);
  }
  // With a tolerance below the gap, the hands are cut off: the gap is real.
  ClusterOptions tight;
  tight.tolerance_mm = 15.0;
  EXPECT_GE(EuclideanClusters(tight, scene.cloud.points).sizes.size(), 4u);
}

}  // namespace
}  // namespace bespoke
