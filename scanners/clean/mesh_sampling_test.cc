// Meshes sampled over their faces: even density whatever the triangles,
// face normals, units resolved, clouds passed through unchanged.
#include "scanners/clean/mesh_sampling.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

// A 200 x 200 mm plate on z = 0 (normal +z): the left half (x < 0) two
// triangles, the right half a fan of 2,000 thin triangles about one corner,
// so the vertices crowd one corner and the triangles' areas differ 1000-fold.
TriangleMesh UnevenPlate() {
  TriangleMesh m;
  const int fan = 2000;
  m.vertices.resize(4 + fan + 1, 3);
  m.vertices.row(0) << -100, -100, 0;
  m.vertices.row(1) << 0, -100, 0;
  m.vertices.row(2) << 0, 100, 0;
  m.vertices.row(3) << -100, 100, 0;
  // Fan about (0, -100) over the right half's far edges (x = 100, then y = 100).
  for (int i = 0; i <= fan; ++i) {
    const double t = 2.0 * i / fan;  // 0..2 along the two far edges
    m.vertices.row(4 + i) << (t <= 1 ? 100 : 100 - 100 * (t - 1)), (t <= 1 ? -100 + 200 * t : 100),
        0;
  }
  m.faces.resize(2 + fan, 3);
  m.faces.row(0) << 0, 1, 2;
  m.faces.row(1) << 0, 2, 3;
  for (int i = 0; i < fan; ++i) m.faces.row(2 + i) << 1, 4 + i, 5 + i;
  return m;
}

TEST(MeshSampling, DensityIsEvenWhateverTheTriangles) {
  MeshSamplingOptions options;
  options.points_per_cm2 = 20;
  const PointCloud cloud = SampleMeshSurface(options, UnevenPlate());
  ASSERT_EQ(cloud.size(), 8000);  // 400 cm2 x 20
  // Every 5 x 5 cm patch holds its share (500 points): a Poisson count's SD
  // is 22, so 25 % is over 5 SD; the mesh's vertices would give 0 in most.
  int counts[4][4] = {};
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    EXPECT_NEAR(cloud.points(i, 2), 0, 1e-9);
    EXPECT_NEAR(cloud.normals(i, 2), 1, 1e-9);
    const int cx = std::min(3, static_cast<int>((cloud.points(i, 0) + 100) / 50));
    const int cy = std::min(3, static_cast<int>((cloud.points(i, 1) + 100) / 50));
    ++counts[cx][cy];
  }
  int worst = 0;
  for (const auto& row : counts)
    for (int c : row) worst = std::max(worst, std::abs(c - 500));
  std::printf("5 x 5 cm patches: largest deviation from 500 points %d\n", worst);
  EXPECT_LT(worst, 125);
  // The same seed gives the same cloud.
  EXPECT_EQ(SampleMeshSurface(options, UnevenPlate()).points, cloud.points);
}

TEST(MeshSampling, ChecksItsInput) {
  MeshSamplingOptions bad;
  bad.points_per_cm2 = 0;
  EXPECT_THROW(bad.Check(), InputError);
  TriangleMesh empty;
  EXPECT_THROW(SampleMeshSurface(MeshSamplingOptions(), empty), InputError);
  TriangleMesh flat = UnevenPlate();
  flat.vertices.col(1).setZero();  // every face degenerate
  EXPECT_THROW(SampleMeshSurface(MeshSamplingOptions(), flat), InputError);
  MeshSamplingOptions capped;
  capped.max_points = 100;
  EXPECT_EQ(SampleMeshSurface(capped, UnevenPlate()).size(), 100);
}

TEST(MeshSampling, AMeshFileIsSampledInMillimetresAndACloudPassesThrough) {
  testing::TempDir dir;
  // A 2 m x 0.5 m plate in metres (a body-sized extent, so metres are guessed).
  TriangleMesh plate = UnevenPlate();
  plate.vertices.col(0) *= 0.01;    // 2 m wide
  plate.vertices.col(1) *= 0.0025;  // 0.5 m tall
  WriteMesh(WriteOptions(), plate, dir / "plate.obj");
  MeshSamplingOptions sampling;
  sampling.points_per_cm2 = 1;
  ReadOptions read;
  read.min_finite_points = 0;
  const Scan scan = ReadScanSamplingMeshes(read, sampling, dir / "plate.obj");
  EXPECT_EQ(scan.report.unit, LengthUnit::kMetre);
  EXPECT_EQ(scan.report.faces_in_file, plate.num_faces());
  EXPECT_EQ(scan.cloud.size(), 10000);                        // 1 m2 at 1 point per cm2
  EXPECT_NEAR(scan.cloud.points.col(0).maxCoeff(), 1000, 5);  // mm
  ASSERT_FALSE(scan.report.warnings.empty());
  EXPECT_NE(scan.report.warnings.back().find("sampled over its faces"), std::string::npos);
  // A cloud is read as it is.
  WriteScan(WriteOptions(), scan.cloud, dir / "cloud.ply");
  read.units = LengthUnit::kMillimetre;
  const Scan cloud = ReadScanSamplingMeshes(read, sampling, dir / "cloud.ply");
  EXPECT_EQ(cloud.cloud.size(), scan.cloud.size());
}

}  // namespace
}  // namespace bespoke
