// PLY: known fixtures (every scalar type and alias, both byte orders),
// round trips of every encoding, and the malformed-file corpus.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <limits>

#include "scanners/io/scan_io.h"
#include "tests/support/io_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectInputError;
using testing::ExpectScanRejected;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

// Appends `value` as raw bytes, byte-swapped for big endian (written here
// independently of the library's writer).
template <typename T>
void Put(std::string* out, T value, bool big_endian) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big_endian) std::reverse(b, b + sizeof(T));
  out->append(b, sizeof(T));
}

// Two vertices with one property of every type (names and aliases mixed), an
// unknown element with a list between vertex and face, and a quad.
std::string EveryTypePly(bool big_endian) {
  std::string s =
      std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\ncomment made in a test\nobj_info nothing\n"
      "element vertex 4\n"
      "property float32 x\nproperty double y\nproperty int16 z\n"
      "property char c8\nproperty uint8 red\nproperty uchar green\nproperty uchar blue\n"
      "property ushort u16\nproperty int i32\nproperty uint32 u32\n"
      "property list uchar float junk_list\n"
      "element material 2\nproperty list int int8 ids\nproperty float64 w\n"
      "element face 1\nproperty list uint16 uint vertex_indices\n"
      "end_header\n";
  for (int i = 0; i < 4; ++i) {
    Put<float>(&s, 0.5f + i, big_endian);
    Put<double>(&s, -1.0 / 3.0 * i, big_endian);
    Put<std::int16_t>(&s, static_cast<std::int16_t>(-1000 * i), big_endian);
    Put<std::int8_t>(&s, static_cast<std::int8_t>(-100 + i), big_endian);
    Put<std::uint8_t>(&s, static_cast<std::uint8_t>(200 + i), big_endian);
    Put<std::uint8_t>(&s, 7, big_endian);
    Put<std::uint8_t>(&s, 255, big_endian);
    Put<std::uint16_t>(&s, static_cast<std::uint16_t>(65000 + i), big_endian);
    Put<std::int32_t>(&s, -2000000000 + i, big_endian);
    Put<std::uint32_t>(&s, 4000000000u + i, big_endian);
    Put<std::uint8_t>(&s, static_cast<std::uint8_t>(i), big_endian);  // list of i floats
    for (int k = 0; k < i; ++k) Put<float>(&s, 9.0f, big_endian);
  }
  for (int m = 0; m < 2; ++m) {
    Put<std::int32_t>(&s, 3, big_endian);
    for (int k = 0; k < 3; ++k) Put<std::int8_t>(&s, static_cast<std::int8_t>(k), big_endian);
    Put<double>(&s, 1.5, big_endian);
  }
  Put<std::uint16_t>(&s, 4, big_endian);
  for (std::uint32_t v : {0u, 1u, 2u, 3u}) Put<std::uint32_t>(&s, v, big_endian);
  return s;
}

TEST(PlyRead, EveryScalarTypeInBothByteOrders) {
  TempDir dir;
  for (const bool big : {false, true}) {
    const auto file = dir / (big ? "be.ply" : "le.ply");
    WriteBytes(file, EveryTypePly(big));
    const Mesh mesh = ReadMesh(FixtureOptions(), file);
    EXPECT_EQ(mesh.report.encoding, big ? "binary_big_endian" : "binary_little_endian");
    EXPECT_EQ(mesh.mesh.faces, (Eigen::MatrixX3i(2, 3) << 0, 1, 2, 0, 2, 3).finished());
    EXPECT_EQ(mesh.report.faces_in_file, 1);
    const Scan scan = ReadScan(FixtureOptions(), file);
    const PointCloud& c = scan.cloud;
    ASSERT_EQ(c.size(), 4);
    ASSERT_TRUE(c.has_colors());
    EXPECT_FALSE(c.has_normals());
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(c.points(i, 0), 0.5 + i);
      EXPECT_EQ(c.points(i, 1), -1.0 / 3.0 * i);
      EXPECT_EQ(c.points(i, 2), -1000.0 * i);
      EXPECT_EQ(c.scalars.at("c8")[i], -100 + i);
      EXPECT_EQ(c.colors(i, 0), 200 + i);
      EXPECT_EQ(c.colors(i, 1), 7);
      EXPECT_EQ(c.colors(i, 2), 255);
      EXPECT_EQ(c.scalars.at("u16")[i], 65000 + i);
      EXPECT_EQ(c.scalars.at("i32")[i], -2000000000.0 + i);
      EXPECT_EQ(c.scalars.at("u32")[i], 4000000000.0 + i);
    }
    EXPECT_EQ(c.scalars.size(), 4u);  // the vertex list property is skipped
    EXPECT_EQ(scan.report.fields.size(), 11u);
  }
}

