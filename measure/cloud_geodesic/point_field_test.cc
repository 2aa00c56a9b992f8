// The per-point distance field (point_field.h) against known answers.
#include "measure/cloud_geodesic/point_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "scanners/core/errors.h"
#include "tests/support/sampled_surfaces.h"

namespace bespoke {
namespace {

using testing::CompareField;
using testing::FieldErrors;

// On a plane the sweep's segment offers follow the circular wavefront: a
// graph's edges alone would zig-zag several per cent long.
TEST(PointField, PlaneDistancesAreEuclidean) {
  const Eigen::MatrixX3d cloud = testing::SamplePlane({2.0, 0.0, 31}, 80);
  const CloudGrid grid({}, cloud);
  const int source = grid.index().Nearest(Eigen::Vector3d::Zero());
  const Eigen::Vector3d s = grid.index().point(source);
  const Eigen::VectorXd d = PointDistanceField({}, grid, {{source, 0.0}});
  const FieldErrors e =
      CompareField(cloud, d, [&](const Eigen::Vector3d& x) { return (x - s).norm(); });
  std::printf("plane: %d points, mean %.3f %%, max %.3f %%\n", e.counted, 100 * e.mean,
              100 * e.worst);
  EXPECT_GT(e.counted, 5000);
  EXPECT_EQ(e.unreached, 0);
  EXPECT_LT(e.mean, 0.005);
  EXPECT_LT(e.worst, 0.02);
}

// A sheet folded round a tube of radius 7.5 mm, on 8 mm cells: the grid's
// links do not make it round a fold tighter than a cell (the upper plate is
// a separate piece, unreached), while chords between neighbouring points do.
// Exact distances from (x1, 0, 0) on the lower plate: sqrt((x - x1)^2 + y^2)
// there, and on the upper plate, unrolled, sqrt((x1 + pi gap / 2 + x)^2 + y^2).
TEST(PointField, ResolvesAFoldTighterThanACell) {
  const double gap = 15, x1 = 60;
  const Eigen::MatrixX3d cloud = testing::SampleFold({2.0, 0.0, 41}, gap, 120, 60);
  const auto exact = [&](const Eigen::Vector3d& x) {
    if (x.x() < 0) return -1.0;  // on the tube: not counted
    return x.z() < gap / 2 ? std::hypot(x.x() - x1, x.y())
                           : std::hypot(x1 + M_PI * gap / 2 + x.x(), x.y());
  };
  CloudGeodesicsOptions options;
  options.grid.cell_size_mm = 8;
  CloudGeodesicsOptions cells_only = options;
  cells_only.point_field.enabled = false;
  FieldErrors e[2];
  for (int k = 0; k < 2; ++k) {
    CloudGeodesics geodesics(k == 0 ? cells_only : options, cloud);
    const CloudDistanceField field = geodesics.DistancesFrom(Eigen::Vector3d(x1, 0, 0));
    e[k] = CompareField(cloud, field.point_distance_mm, exact);
    std::printf("fold, %s: mean %.3f %%, max %.3f %% over %d points, %d unreached\n",
                k == 0 ? "cells only" : "point field", 100 * e[k].mean, 100 * e[k].worst,
                e[k].counted, e[k].unreached);
  }
  EXPECT_GT(e[0].unreached, 1000);  // the limit of cells alone
  // The field at the scan's own points is the same through DistancesAt, also
  // beyond the fold, which the grid's links leave a separate piece.
  CloudGeodesics geodesics(options, cloud);
  const Eigen::VectorXd own = geodesics.DistancesFrom(Eigen::Vector3d(x1, 0, 0)).point_distance_mm;
  const Eigen::VectorXd at = geodesics.DistancesAt(cloud);
  ASSERT_GT(geodesics.grid().component_points().size(), 1u);
  for (Eigen::Index i = 0; i < cloud.rows(); ++i) ASSERT_EQ(at[i], own[i]) << cloud.row(i);
  EXPECT_EQ(e[1].unreached, 0);
  EXPECT_LT(e[1].mean, 0.005);
  EXPECT_LT(e[1].worst, 0.03);
}

// A sheet folded round a 10 mm radius on 20 mm cells: a cell holds the fold
// whole, and its node's quadric does not follow it. Points placed on their own
// fits (24 nearest, `fit_points`) are; on the node surfaces (fit_points = 0)
// points of the fold are carried to the wrong side of it. Exact distances as
// in ResolvesAFoldTighterThanACell.
TEST(PointField, OwnFitsFollowAFoldACellWide) {
  const double gap = 20, x1 = 60;
  const Eigen::MatrixX3d cloud = testing::SampleFold({2.0, 0.0, 41}, gap, 120, 60);
  const auto exact = [&](const Eigen::Vector3d& x) {
    if (x.x() < 0) return -1.0;
    return x.z() < gap / 2 ? std::hypot(x.x() - x1, x.y())
                           : std::hypot(x1 + M_PI * gap / 2 + x.x(), x.y());
  };
  FieldErrors e[2];
  for (int k = 0; k < 2; ++k) {
    CloudGeodesicsOptions options;
    options.grid.cell_size_mm = 20;
    if (k == 0) options.point_field.fit_points = 0;
    CloudGeodesics geodesics(options, cloud);
    e[k] = CompareField(cloud, geodesics.DistancesFrom(Eigen::Vector3d(x1, 0, 0)).point_distance_mm,
                        exact);
    std::printf("fold on 20 mm cells, %s: mean %.3f %%, max %.3f %%, %d unreached\n",
                k == 0 ? "node surfaces" : "own fits", 100 * e[k].mean, 100 * e[k].worst,
                e[k].unreached);
  }
  EXPECT_GT(e[0].worst, 0.03);  // what node surfaces give here
  EXPECT_EQ(e[1].unreached, 0);
  EXPECT_LT(e[1].mean, 0.005);
  EXPECT_LT(e[1].worst, 0.02);
}

TEST(PointField, BadOptionsAndSeedsAreInputErrors) {
  const CloudGrid grid({}, testing::SamplePlane({2.0, 0.0, 32}, 20));
  PointFieldOptions options;
  options.neighbours = 1;
  EXPECT_THROW(PointDistanceField(options, grid, {{0, 0.0}}), InputError);
  options = {};
  options.fit_points = 5;
  EXPECT_THROW(PointDistanceField(options, grid, {{0, 0.0}}), InputError);
  options = {};
  options.max_chord_angle_deg = 0;
  EXPECT_THROW(PointDistanceField(options, grid, {{0, 0.0}}), InputError);
  options = {};
  options.fit_wedge_deg = 2;
  EXPECT_THROW(options.Check(), InputError);
  options.fit_wedge_deg = std::nan("");
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.surface_offset_fraction = -0.1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.agree_fraction = 1;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.seed_radius_cells = -1;
  EXPECT_THROW(options.Check(), InputError);
  EXPECT_THROW(PointDistanceField({}, grid, {{-1, 0.0}}), InputError);
  EXPECT_THROW(PointDistanceField({}, grid, {{0, std::nan("")}}), InputError);
  EXPECT_THROW(PointDistanceField({}, grid, {{0, -1.0}}), InputError);
}

}  // namespace
}  // namespace bespoke
