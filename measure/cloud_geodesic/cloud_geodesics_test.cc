#include "measure/cloud_geodesic/cloud_geodesics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <thread>
#include <utility>

#include "scanners/core/errors.h"
#include "tests/support/sampled_surfaces.h"

namespace bespoke {
namespace {

using testing::Sampling;
constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d OnSphere(double r, double lon, double lat) {
  return r * Eigen::Vector3d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                             std::sin(lat));
}

Eigen::Vector3d OnCylinder(double r, double theta, double z) {
  return Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), z);
}

// Relative error of point-to-point lengths on a sphere of radius 80 mm.
double WorstSphereError(const Eigen::MatrixX3d& cloud, double r) {
  CloudGeodesics geodesics({}, cloud);
  const double pairs[][4] = {{0.0, 0.0, 1.2, 0.4},
                             {0.3, -0.6, 2.8, 0.5},
                             {-1.0, 0.2, 1.0, -0.9},
                             {0.5, 1.0, 0.5, -1.1},
                             {2.0, 0.1, 2.3, 0.15}};
  double worst = 0;
  for (const auto& p : pairs) {
    const Eigen::Vector3d a = OnSphere(r, p[0], p[1]), b = OnSphere(r, p[2], p[3]);
    const CloudGeodesicPath path = geodesics.Between(a, b);
    const double exact = testing::SphereDistance(r, a, b);
    worst = std::max(worst, std::abs(path.length_mm - exact) / exact);
    for (Eigen::Index i = 0; i < path.points.rows(); ++i)  // the path lies on the surface
      EXPECT_NEAR(path.points.row(i).norm(), r, 0.5) << i;
  }
  return worst;
}

TEST(CloudGeodesics, GridStoresOnlyNonEmptyCells) {
  const Eigen::MatrixX3d cloud = testing::SampleSphere({2.0, 0.0, 5}, 80);
  const CloudGrid grid({}, cloud);
  // A dense 160 mm box of ~5 mm cells would have ~33,000 cells; the sphere's
  // shell touches a few thousand, and those are all that is stored.
  EXPECT_NEAR(grid.cell_size_mm(), 3 * grid.spacing_mm(), 1e-9);
  EXPECT_LT(grid.num_cells(), cloud.rows() / 3);
  EXPECT_EQ(grid.num_nodes(), grid.num_cells());  // one sheet per cell here
  for (Eigen::Index i = 0; i < cloud.rows(); i += 97)
    EXPECT_LT((grid.site(grid.node_of_point(i)) - cloud.row(i).transpose()).norm(),
              2 * grid.cell_size_mm());
  for (int node = 0; node < grid.num_nodes(); node += 13) {
    EXPECT_NEAR(grid.site(node).norm(), 80, 0.05);  // sites lie on the surface
    EXPECT_GE(grid.links_end(node) - grid.links_begin(node), 4);
  }
}

TEST(CloudGeodesics, PlaneGivesStraightLines) {
  const Eigen::MatrixX3d cloud = testing::SamplePlane({2.0, 0.0, 3}, 150);
  CloudGeodesics geodesics({}, cloud);
  const double pairs[][4] = {
      {-120, -100, 110, 90}, {-130, 0, 130, 5}, {0, 0, 20, 3}, {-50, 120, 60, -130}};
  for (const auto& p : pairs) {
    const Eigen::Vector3d a(p[0], p[1], 0), b(p[2], p[3], 0);
    const CloudGeodesicPath path = geodesics.Between(a, b);
    const double exact = (a - b).norm();
    EXPECT_NEAR(path.length_mm, exact, 0.005 * exact) << a.transpose() << " -> " << b.transpose();
    for (Eigen::Index i = 0; i < path.points.rows(); ++i) EXPECT_NEAR(path.points(i, 2), 0.0, 0.05);
  }
}

