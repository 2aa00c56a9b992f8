// OBJ reading (groups, corner forms, negative indices), writing, round trips,
// malformed files, and the MakeHuman base mesh from ../shared.
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

// A unit cube: 8 vertices, 6 quads in two groups, every corner form.
const char* kCube =
    "# cube\r\n"
    "mtllib cube.mtl\n"
    "o cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1   # trailing comment\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 -1\nvn 0 0 1\n"
    "g bottom\n"
    "usemtl skin\n"
    "s off\n"
    "f 1/1/1 4/4/1 3/3/1 2/2/1\n"
    "g sides\n"
    "f 1//1 2//1 6//1 5//1\n"
    "f 2/2 3/3 7/3 6/2\n"
    "f -6 -2 -1 -5\n"  // 3 7 8 4
    "f 4 8 5 1\n"
    "g bottom\n"
    "f 5/1/2 6/2/2 7/3/2 8/4/2\n";

TEST(ObjRead, CubeWithGroupsAndEveryCornerForm) {
  TempDir dir;
  WriteBytes(dir / "cube.obj", kCube);
  const Mesh mesh = ReadMesh(FixtureOptions(), dir / "cube.obj");
  EXPECT_EQ(mesh.mesh.num_vertices(), 8);
  EXPECT_EQ(mesh.mesh.num_faces(), 12);  // 6 quads, fanned
  EXPECT_EQ(mesh.report.faces_in_file, 6);
  EXPECT_EQ(mesh.report.format, FileFormat::kObj);
  ASSERT_EQ(mesh.group_names, (std::vector<std::string>{"cube", "bottom", "sides"}));
  ASSERT_EQ(mesh.face_group.size(), 12u);
  EXPECT_EQ(mesh.face_group[0], 1);
  EXPECT_EQ(mesh.face_group[1], 1);
  for (int f = 2; f < 10; ++f) EXPECT_EQ(mesh.face_group[f], 2) << f;
  EXPECT_EQ(mesh.face_group[10], 1);  // "g bottom" again: same group
  // The negative-index quad "-6 -2 -1 -5" is vertices 3 7 8 4 (1-based).
  EXPECT_EQ(mesh.mesh.faces.row(6), Eigen::RowVector3i(2, 6, 7));
  EXPECT_EQ(mesh.mesh.faces.row(7), Eigen::RowVector3i(2, 7, 3));
  EXPECT_EQ(mesh.mesh.vertices.row(6), Eigen::RowVector3d(1, 1, 1));
  EXPECT_NO_THROW(mesh.mesh.CheckIndices());
}

