// `bespoke scan-sim` as a user runs it: a separate process on files on disk.
// A valid body gives exit 0 and every promised file; bad input gives exit 1
// with the problem (and the file) named on stderr and no scan written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "oracle/body/parametric_body.h"
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

ProcessResult ScanSim(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' -q scan-sim " + args,
                             dir.path());
}

std::string Q(const std::filesystem::path& p) { return testing::Quote(p); }

// A small body (coarse mesh) and a truth file with its landmarks.
void WriteBody(const TempDir& dir) {
  ParametricBodyOptions o;
  o.torso_segments = 48;
  o.arm_segments = 32;
  o.ring_spacing_mm = 30;
  o.girth_ring_segments = 64;
  o.max_girth_deficit_mm = 2;
  const Body body = GenerateParametricBody(o);
  WriteMesh(WriteOptions(), body.mesh, dir / "body.obj");
  nlohmann::json truth = {{"format", "bespoke-measurements"},
                          {"version", 1},
                          {"units", "mm"},
                          {"frame", "body"},
                          {"measurements", nlohmann::json::array()}};
  for (const auto& [name, point] : body.landmarks)
    truth["landmarks"][name] = ToJson(PositionOf(body.mesh, point));
  WriteJsonFile(dir / "truth.json", truth);
}

TEST(ScanSimCli, WritesTheScanReportTruthAndPreview) {
  TempDir dir;
  WriteBody(dir);
  const ProcessResult r = ScanSim(dir, Q(dir / "body.obj") + " -o " + Q(dir / "scan.ply") +
                                           " --truth " + Q(dir / "truth.json") +
                                           " --resolution 40x30 --pcd --labels --transform y-up" +
                                           " --preview " + Q(dir / "scan.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"scan.ply", "scan.pcd", "scan.scan.json", "scan.truth.json", "scan.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  const Scan scan = ReadScan(ReadOptions(), dir / "scan.ply");
  EXPECT_EQ(scan.report.unit, LengthUnit::kMetre);  // guessed from the size: written in metres
  EXPECT_TRUE(scan.cloud.has_normals());
  EXPECT_EQ(scan.cloud.scalars.count("source"), 1u);
  // y-up: the scan's height is along y.
  const Eigen::Vector3d extent =
      scan.cloud.points.colwise().maxCoeff() - scan.cloud.points.colwise().minCoeff();
  EXPECT_GT(extent.y(), 1500);
  const nlohmann::json truth = ReadJsonFile(dir / "scan.truth.json");
  EXPECT_EQ(truth["frame"], "scanner");
  EXPECT_GT(Vector3FromJson(truth["landmarks"]["crown"], "crown").y(), 1600);
  EXPECT_EQ(ReadJsonFile(dir / "scan.scan.json")["settings"]["transform"], "y-up");
}

TEST(ScanSimCli, BadInputExitsOneAndWritesNothing) {
  TempDir dir;
  ProcessResult r = ScanSim(dir, Q(dir / "missing.obj") + " -o " + Q(dir / "scan.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.obj"), std::string::npos) << r.err;
  WriteBody(dir);
  r = ScanSim(dir, Q(dir / "body.obj") + " -o " + Q(dir / "scan.ply") + " --sensors six");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--sensors"), std::string::npos) << r.err;
  r = ScanSim(dir, Q(dir / "body.obj") + " -o " + Q(dir / "scan.ply") + " --truth-out " +
                       Q(dir / "t.json"));
  EXPECT_EQ(r.exit_code, 1);
  r = ScanSim(dir, Q(dir / "body.obj") + " -o " + Q(dir / "scan.xyz"));
  EXPECT_EQ(r.exit_code, 1);
  std::ofstream(dir / "bad.json") << "{ not json";
  r = ScanSim(dir, Q(dir / "body.obj") + " -o " + Q(dir / "scan.ply") + " --truth " +
                       Q(dir / "bad.json") + " --resolution 20x15");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "scan.ply"));
}

}  // namespace
}  // namespace bespoke