TEST(CloudGeodesics, SphereGivesGreatCircles) {
  const double r = 80;
  EXPECT_LE(WorstSphereError(testing::SampleSphere({2.0, 0.0, 5}, r), r), 0.005);
}

// 0.5 mm Gaussian noise along the normal (a good scanner's level). Measured
// worst 0.16 % (sphere) with the default fit of 32 neighbours; tolerance 0.5 %.
TEST(CloudGeodesics, NoisySphereWithinHalfAPercent) {
  const double r = 80;
  const double worst = WorstSphereError(testing::SampleSphere({2.0, 0.5, 5}, r), r);
  std::printf("noisy sphere: worst relative error %.3f %%\n", 100 * worst);
  EXPECT_LE(worst, 0.005);
}

// Holes of 16 mm diameter on the paths (unscanned patches): the local fits
// bridge them, so the geodesic still crosses straight over.
TEST(CloudGeodesics, SphereWithHolesWithinHalfAPercent) {
  const double r = 80;
  Eigen::MatrixX3d cloud = testing::SampleSphere({2.0, 0.0, 5}, r);
  for (const double lon : {0.4, 0.8, 1.5, 2.2})
    cloud = testing::RemoveBall(cloud, OnSphere(r, lon, 0.2), 8);
  const double worst = WorstSphereError(cloud, r);
  std::printf("sphere with holes: worst relative error %.3f %%\n", 100 * worst);
  EXPECT_LE(worst, 0.005);
}

TEST(CloudGeodesics, CylinderGivesHelices) {
  const double r = 50;
  const double pairs[][4] = {
      {0.0, 30, 2.5, 260}, {0.5, 150, -1.0, 40}, {1.0, 100, 1.0 + kPi * 0.9, 120}};
  // Clean; then 0.5 mm noise and a 20 mm hole on the first path.
  Eigen::MatrixX3d noisy = testing::SampleCylinder({2.0, 0.5, 8}, r, 300);
  noisy = testing::RemoveBall(noisy, OnCylinder(r, 1.25, 145), 10);
  const Eigen::MatrixX3d clouds[] = {testing::SampleCylinder({2.0, 0.0, 7}, r, 300), noisy};
  for (const auto& cloud : clouds) {
    CloudGeodesics geodesics({}, cloud);
    for (const auto& p : pairs) {
      const CloudGeodesicPath path =
          geodesics.Between(OnCylinder(r, p[0], p[1]), OnCylinder(r, p[2], p[3]));
      const double exact = testing::CylinderDistance(r, p[0], p[1], p[2], p[3]);
      std::printf("cylinder: %.3f mm for %.3f mm (%.3f %%)\n", path.length_mm, exact,
                  100 * (path.length_mm - exact) / exact);
      EXPECT_NEAR(path.length_mm, exact, 0.005 * exact);
    }
  }
}

// A tube of radius r_mm and height_mm sampled as a sparse scanner sees skin
// at a grazing angle: vertical columns column_mm apart round it, a point every
// 4 mm down each, 0.5 mm of noise along the normal. The nearest-neighbour
// spacing is the 4 mm within a column, so the sheet gap (twice its 90th
// percentile) is narrower than the columns are apart.
Eigen::MatrixX3d ScanColumnsOnCylinder(double r_mm, double height_mm, double column_mm) {
  const int columns = static_cast<int>(std::floor(2 * kPi * r_mm / column_mm));
  const int rows = static_cast<int>(height_mm / 4.0) + 1;
  Eigen::MatrixX3d cloud(columns * rows, 3);
  std::uint32_t state = 12345;  // a fixed LCG: the same cloud on every platform
  const auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0 - 0.5;
  };
  for (int c = 0; c < columns; ++c)
    for (int k = 0; k < rows; ++k) {
      const double theta = 2 * kPi * c / columns;
      const double noise_mm = 0.5 * std::sqrt(12.0) * uniform();  // SD 0.5 mm
      cloud.row(c * rows + k) =
          OnCylinder(r_mm + noise_mm, theta, 4.0 * k + 0.5 * uniform()).transpose();
    }
  return cloud;
}