TEST(PlyRead, AsciiWithNormalsFloatColoursAndNonFinitePoints) {
  TempDir dir;
  const auto file = dir / "a.ply";
  WriteBytes(file,
             "ply\r\nformat ascii 1.0\r\nelement vertex 4\r\n"
             "property float x\nproperty float y\nproperty float z\n"
             "property float nx\nproperty float ny\nproperty float nz\n"
             "property float red\nproperty float green\nproperty float blue\n"
             "property float confidence\n"
             "element face 0\nproperty list uchar int vertex_index\nend_header\n"
             "1 2 3 0 0 1 1 0.5 0 0.25\n"
             "\n"
             "+4 -5e0 6.5 0 1 0 0 0 1 1e-3\r\n"
             "nan 0 0 0 1 0 0 0 1 2\n"
             "7 8 inf 1 0 0 0 0 0 3\n");
  const Scan scan = ReadScan(FixtureOptions(), file);
  EXPECT_EQ(scan.report.points_in_file, 4);
  EXPECT_EQ(scan.report.non_finite_dropped, 2);
  ASSERT_EQ(scan.cloud.size(), 2);
  EXPECT_EQ(scan.cloud.points.row(1), Eigen::RowVector3d(4, -5, 6.5));
  EXPECT_EQ(scan.cloud.normals.row(0), Eigen::RowVector3d(0, 0, 1));
  EXPECT_EQ(scan.cloud.colors(0, 1), 128);  // 0.5 * 255 rounded
  EXPECT_EQ(scan.cloud.scalars.at("confidence")[1], static_cast<double>(1e-3f));  // a float
  EXPECT_EQ(scan.report.encoding, "ascii");
}

TEST(PlyRead, UnitsAreGuessedAndConverted) {
  TempDir dir;
  PointCloud cloud;
  cloud.points.resize(3, 3);
  cloud.points << 0, 0, 0, 0.3, 0.2, 1.75, -0.1, 0, 0.9;  // a 1.75 m "person"
  WriteScan({}, cloud, dir / "m.ply");
  ReadOptions options;
  options.min_finite_points = 3;
  const Scan scan = ReadScan(options, dir / "m.ply");
  EXPECT_EQ(scan.report.unit, LengthUnit::kMetre);
  EXPECT_TRUE(scan.report.unit_guessed);
  EXPECT_NEAR(scan.cloud.points(1, 2), 1750.0, 1e-9);
  EXPECT_NEAR(scan.report.bounds_file_units.max().z(), 1.75, 0.0);
  options.units = LengthUnit::kCentimetre;
  const Scan given = ReadScan(options, dir / "m.ply");
  EXPECT_FALSE(given.report.unit_guessed);
  EXPECT_NEAR(given.cloud.points(1, 2), 17.5, 1e-12);
  // 0.003 file units tall is no body in any unit: the error suggests --units.
  cloud.points *= 0.001;
  WriteScan({}, cloud, dir / "tiny.ply");
  options.units.reset();
  ExpectInputError([&] { ReadScan(options, dir / "tiny.ply"); }, dir / "tiny.ply", "--units");
}

