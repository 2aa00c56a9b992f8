// OFF: fixtures (polygons, colours, normals, comments), round trip,
// malformed files, and the meshes in ../shared/data/meshes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scanners/io/scan_io.h"
#include "tests/support/io_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectInputError;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

TEST(OffRead, QuadsCommentsAndCountsOnTheKeywordLine) {
  TempDir dir;
  WriteBytes(dir / "q.off",
             "OFF 5 2 0 # a square and a triangle\n"
             "# vertices\n"
             "0 0 0\n1 0 0\n1 1 0\n0 1 0\n\n0.5 0.5 1\n"
             "4 0 1 2 3\n"
             "3 0 1 4 255 0 0\n");
  const Mesh mesh = ReadMesh(FixtureOptions(), dir / "q.off");
  EXPECT_EQ(mesh.mesh.num_vertices(), 5);
  EXPECT_EQ(mesh.report.faces_in_file, 2);
  EXPECT_EQ(mesh.mesh.faces, (Eigen::MatrixX3i(3, 3) << 0, 1, 2, 0, 2, 3, 0, 1, 4).finished());
  EXPECT_EQ(mesh.report.format, FileFormat::kOff);
  EXPECT_TRUE(mesh.face_group.empty());
}

TEST(OffRead, ColouredAndNormalVariants) {
  TempDir dir;
  WriteBytes(dir / "c.off",
             "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 1.0 0 1\n0 1 0 0 0 9\n3 0 1 2\n");
  const Scan coff = ReadScan(FixtureOptions(), dir / "c.off");
  ASSERT_TRUE(coff.cloud.has_colors());
  EXPECT_EQ(coff.cloud.colors(0, 0), 255);
  EXPECT_EQ(coff.cloud.colors(1, 1), 255);  // 1.0 is a float: scaled
  EXPECT_EQ(coff.cloud.colors(2, 2), 9);
  WriteBytes(dir / "n.off", "NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  const Scan noff = ReadScan(FixtureOptions(), dir / "n.off");
  ASSERT_TRUE(noff.cloud.has_normals());
  EXPECT_EQ(noff.cloud.normals.row(2), Eigen::RowVector3d(0, 0, 1));
}

TEST(OffWrite, RoundTripIsExact) {
  TempDir dir;
  TriangleMesh mesh;
  mesh.vertices = Eigen::MatrixX3d::Random(12, 3) * 3.0;
  mesh.faces.resize(10, 3);
  for (int f = 0; f < 10; ++f) mesh.faces.row(f) << f, f + 1, f + 2;
  WriteOptions options;
  options.comment = "units dm";
  WriteMesh(options, mesh, dir / "m.off");
  const Mesh back = ReadMesh(FixtureOptions(), dir / "m.off");
  EXPECT_EQ(back.mesh.vertices, mesh.vertices);
  EXPECT_EQ(back.mesh.faces, mesh.faces);
}

TEST(OffMalformed, Corpus) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"PLOFF\n", "unsupported OFF variant"},
      {"4OFF\n3 1\n", "unsupported OFF variant"},
      {"OFF BINARY\n", "binary OFF is not supported"},
      {"OFF\n", "counts are missing"},
      {"OFF\n3\n", "expected '#vertices #faces"},
      {"OFF\n3 x\n", "count 'x' is not an integer"},
      {"OFF\n-3 1\n", "is negative"},
      {"OFF\n3000000000 1\n", "more than the limit"},
      {"OFF\n1000000 1\n0 0 0\n", "cannot fit"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1      \n3 0 1 2\n", "line 5: a vertex needs 3 values, found 2"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 q\n3 0 1 2\n", "'q' is not a number"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "refers to vertex '3' but there are 3"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "refers to vertex '-1'"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n2 0 1    \n", "vertex count (>= 3)"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "needs 5 values"},
      {"OFF\n3 2\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n      \n", "1 of 2 faces (truncated)"},
      {"OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n", "data after the last face"},
      {"OFF\n3 0\n0 0 0\n1 0 0\n0 1 0\n", "has no faces"},
  };
  int k = 0;
  for (const auto& [text, fragment] : cases) {
    SCOPED_TRACE(fragment);
    const auto file = dir / ("bad" + std::to_string(k++) + ".off");
    WriteBytes(file, text);
    ExpectInputError([&] { ReadMesh(FixtureOptions(), file); }, file, fragment);
  }
}

TEST(OffRead, SharedMeshes) {
  BESPOKE_REQUIRE_SHARED(shared);
  const Mesh body = ReadMesh(ReadOptions(), shared / "data/meshes/makehuman-body-tri-13k.off");
  EXPECT_EQ(body.mesh.num_vertices(), 13380);
  EXPECT_EQ(body.mesh.num_faces(), 26756);
  EXPECT_EQ(body.report.unit, LengthUnit::kDecimetre);
  EXPECT_TRUE(body.report.unit_guessed);
  // The bunny is 0.15 m across: no body-sized unit fits, the mesh still loads.
  const Mesh bunny = ReadMesh(ReadOptions(), shared / "data/meshes/bunny-35k.off");
  EXPECT_EQ(bunny.mesh.num_vertices(), 34834);
  EXPECT_EQ(bunny.mesh.num_faces(), 69451);
  EXPECT_FALSE(bunny.report.unit_guessed);
  EXPECT_THAT(bunny.report.warnings, ::testing::Contains(::testing::HasSubstr("length unit")));
}

}  // namespace
}  // namespace bespoke