// Columns 12 mm apart, wider than the sheet gap and the 8 mm cells (set
// here, as where a denser scan elsewhere sets them): a cell often holds one
// column, a line of points that fixes no plane. Its node must still lie on
// the tube and link to the columns beside it; a plane through the column
// but across the tube left every column a separate piece.
TEST(CloudGeodesics, ScanColumnsWiderThanTheSheetGapStayOneSurface) {
  const double r = 55;
  const Eigen::MatrixX3d cloud = ScanColumnsOnCylinder(r, 240, 12);
  CloudGeodesicsOptions options;
  options.grid.cell_size_mm = 8;
  CloudGeodesics geodesics(options, cloud);
  ASSERT_LT(geodesics.grid().sheet_gap_mm(), 12.0);
  const double pairs[][4] = {{0.0, 120, 0.5 * kPi, 120}, {0.3, 60, 2.1, 180}, {1.0, 100, 4.0, 110}};
  for (const auto& p : pairs) {
    const CloudGeodesicPath path =
        geodesics.Between(OnCylinder(r, p[0], p[1]), OnCylinder(r, p[2], p[3]));
    const double exact = testing::CylinderDistance(r, p[0], p[1], p[2], p[3]);
    std::printf("scan columns: %.2f mm for %.2f mm\n", path.length_mm, exact);
    EXPECT_NEAR(path.length_mm, exact, 0.02 * exact);
  }
}

TEST(CloudGeodesics, BadQueriesAreInputErrors) {
  const Eigen::MatrixX3d cloud = testing::SamplePlane({2.0, 0.0, 3}, 50);
  CloudGeodesics geodesics({}, cloud);
  const Eigen::Vector3d on(0, 0, 0);
  EXPECT_THROW(geodesics.Between(Eigen::Vector3d(0, std::nan(""), 0), on), InputError);
  EXPECT_THROW(geodesics.Between(on, Eigen::Vector3d(0, 0, 300)), InputError);  // far off
  EXPECT_THROW(geodesics.DistancesFrom(Eigen::Vector3d(1e6, 0, 0)), InputError);
  EXPECT_NEAR(geodesics.Between(on, on).length_mm, 0.0, 1e-9);
  EXPECT_THROW(CloudGeodesics({}, Eigen::MatrixX3d::Zero(5, 3)), InputError);
  CloudGeodesicsOptions bad;
  bad.grid.neighbours = 2;
  EXPECT_THROW(CloudGeodesics(bad, cloud), InputError);
  CloudGeodesicsOptions splits;
  splits.polish_splits = -1;
  EXPECT_THROW(CloudGeodesics(splits, cloud), InputError);
}