class PlyRoundTrip : public ::testing::TestWithParam<PlyEncoding> {};

TEST_P(PlyRoundTrip, CloudAttributesSurviveExactly) {
  TempDir dir;
  const PointCloud cloud = testing::RichCloud(50);
  WriteOptions options;
  options.ply_encoding = GetParam();
  options.comment = "units mm";
  WriteScan(options, cloud, dir / "c.ply");
  const Scan back = ReadScan(FixtureOptions(), dir / "c.ply");
  // Positions and scalars are doubles: exact in binary, and in ascii too
  // (shortest round-trip text). Normals are floats: exact to float.
  EXPECT_EQ(back.cloud.points, cloud.points);
  EXPECT_EQ(back.cloud.normals, cloud.normals.cast<float>().cast<double>());
  EXPECT_EQ(back.cloud.colors, cloud.colors);
  ASSERT_EQ(back.cloud.scalars.size(), 2u);
  EXPECT_EQ(back.cloud.scalars.at("intensity"), cloud.scalars.at("intensity"));
  EXPECT_EQ(back.cloud.scalars.at("curvature"), cloud.scalars.at("curvature"));
}

TEST_P(PlyRoundTrip, MeshSurvivesExactly) {
  TempDir dir;
  TriangleMesh mesh;
  mesh.vertices = Eigen::MatrixX3d::Random(30, 3) * 1000.0;
  mesh.faces.resize(20, 3);
  for (int f = 0; f < 20; ++f) mesh.faces.row(f) << f, f + 1, 29 - f;
  WriteOptions options;
  options.ply_encoding = GetParam();
  WriteMesh(options, mesh, dir / "m.ply");
  const Mesh back = ReadMesh(FixtureOptions(), dir / "m.ply");
  EXPECT_EQ(back.mesh.vertices, mesh.vertices);
  EXPECT_EQ(back.mesh.faces, mesh.faces);
}

INSTANTIATE_TEST_SUITE_P(Encodings, PlyRoundTrip,
                         ::testing::Values(PlyEncoding::kAscii, PlyEncoding::kBinaryLittleEndian,
                                           PlyEncoding::kBinaryBigEndian));

// Every strict prefix of a valid binary PLY is rejected with InputError.
TEST(PlyMalformed, EveryTruncationOfABinaryFile) {
  for (const bool big : {false, true}) {
    const std::string full = EveryTypePly(big);
    const std::filesystem::path file = "t.ply";
    for (std::size_t n = 0; n < full.size(); ++n) {
      SCOPED_TRACE("truncated at byte " + std::to_string(n));
      const std::string prefix = full.substr(0, n);
      ExpectInputError([&] { ReadScanFromBytes(FixtureOptions(), file, prefix); }, file);
      ExpectInputError([&] { ReadMeshFromBytes(FixtureOptions(), file, prefix); }, file);
    }
  }
}

// Truncated ascii files may still parse when the cut falls inside the last
// number; they must never crash or throw anything but InputError.
TEST(PlyMalformed, EveryTruncationOfAnAsciiFile) {
  TempDir dir;
  WriteOptions options;
  options.ply_encoding = PlyEncoding::kAscii;
  TriangleMesh mesh;
  mesh.vertices = Eigen::MatrixX3d::Random(5, 3);
  mesh.faces = (Eigen::MatrixX3i(2, 3) << 0, 1, 2, 2, 3, 4).finished();
  WriteMesh(options, mesh, dir / "full.ply");
  const std::string full = testing::ReadBytes(dir / "full.ply");
  int rejected = 0;
  for (std::size_t n = 0; n < full.size(); ++n) {
    try {
      const Mesh m = ReadMeshFromBytes(FixtureOptions(), "t.ply", full.substr(0, n));
      EXPECT_EQ(m.mesh.num_faces(), 2);
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("t.ply: "));
      ++rejected;
    }
  }
  EXPECT_GT(rejected, static_cast<int>(full.size()) - 10);
}