TEST(ObjRead, FacesBeforeAnyGroupGoToDefault) {
  TempDir dir;
  WriteBytes(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ng\nf 3 2 1\n");
  const Mesh mesh = ReadMesh(FixtureOptions(), dir / "tri.obj");
  EXPECT_EQ(mesh.group_names, (std::vector<std::string>{"default"}));
  EXPECT_EQ(mesh.face_group, (std::vector<int>{0, 0}));
}

TEST(ObjRead, VertexColoursAndScanOfVertices) {
  TempDir dir;
  WriteBytes(dir / "c.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
  const Scan scan = ReadScan(FixtureOptions(), dir / "c.obj");
  ASSERT_TRUE(scan.cloud.has_colors());
  EXPECT_EQ(scan.cloud.colors.row(0), (ColorMatrix(1, 3) << 255, 0, 0).finished());
  EXPECT_EQ(scan.cloud.colors(1, 1), 128);
  EXPECT_EQ(scan.report.faces_in_file, 1);
  EXPECT_EQ(scan.report.fields, (std::vector<std::string>{"x", "y", "z", "red", "green", "blue"}));
}

TEST(ObjWrite, RoundTripIsExact) {
  TempDir dir;
  TriangleMesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices << 0.1, 1.0 / 3.0, -2.5e-7, 1e6 / 7.0, 0, 1, -0.0, 5, 6, 3.14159265358979, 2, 1;
  mesh.faces.resize(2, 3);
  mesh.faces << 0, 1, 2, 2, 1, 3;
  WriteOptions options;
  options.comment = "units mm\nframe body";
  WriteMesh(options, mesh, dir / "m.obj");
  const Mesh back = ReadMesh(FixtureOptions(), dir / "m.obj");
  EXPECT_EQ(back.mesh.vertices, mesh.vertices);
  EXPECT_EQ(back.mesh.faces, mesh.faces);
  EXPECT_THAT(testing::ReadBytes(dir / "m.obj"),
              ::testing::StartsWith("# units mm\n# frame body\n"));
}

TEST(ObjRead, MalformedFilesAreInputErrors) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"v 0 0 0\nv 1 0 x\n", "line 2: 'x' is not a number"},
      {"v 0 0\n", "line 1: a vertex needs 3 numbers"},
      {"v 0 0 0 1 2\n", "found 5"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "refers to vertex 4 but 3 vertices"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "needs a vertex index"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "refers to vertex -4"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "at least 3 corners"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", "is not an index"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1a 2 3\n", "needs a vertex index"},
      {"vn 0 0\n", "a normal needs 3 numbers"},
      {"\x01\x02\x03 binary junk\n", "is not an OBJ statement"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "needs a vertex index"},
  };
  int k = 0;
  for (const auto& [text, fragment] : cases) {
    const auto file = dir / ("bad" + std::to_string(k++) + ".obj");
    WriteBytes(file, text);
    ExpectInputError([&] { ReadMesh(FixtureOptions(), file); }, file, fragment);
  }
  // Vertices only: a mesh needs faces.
  WriteBytes(dir / "nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  ExpectInputError([&] { ReadMesh(FixtureOptions(), dir / "nofaces.obj"); }, dir / "nofaces.obj",
                   "has no faces");
  // NaN vertex in a mesh.
  WriteBytes(dir / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  ExpectInputError([&] { ReadMesh(FixtureOptions(), dir / "nan.obj"); }, dir / "nan.obj",
                   "vertex 1 has a NaN/Inf coordinate");
}

TEST(ObjRead, MaxElementsIsEnforced) {
  TempDir dir;
  WriteBytes(dir / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n");
  ReadOptions options = FixtureOptions();
  options.max_elements = 3;
  ExpectInputError([&] { ReadMesh(options, dir / "m.obj"); }, dir / "m.obj", "more than the limit");
}

// The MakeHuman base mesh: 19,158 vertices, 18,486 quads, 172 `g` statements
// naming 139 distinct groups (some, e.g. the eyelash helpers, are repeated);
// the skin group `body` has 13,378 quads. Units are decimetres.
TEST(ObjRead, MakeHumanBaseMesh) {
  BESPOKE_REQUIRE_SHARED(shared);
  const auto file = shared / "data/bodies/makehuman/base.obj";
  ReadOptions options;  // defaults, as the MakeHuman body code uses them
  const Mesh mesh = ReadMesh(options, file);
  EXPECT_EQ(mesh.mesh.num_vertices(), 19158);
  EXPECT_EQ(mesh.report.faces_in_file, 18486);
  EXPECT_EQ(mesh.mesh.num_faces(), 2 * 18486);
  EXPECT_EQ(mesh.group_names.size(), 139u);
  EXPECT_EQ(mesh.report.unit, LengthUnit::kDecimetre);
  EXPECT_TRUE(mesh.report.unit_guessed);
  const auto body = std::find(mesh.group_names.begin(), mesh.group_names.end(), "body");
  ASSERT_NE(body, mesh.group_names.end());
  const int body_index = static_cast<int>(body - mesh.group_names.begin());
  EXPECT_EQ(std::count(mesh.face_group.begin(), mesh.face_group.end(), body_index), 2 * 13378);
  EXPECT_EQ(mesh.mesh.vertices.row(0), Eigen::RowVector3d(-0.3492, 7.3299, 1.4076));
}

}  // namespace
}  // namespace bespoke