// A query point inside a large unscanned patch (as the crotch on a body
// scan) is accepted and flagged, the hole spanned by chords to its rim; a
// point as far off the surface in the air is refused.
TEST(CloudGeodesics, PointsInAnUnscannedHoleAreReachedAcrossIt) {
  const double r = 80;
  const Eigen::Vector3d centre = OnSphere(r, 0.0, 0.0);
  const Eigen::MatrixX3d cloud =
      testing::RemoveBall(testing::SampleSphere({2.0, 0.0, 5}, r), centre, 30);
  CloudGeodesics geodesics({}, cloud);
  const Eigen::Vector3d far = OnSphere(r, 2.0, 0.3);
  const CloudGeodesicPath path = geodesics.Between(centre, far);
  EXPECT_TRUE(path.from_unscanned);
  EXPECT_FALSE(path.to_unscanned);
  EXPECT_NEAR(path.from_snap_mm, 30, 4);  // mm: the rim, about 30 mm from the centre
  EXPECT_LT(path.to_snap_mm, 1.0);
  // The hole is spanned by straight chords from the point to its rim, so the
  // length is short only by chord vs arc across the hole (30.2 vs 30 mm).
  const double exact = testing::SphereDistance(r, centre, far);
  EXPECT_NEAR(path.length_mm, exact, 1.5);
  EXPECT_LT((path.points.row(0).transpose() - centre).norm(), 1e-9);  // starts at the point
  // Either way round, and with both ends in holes (a second hole at `far`).
  EXPECT_NEAR(geodesics.Between(far, centre).length_mm, path.length_mm, 1.0);
  const CloudGeodesicPath both =
      CloudGeodesics({}, testing::RemoveBall(cloud, far, 25)).Between(centre, far);
  EXPECT_TRUE(both.from_unscanned && both.to_unscanned);
  EXPECT_NEAR(both.length_mm, exact, 2.5);
  // 30 mm off the skin, in the air beside the hole: not surrounded, refused.
  EXPECT_THROW(geodesics.Between(OnSphere(r + 30, 0.6, 0.0), far), InputError);
  EXPECT_THROW(geodesics.Between(OnSphere(r + 30, 0.0, 0.0), far), InputError);
  CloudGeodesicsOptions never;
  never.max_hole_snap_distance_mm = 0;
  CloudGeodesics strict(never, cloud);
  EXPECT_THROW(strict.Between(centre, far), InputError);
}

// A fork shares the grid and answers on another thread exactly as the
// original, and a propagation that reuses the storage of the one before it
// (a new source on the same object) exactly as a fresh object.
TEST(CloudGeodesics, ForksAndReusedStorageGiveTheSamePaths) {
  const double r = 80;
  const Eigen::MatrixX3d cloud = testing::SampleSphere({2.0, 0.3, 4}, r);
  const Eigen::Vector3d a = OnSphere(r, 0.0, 0.1), b = OnSphere(r, 1.9, -0.4);
  const Eigen::Vector3d c = OnSphere(r, -0.8, 0.9), d = OnSphere(r, 2.6, 0.2);
  CloudGeodesics original({}, cloud);
  const CloudGeodesicPath ab = original.Between(a, b);
  const CloudGeodesicPath cd = original.Between(c, d);  // reuses ab's storage
  const std::unique_ptr<CloudGeodesics> fork = original.Fork();
  EXPECT_EQ(&fork->grid(), &original.grid());
  CloudGeodesicPath fork_cd, fork_ab;
  std::thread worker([&] {
    fork_cd = fork->Between(c, d);
    fork_ab = fork->Between(a, b);
  });
  const CloudGeodesicPath again_ab = original.Between(a, b);  // meanwhile, on this thread
  worker.join();
  const CloudGeodesicPath fresh_cd = CloudGeodesics({}, cloud).Between(c, d);
  EXPECT_GT(ab.length_mm, 100);  // mm: about 150 on the sphere
  using Pair = std::pair<const CloudGeodesicPath*, const CloudGeodesicPath*>;
  for (const Pair& p :
       {Pair{&ab, &fork_ab}, Pair{&ab, &again_ab}, Pair{&cd, &fork_cd}, Pair{&cd, &fresh_cd}}) {
    EXPECT_EQ(p.first->length_mm, p.second->length_mm);
    EXPECT_TRUE(p.first->points == p.second->points);
  }
}