std::string Header(const std::string& body) { return "ply\nformat ascii 1.0\n" + body; }
const char* kXyz = "property float x\nproperty float y\nproperty float z\n";

TEST(PlyMalformed, HeaderAndDataCorpus) {
  TempDir dir;
  const std::string le = "ply\nformat binary_little_endian 1.0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"ply", "no 'end_header'"},
      {"plx\nformat ascii 1.0\nend_header\n", "first line must be 'ply'"},
      {"ply\nend_header\n", "no 'format' line"},
      {"ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n", "a second 'format'"},
      {"ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown PLY format"},
      {"ply\nformat ascii 2.0\nend_header\n", "unsupported PLY version"},
      {Header("element vertex 5000000000\n") + kXyz + "end_header\n", "more than the limit"},
      {Header("element vertex -3\n") + kXyz + "end_header\n", "is negative"},
      {Header("element vertex 1e3\n") + kXyz + "end_header\n", "is not an integer"},
      {Header("element vertex 1\nelement vertex 1\n") + "end_header\n", "declared twice"},
      {Header("element vertex 1\nproperty float x\nproperty float x\nend_header\n"),
       "declared twice"},
      {le + "element vertex 40000000\n" + kXyz + "end_header\n\x01\x02", "only 2 bytes"},
      {Header("element vertex 40000000\n") + kXyz + "end_header\n1 2 3\n", "only 6 bytes"},
      {Header("property float x\n"), "property before any element"},
      {Header("element vertex 1\nproperty float128 x\nend_header\n0\n"), "unknown PLY property"},
      {Header("element vertex 1\nproperty list float int x\nend_header\n"), "not an integer type"},
      {Header("element vertex 1\nproperty list uchar int\nend_header\n"), "expected 'property"},
      {Header("element vertex 1\nbogus\nend_header\n"), "unknown PLY header keyword"},
      {Header("element face 0\nend_header\n"), "no 'vertex' element"},
      {Header("element vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n"),
       "needs scalar properties x, y and z"},
      {Header("element vertex 2\n") + kXyz + "end_header\n1 2 3\n4 5        \n",
       "line 9: too few values"},
      {Header("element vertex 2\n") + kXyz + "end_header\n1 2 3\n4 5 6 7\n",
       "line 9: expected 3 values"},
      {Header("element vertex 2\n") + kXyz + "end_header\n1 2 3\n4 five 6\n",
       "line 9: 'five' is not a number"},
      {Header("element vertex 2\n") + kXyz + "end_header\n1 2 3\n4 5 6\n7 8 9\n",
       "data after the last element"},
      {Header("element vertex 3\n") + kXyz + "end_header\n1 2 3\n4 5 6\n", "truncated"},
      {Header("element vertex 3\n") + kXyz +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       "refers to vertex 3 but the file has 3 vertices"},
      {Header("element vertex 3\n") + kXyz +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
       "needs a count >= 0"},
      {Header("element vertex 3\n") + kXyz +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
       "declares 4 items but only 3 follow"},
      {Header("element vertex 3\n") + kXyz +
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
       "face 0 has 2 vertices"},
      {Header("element vertex 3\n") + kXyz +
           "element face 1\nproperty list uchar float vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "must have an integer type"},
      {Header("element vertex 1\n") + kXyz + "element edge 2\nend_header\n0 0 0\n",
       "no properties"},
  };
  int k = 0;
  for (const auto& [bytes, fragment] : cases) {
    SCOPED_TRACE(fragment);
    ExpectScanRejected(dir / ("bad" + std::to_string(k++) + ".ply"), bytes, fragment);
  }
}

