// `bespoke clean` as a user runs it: a separate process on files on disk.
// A synthetic scan written in metres in a random pose comes out in the body
// frame in mm with a report; bad files and options give exit code 1 and
// leave no output behind.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "oracle/scene/synthetic_scene.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using testing::TempDir;

using ProcessResult = testing::CommandResult;

ProcessResult Clean(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' clean " + args, dir.path());
}

std::string Q(const std::filesystem::path& file) { return testing::Quote(file); }

TEST(CleanCli, ScanInMetresComesOutInTheBodyFrame) {
  TempDir dir;
  testing::SyntheticSceneOptions options;
  options.spacing_mm = 6.0;
  options.floor_half_size_mm = 500.0;  // small enough for the unit to be guessed
  options.second_object = false;
  options.scanner_from_body = testing::RandomRigid(11, 2000.0);
  options.mm_per_unit = 1000.0;
  const testing::SyntheticScene scene = testing::MakeSyntheticScene(options);
  WriteScan(WriteOptions{}, scene.cloud, dir / "scan.ply");

  const ProcessResult run = Clean(dir, Q(dir / "scan.ply") + " -o " + Q(dir / "out.ply") +
                                           " --report " + Q(dir / "report.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("largest_cluster"), std::string::npos) << "no stage table:\n" << run.out;

  ReadOptions read;
  read.units = LengthUnit::kMillimetre;
  const Scan out = ReadScan(read, dir / "out.ply");
  ASSERT_TRUE(out.cloud.has_normals());
  EXPECT_NEAR(out.cloud.points.col(2).maxCoeff(), scene.height_mm, 6.0);  // mm, body frame
  EXPECT_GT(out.cloud.points.col(2).minCoeff(), -3.0);

  const nlohmann::json report = ReadJsonFile(dir / "report.json");
  EXPECT_EQ(report["format"], "bespoke-clean-report");
  EXPECT_EQ(report["file"]["file_unit"], "m");
  EXPECT_EQ(report["file"]["unit_guessed"], true);
  EXPECT_EQ(report["settings"]["voxel_grid"]["leaf_mm"], 4.0);
  EXPECT_EQ(report["result"]["stages"].size(), 9u);
  EXPECT_EQ(report["result"]["points_out"], out.cloud.size());
  const Eigen::Affine3d body_from_scanner =
      AffineFromJson(report["result"]["body_from_scanner"], "body_from_scanner");
  const Eigen::Isometry3d truth = scene.scanner_from_body.inverse();
  EXPECT_LT(testing::AngleDeg(body_from_scanner.linear().row(2), truth.linear().row(2)), 1.0);
  EXPECT_LT(testing::AngleDeg(body_from_scanner.linear().row(1), truth.linear().row(1)), 2.0);
  EXPECT_LT((body_from_scanner * scene.scanner_from_body.translation()).norm(), 8.0);  // mm
}

TEST(CleanCli, MalformedScanExitsOneAndWritesNothing) {
  TempDir dir;
  std::ofstream(dir / "bad.ply", std::ios::binary)
      << "ply\nformat binary_little_endian 1.0\nelement vertex 500000000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n0123";
  const ProcessResult run = Clean(
      dir, Q(dir / "bad.ply") + " -o " + Q(dir / "out.ply") + " --report " + Q(dir / "r.json"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bad.ply"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.ply"));
  EXPECT_FALSE(std::filesystem::exists(dir / "r.json"));
}

TEST(CleanCli, TooLittleToBeABodyExitsOne) {
  TempDir dir;
  PointCloud tiny;
  tiny.points = Eigen::MatrixX3d::Random(2000, 3) * 5.0;  // a 10 mm cube
  WriteScan(WriteOptions{}, tiny, dir / "tiny.ply");
  const ProcessResult run =
      Clean(dir, Q(dir / "tiny.ply") + " --units mm -o " + Q(dir / "out.ply"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.ply"));
}

TEST(CleanCli, BadOptionsExitOne) {
  TempDir dir;
  PointCloud tiny;
  tiny.points = Eigen::MatrixX3d::Random(2000, 3) * 800.0;
  WriteScan(WriteOptions{}, tiny, dir / "scan.ply");
  for (const std::string& args :
       {" -o " + Q(dir / "out.ply") + " --voxel-mm 0", " -o " + Q(dir / "out.txt"),
        " -o " + Q(dir / "out.ply") + " --units furlongs",
        " -o " + Q(dir / "out.ply") + " --report " + Q(dir / "r.txt"),
        " -o " + Q(dir / "no_such_folder" / "out.ply")}) {
    const ProcessResult run = Clean(dir, Q(dir / "scan.ply") + args);
    EXPECT_EQ(run.exit_code, 1) << args << "\n" << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.ply")) << args;
  }
}

}  // namespace
}  // namespace bespoke