// NearestOf skips the targets that cannot win but answers as trying each
// target alone does: the least distance plus extra, the first of equals.
// The winner here is not the target with the least straight distance plus
// extra: a far target's arc is much longer than its chord.
TEST(CloudGeodesics, NearestOfAgreesWithEveryTargetTriedAlone) {
  const double r = 80;
  const Eigen::MatrixX3d cloud = testing::SampleSphere({2.0, 0.3, 6}, r);
  const auto nearest_row = [&](const Eigen::Vector3d& x) {
    Eigen::Index row = 0;
    (cloud.rowwise() - x.transpose()).rowwise().squaredNorm().minCoeff(&row);
    return static_cast<int>(row);
  };
  const Eigen::Vector3d from = OnSphere(r, 0.0, 0.0);
  // Far: chord 140 mm, arc about 170, no extra. Near: chord 20, extra 125.
  std::vector<int> targets = {nearest_row(OnSphere(r, 2.13, 0.0)),
                              nearest_row(OnSphere(r, 0.25, 0.0))};
  std::vector<double> extra = {0.0, 125.0};
  for (int k = 0; k < 40; ++k) {  // decoys all round, too dear to win
    targets.push_back((k * 7919) % static_cast<int>(cloud.rows()));
    extra.push_back(200.0 + k);
  }
  targets.push_back(targets[1]);  // a duplicate: the first of two equals wins
  extra.push_back(extra[1]);
  double alone_best = std::numeric_limits<double>::infinity();
  int alone_index = -1;
  CloudGeodesics alone({}, cloud);  // one propagation, grown target by target
  for (size_t i = 0; i < targets.size(); ++i) {
    double cost = 0;
    if (alone.NearestOf(from, {targets[i]}, {extra[i]}, &cost) == 0 && cost < alone_best)
      alone_best = cost, alone_index = static_cast<int>(i);
  }
  EXPECT_EQ(alone_index, 1);
  CloudGeodesics geodesics({}, cloud);
  double cost = 0;
  EXPECT_EQ(geodesics.NearestOf(from, targets, extra, &cost), alone_index);
  EXPECT_EQ(cost, alone_best);
}

// Relative errors of a distance field from `source` on a cloud sampled from
// the sphere of radius r (mm) about the origin, over the points at least 10 mm
// from the source (exact: the great circle to the point's projection on the
// sphere). `unreached`: points without a distance.
using testing::FieldErrors;
FieldErrors SphereFieldErrors(const Eigen::MatrixX3d& cloud, double r,
                              const Eigen::Vector3d& source) {
  CloudGeodesics geodesics({}, cloud);
  const CloudDistanceField field = geodesics.DistancesFrom(source);
  return testing::CompareField(cloud, field.point_distance_mm, [&](const Eigen::Vector3d& x) {
    return testing::SphereDistance(r, source, r * x.normalized());
  });
}

TEST(CloudGeodesics, DistanceFieldOnTheSphere) {
  const double r = 80;
  const FieldErrors e =
      SphereFieldErrors(testing::SampleSphere({2.0, 0.0, 11}, r), r, OnSphere(r, 0.2, 0.3));
  std::printf("sphere field: %d points, mean rel %.4f %%, max rel %.4f %%\n", e.counted,
              100 * e.mean, 100 * e.worst);
  EXPECT_EQ(e.unreached, 0);
  EXPECT_LE(e.mean, 0.005);
  EXPECT_LE(e.worst, 0.03);
}

// Distance fields on noisy spheres (1.5 mm spacing, 0.5 mm noise along the
// normal): every point is reached and every point at least 10 mm from the
// source is within 3 % of the great-circle distance (mean within 0.5 %). Cells
// holding only a few noisy points fit planes tilted into the tangent plane,
// link to nothing and leave islands; min_seed_points guards against that
// (seed 1 shows it).
TEST(CloudGeodesics, NoisySphereFieldReachesEveryPointWithinThreePercent) {
  const double r = 80;
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    const FieldErrors e =
        SphereFieldErrors(testing::SampleSphere({1.5, 0.5, seed}, r), r, OnSphere(r, 0.3, 0.2));
    std::printf("noisy sphere, seed %u: mean %.3f %%, max %.3f %% over %d points\n", seed,
                100 * e.mean, 100 * e.worst, e.counted);
    EXPECT_EQ(e.unreached, 0) << "seed " << seed;
    EXPECT_LT(e.worst, 0.03) << "seed " << seed;
    EXPECT_LT(e.mean, 0.005) << "seed " << seed;
  }
}

}  // namespace
}  // namespace bespoke
