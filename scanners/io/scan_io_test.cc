// The front door: format detection by content before extension, writer
// dispatch, atomic writes, and reading clouds from mesh files.
#include "scanners/io/scan_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/io_test_util.h"
#include "tests/support/malformed_corpus.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectInputError;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

TEST(ScanIoDetect, ContentWinsOverTheExtension) {
  TempDir dir;
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n";
  WriteBytes(dir / "really_ply.txt", ply);
  EXPECT_EQ(ReadScan(FixtureOptions(), dir / "really_ply.txt").report.format, FileFormat::kPly);
  WriteBytes(dir / "pcd.xyz",
             "# comment\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
             "WIDTH 1\nDATA ascii\n1 2 3\n");
  EXPECT_EQ(ReadScan(FixtureOptions(), dir / "pcd.xyz").report.format, FileFormat::kPcd);
  WriteBytes(dir / "off.dat", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(ReadMesh(FixtureOptions(), dir / "off.dat").report.format, FileFormat::kOff);
  WriteBytes(dir / "obj.dat", "# exported\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(ReadMesh(FixtureOptions(), dir / "obj.dat").report.format, FileFormat::kObj);
  WriteBytes(dir / "points.dat", "1 2 3\n4 5 6\n");
  EXPECT_EQ(ReadScan(FixtureOptions(), dir / "points.dat").report.format, FileFormat::kXyz);
  // An extension alone sends the file to that reader, which explains itself.
  WriteBytes(dir / "fake.ply", "hello\n");
  ExpectInputError([&] { ReadScan(FixtureOptions(), dir / "fake.ply"); }, dir / "fake.ply",
                   "first line must be 'ply'");
}

TEST(ScanIoRead, ScansOfMeshFilesAreTheirVerticesAndCountFaces) {
  TempDir dir;
  WriteBytes(dir / "m.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n3 0 1 2\n3 1 3 2\n");
  const Scan scan = ReadScan(FixtureOptions(), dir / "m.off");
  EXPECT_EQ(scan.cloud.size(), 4);
  EXPECT_EQ(scan.report.faces_in_file, 2);
  EXPECT_EQ(scan.report.bounds_file_units.max(), Eigen::Vector3d(1, 1, 1));
}

// A raw scan in metres: a 1.75 m column of points plus 1 % outliers up to
// 4 m away (flying pixels, clutter). The full box (4.7 m) is no body's size;
// the central 98 % of the points is, so the unit is guessed as metres. Far
// more outliers than that leave the unit undecided, an InputError.
TEST(ScanIoRead, UnitGuessIgnoresAFewOutliers) {
  TempDir dir;
  std::string xyz;
  for (int i = 0; i < 990; ++i) {
    xyz += "0.1 0.05 " + std::to_string(1.75 * i / 989.0) + "\n";
  }
  for (int i = 0; i < 10; ++i) xyz += "3.5 -1.2 " + std::to_string(0.4 * i) + "\n";
  WriteBytes(dir / "metres.xyz", xyz);
  ReadOptions options = FixtureOptions();
  options.units.reset();  // guess
  const Scan scan = ReadScan(options, dir / "metres.xyz");
  EXPECT_EQ(scan.report.unit, LengthUnit::kMetre);
  EXPECT_TRUE(scan.report.unit_guessed);
  EXPECT_NEAR(scan.cloud.points(989, 2), 1750.0, 1e-6);  // the body's top, in mm
  for (int i = 0; i < 100; ++i) xyz += "40 -12 " + std::to_string(0.4 * i) + "\n";
  WriteBytes(dir / "cluttered.xyz", xyz);
  ExpectInputError([&] { ReadScan(options, dir / "cluttered.xyz"); }, dir / "cluttered.xyz",
                   "cannot tell the length unit");
}

TEST(ScanIoRead, PointFormatsAreNotMeshes) {
  TempDir dir;
  WriteBytes(dir / "p.xyz", "1 2 3\n4 5 6\n7 8 9\n");
  ExpectInputError([&] { ReadMesh(FixtureOptions(), dir / "p.xyz"); }, dir / "p.xyz",
                   "is a point cloud (XYZ)");
}

TEST(ScanIoWrite, UnknownExtensionsAndMissingFolders) {
  TempDir dir;
  PointCloud cloud;
  cloud.points = Eigen::MatrixX3d::Ones(2, 3);
  EXPECT_THROW(WriteScan({}, cloud, dir / "c.obj"), InputError);
  EXPECT_THROW(WriteScan({}, cloud, dir / "no_folder" / "c.ply"), InputError);
  TriangleMesh mesh;
  mesh.vertices = cloud.points;
  mesh.faces = (Eigen::MatrixX3i(1, 3) << 0, 1, 2).finished();  // index 2 out of range
  EXPECT_THROW(WriteMesh({}, mesh, dir / "m.ply"), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "m.ply"));
  mesh.faces(0, 2) = 1;
  EXPECT_THROW(WriteMesh({}, mesh, dir / "m.xyz"), InputError);
}

TEST(ScanIoWrite, OverwritesAtomically) {
  TempDir dir;
  PointCloud cloud = testing::RichCloud(5);
  WriteScan({}, cloud, dir / "c.ply");
  cloud.points *= 2.0;
  WriteScan({}, cloud, dir / "c.ply");
  EXPECT_EQ(ReadScan(FixtureOptions(), dir / "c.ply").cloud.points, cloud.points);
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    ++files;
  }
  EXPECT_EQ(files, 1);  // no temporary files left behind
}

// The shared malformed corpus (also run through `bespoke info` by
// pipeline/cli/cmd_info_test.cc), read with default options.
TEST(ScanIoRead, MalformedCorpusIsRejected) {
  TempDir dir;
  const auto corpus = testing::MalformedCorpus();
  EXPECT_GE(corpus.size(), 25u);
  for (const auto& bad : corpus) {
    SCOPED_TRACE(bad.name);
    testing::ExpectScanRejected(dir / bad.name, bad.bytes, bad.fragment, ReadOptions());
  }
}

}  // namespace
}  // namespace bespoke
