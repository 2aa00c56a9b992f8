// STL: binary and ascii fixtures with exact vertex merging, round trip,
// truncations and malformed files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "scanners/io/scan_io.h"
#include "tests/support/io_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectInputError;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

template <typename T>
void Put(std::string* out, T value) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  out->append(b, sizeof(T));
}

// Two triangles of a unit square sharing the diagonal (0,0,0)-(1,1,0); the
// second uses -0.0 for a zero (still the same vertex), and a third triangle
// has a corner 1e-7 away from (1,0,0) (a different vertex: no tolerance).
std::string BinaryStl(const std::string& header_start = "made by a test") {
  std::string s = header_start;
  s.resize(80, ' ');
  Put<std::uint32_t>(&s, 3);
  const float tris[3][9] = {{0, 0, 0, 1, 0, 0, 1, 1, 0},
                            {0, -0.0f, 0, 1, 1, 0, 0, 1, 0},
                            {1, 0, 0, 1.0000001f, 0, 0, 1, 1, 0}};
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) Put<float>(&s, 0.0f);  // normal
    for (const float v : t) Put<float>(&s, v);
    Put<std::uint16_t>(&s, 0);
  }
  return s;
}

void ExpectMerged(const Mesh& mesh) {
  ASSERT_EQ(mesh.mesh.num_vertices(), 5);
  EXPECT_EQ(mesh.mesh.faces, (Eigen::MatrixX3i(3, 3) << 0, 1, 2, 0, 2, 3, 1, 4, 2).finished());
  EXPECT_EQ(mesh.report.faces_in_file, 3);
  EXPECT_EQ(mesh.mesh.vertices(4, 0), static_cast<double>(1.0000001f));
}

TEST(StlRead, BinaryMergesEqualCornersExactly) {
  TempDir dir;
  WriteBytes(dir / "b.stl", BinaryStl());
  const Mesh mesh = ReadMesh(FixtureOptions(), dir / "b.stl");
  EXPECT_EQ(mesh.report.encoding, "binary");
  ExpectMerged(mesh);
  // A binary file whose header starts with "solid" is still binary (its size says so).
  WriteBytes(dir / "solid.stl", BinaryStl("solid but binary"));
  ExpectMerged(ReadMesh(FixtureOptions(), dir / "solid.stl"));
}

TEST(StlRead, AsciiMergesEqualCornersExactly) {
  TempDir dir;
  WriteBytes(dir / "a.stl",
             "solid square\n"
             "  facet normal 0 0 1\n    outer loop\n"
             "      vertex 0 0 0\n      vertex 1 0 0\n      vertex 1 1 0\n"
             "    endloop\n  endfacet\n"
             "  facet normal 0 0 1\n    outer loop\n"
             "      vertex 0 -0 0\n      vertex 1 1 0\n      vertex 0 1 0\n"
             "    endloop\n  endfacet\n"
             "endsolid square\n"
             "solid second\n"
             "  facet normal 0 0 0\n    outer loop\n"
             "      vertex 1 0 0\n      vertex 1.00000011920928955078125 0 0\n      vertex 1 1 0\n"
             "    endloop\n  endfacet\n"
             "endsolid\n");
  const Mesh mesh = ReadMesh(FixtureOptions(), dir / "a.stl");
  EXPECT_EQ(mesh.report.encoding, "ascii");
  ExpectMerged(mesh);
}

TEST(StlWrite, RoundTripToFloatPrecision) {
  TempDir dir;
  TriangleMesh mesh;
  mesh.vertices = Eigen::MatrixX3d::Random(6, 3) * 100.0;
  mesh.faces = (Eigen::MatrixX3i(4, 3) << 0, 1, 2, 2, 1, 3, 3, 4, 2, 4, 5, 0).finished();
  WriteOptions options;
  options.comment = "solid-looking comment";
  WriteMesh(options, mesh, dir / "m.stl");
  const Mesh back = ReadMesh(FixtureOptions(), dir / "m.stl");
  EXPECT_EQ(back.mesh.vertices, mesh.vertices.cast<float>().cast<double>());
  EXPECT_EQ(back.mesh.faces, mesh.faces);  // corners first seen in vertex order
}

TEST(StlMalformed, EveryTruncationOfABinaryFile) {
  const std::string full = BinaryStl();
  const std::filesystem::path file = "t.stl";
  for (std::size_t n = 0; n < full.size(); ++n) {
    SCOPED_TRACE("truncated at byte " + std::to_string(n));
    ExpectInputError([&] { ReadMeshFromBytes(FixtureOptions(), file, full.substr(0, n)); }, file);
  }
}

TEST(StlMalformed, Corpus) {
  TempDir dir;
  std::string huge = BinaryStl();
  const std::uint32_t count = 4000000000u;
  std::memcpy(&huge[80], &count, 4);
  std::string many = BinaryStl();
  const std::uint32_t forty_million = 40000000u;
  std::memcpy(&many[80], &forty_million, 4);
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {huge, "more than the limit"},
      {many, "declares 40000000 triangles"},
      {"solid x\n" + facet + "vertex 0 1 0\nendloop\nendfacet\n", "'endsolid' missing"},
      {"solid x\n" + facet + "endloop\nendfacet\nendsolid\n", "expected 'vertex'"},
      {"solid x\n" + facet + "vertex 0 1\nendloop\nendfacet\nendsolid\n", "needs 3 numbers"},
      {"solid x\n" + facet + "vertex 0 1 z\nendloop\nendfacet\nendsolid\n", "'z' is not a number"},
      {"solid x\nfacet normal 0 0 1\nvertex 0 0 0\n", "expected 'outer loop'"},
      {"solid x\n" + facet + "vertex 0 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n",
       "expected 'endloop'"},
      {"solid x\nendsolid x\n", "has no faces"},
  };
  int k = 0;
  for (const auto& [bytes, fragment] : cases) {
    SCOPED_TRACE(fragment);
    const auto file = dir / ("bad" + std::to_string(k++) + ".stl");
    WriteBytes(file, bytes);
    ExpectInputError([&] { ReadMesh(FixtureOptions(), file); }, file, fragment);
  }
}

}  // namespace
}  // namespace bespoke