TEST(PlyMalformed, BinaryListCountsThatDoNotFit) {
  TempDir dir;
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + std::string(kXyz) +
                  "element face 1\nproperty list int int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) Put<float>(&s, 1.0f * i, false);
  std::string negative = s, huge = s;
  Put<std::int32_t>(&negative, -1, false);
  Put<std::int32_t>(&huge, 2000000000, false);
  for (int i = 0; i < 3; ++i) {
    Put<std::int32_t>(&negative, i, false);
    Put<std::int32_t>(&huge, i, false);
  }
  ExpectScanRejected(dir / "neg.ply", negative, "has -1 items");
  ExpectScanRejected(dir / "huge.ply", huge, "has 2000000000 items, which do not fit");
}

TEST(PlyMalformed, TooFewFinitePointsAndNoPoints) {
  TempDir dir;
  const std::string nan_only =
      Header("element vertex 2\n") + kXyz + "end_header\nnan nan nan\ninf 0 0\n";
  ReadOptions options = FixtureOptions();
  options.min_finite_points = 1;
  ExpectScanRejected(dir / "nan.ply", nan_only, "only 0 finite points (2 NaN/Inf", options);
  ExpectScanRejected(dir / "zero.ply", Header("element vertex 0\n") + kXyz + "end_header\n",
                     "only 0 finite points", options);
  ReadOptions defaults;  // a body needs 1000 points
  ExpectScanRejected(dir / "few.ply", Header("element vertex 1\n") + kXyz + "end_header\n1 2 3\n",
                     "at least 1000", defaults);
}

// 200,000 declared elements and properties: the header checks are linear
// (a quadratic duplicate check would take minutes and hit the test timeout).
TEST(PlyMalformed, HugeHeadersParseInLinearTime) {
  std::string many_elements = "ply\nformat ascii 1.0\nelement vertex 1\n" + std::string(kXyz);
  std::string many_properties = "ply\nformat ascii 1.0\nelement vertex 0\n" + std::string(kXyz);
  for (int i = 0; i < 200000; ++i) {
    many_elements += "element e" + std::to_string(i) + " 0\n";
    many_properties += "property uchar p" + std::to_string(i) + "\n";
  }
  many_elements += "end_header\n1 2 3\n";
  many_properties += "end_header\n";
  EXPECT_EQ(ReadScanFromBytes(FixtureOptions(), "e.ply", many_elements).cloud.size(), 1);
  EXPECT_EQ(ReadScanFromBytes(FixtureOptions(), "p.ply", many_properties).report.fields.size(),
            200003u);
}

TEST(ScanIo, FileSystemProblemsAreInputErrors) {
  TempDir dir;
  ExpectScanRejected(dir / "empty.ply", "", "file is empty");
  ExpectInputError([&] { ReadScan(FixtureOptions(), dir / "missing.ply"); }, dir / "missing.ply",
                   "not found");
  std::filesystem::create_directory(dir / "folder.ply");
  ExpectInputError([&] { ReadScan(FixtureOptions(), dir / "folder.ply"); }, dir / "folder.ply",
                   "is a folder");
  ExpectScanRejected(dir / "what.bin", "\x7f\x45\x4c\x46 not a scan", "unknown file format");
}

TEST(ScanIo, UnreadableFileIsAnInputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: file permissions do not apply";
  TempDir dir;
  const auto file = dir / "locked.ply";
  WriteBytes(file, Header("element vertex 1\n") + kXyz + "end_header\n1 2 3\n");
  std::filesystem::permissions(file, std::filesystem::perms::none);
  ExpectInputError([&] { ReadScan(FixtureOptions(), file); }, file, "Permission denied");
}

TEST(ScanIo, OptionsAreChecked) {
  ReadOptions options;
  options.max_elements = 0;
  EXPECT_THROW(options.Check(), InputError);
  options.max_elements = std::int64_t{1} << 40;
  EXPECT_THROW(options.Check(), InputError);
  options = ReadOptions();
  options.min_finite_points = -1;
  EXPECT_THROW(options.Check(), InputError);
  EXPECT_NO_THROW(ReadOptions().Check());
}

}  // namespace
}  // namespace bespoke
