#include "scanners/clean/voxel_grid.h"

#include <gtest/gtest.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "scanners/clean/neighbours.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

TEST(VoxelGridTest, AveragesEveryAttributePerCell) {
  PointCloud cloud;
  cloud.points.resize(3, 3);
  cloud.points << 1, 1, 1,  //
      3, 3, 3,              // same 4 mm cell as the first
      5, 1, 1;              // the next cell in x
  cloud.normals.resize(3, 3);
  cloud.normals << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  cloud.colors.resize(3, 3);
  cloud.colors << 0, 10, 255, 100, 20, 255, 7, 7, 7;
  cloud.scalars["intensity"] = Eigen::Vector3d(1, 3, 9);

  const PointCloud out = VoxelGridDownsample(VoxelGridOptions{}, cloud);
  ASSERT_EQ(out.size(), 2);
  EXPECT_TRUE(out.points.row(0).isApprox(Eigen::RowVector3d(2, 2, 2)));
  EXPECT_TRUE(out.points.row(1).isApprox(Eigen::RowVector3d(5, 1, 1)));
  EXPECT_TRUE(out.normals.row(0).isApprox(Eigen::RowVector3d(1, 1, 0) / std::sqrt(2.0)));
  EXPECT_EQ(out.colors(0, 0), 50);
  EXPECT_EQ(out.colors(0, 1), 15);
  EXPECT_EQ(out.colors(0, 2), 255);
  EXPECT_DOUBLE_EQ(out.scalars.at("intensity")[0], 2.0);
  EXPECT_DOUBLE_EQ(out.scalars.at("intensity")[1], 9.0);
}

// A dense patch (0.5 mm spacing) comes out at one point per 4 mm cell,
// about 4 mm apart.
TEST(VoxelGridTest, GivesTheTargetSpacing) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 200.0);
  std::normal_distribution<double> noise(0.0, 0.3);
  PointCloud cloud;
  cloud.points.resize(160000, 3);
  for (Eigen::Index i = 0; i < cloud.size(); ++i)
    cloud.points.row(i) << u(rng), u(rng), 2.0 + noise(rng);  // one layer of cells
  const PointCloud out = VoxelGridDownsample(VoxelGridOptions{}, cloud);

  std::set<std::tuple<int, int, int>> cells;
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    cells.emplace(static_cast<int>(std::floor(out.points(i, 0) / 4)),
                  static_cast<int>(std::floor(out.points(i, 1) / 4)),
                  static_cast<int>(std::floor(out.points(i, 2) / 4)));
  }
  EXPECT_EQ(static_cast<Eigen::Index>(cells.size()), out.size()) << "two points in one cell";
  EXPECT_EQ(out.size(), 50 * 50);  // (200 / 4)^2 cells, all occupied
  const NeighbourLists nn = FindNearestNeighbours(out.points, 1);
  std::vector<double> d(nn.distance_mm.begin(), nn.distance_mm.end());
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  EXPECT_NEAR(d[d.size() / 2], 4.0, 0.3);  // median spacing, mm
}

// pcl::VoxelGrid returns its input unchanged when the grid would have more
// than 2^31 cells; one stray point 1 km away must not do that here.
TEST(VoxelGridTest, FarStrayPointDoesNotDisableTheGrid) {
  PointCloud cloud;
  cloud.points.resize(1001, 3);
  for (int i = 0; i < 1000; ++i) cloud.points.row(i) << 0.001 * i, 0, 0;  // all in one 4 mm cell
  cloud.points.row(1000) << 1e6, 1e6, 1e6;
  const PointCloud out = VoxelGridDownsample(VoxelGridOptions{}, cloud);
  EXPECT_EQ(out.size(), 2);
}

TEST(VoxelGridTest, MatchesPclVoxelGridCentroids) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-150.0f, 150.0f);
  pcl::PointCloud<pcl::PointXYZ>::Ptr pcl_cloud(new pcl::PointCloud<pcl::PointXYZ>);
  PointCloud cloud;
  cloud.points.resize(50000, 3);
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ p(u(rng), u(rng), u(rng) * 0.1f);
    pcl_cloud->push_back(p);
    cloud.points.row(i) << p.x, p.y, p.z;  // the same float values
  }
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(pcl_cloud);
  grid.setLeafSize(4.0f, 4.0f, 4.0f);
  pcl::PointCloud<pcl::PointXYZ> pcl_out;
  grid.filter(pcl_out);
  const PointCloud out = VoxelGridDownsample(VoxelGridOptions{}, cloud);

  // Float rounding at cell borders may move a rare point; allow 0.2 %.
  EXPECT_NEAR(static_cast<double>(out.size()), static_cast<double>(pcl_out.size()),
              0.002 * out.size());
  Eigen::MatrixX3d pcl_points(static_cast<Eigen::Index>(pcl_out.size()), 3);
  for (size_t i = 0; i < pcl_out.size(); ++i) {
    pcl_points.row(static_cast<Eigen::Index>(i)) << pcl_out[i].x, pcl_out[i].y, pcl_out[i].z;
  }
  const std::vector<int> nearest = NearestPointIndices(pcl_points, out.points);
  int matched = 0;
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    if ((out.points.row(i) - pcl_points.row(nearest[static_cast<size_t>(i)])).norm() < 1e-3)
      ++matched;
  }
  EXPECT_GT(matched, 0.995 * out.size());
}

TEST(VoxelGridTest, RejectsBadLeaf) {
  VoxelGridOptions options;
  options.leaf_mm = 0.0;
  EXPECT_THROW(options.Check(), InputError);
  options.leaf_mm = std::nan("");
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace bespoke
