// `bespoke measure` as a user runs it: a separate process on files on disk.
// A virtual scan of a generated body, measured with its true datum points
// as the override file, gives every output; bad files and options give exit
// code 1, name the file and leave no output behind. A mesh export is sampled
// over its faces.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/scan_sim.h"
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

testing::CommandResult MeasureCmd(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' measure " + args, dir.path());
}

std::string Q(const std::filesystem::path& file) { return testing::Quote(file); }

// A scan in mm (scanner frame = rotated body frame) and its true landmarks as an override file.
void WriteScanAndOverrides(const TempDir& dir) {
  ParametricBodyOptions shape;
  shape.torso_segments = 48, shape.arm_segments = 32, shape.ring_spacing_mm = 20;
  shape.girth_ring_segments = 64, shape.max_girth_deficit_mm = 2.0;
  const Body body = GenerateParametricBody(shape);
  ScanSimOptions booth;
  booth.booth.width_px = 120, booth.booth.height_px = 90;
  booth.transform = ScanTransform::kRandom;
  const ScanSimResult scan = SimulateScan(booth, body.mesh);
  WriteScan({}, scan.cloud, dir / "scan.ply");
  nlohmann::json points = nlohmann::json::object();
  for (const auto& [name, p] : body.landmarks)
    points[name] = ToJson(Eigen::Vector3d(scan.scanner_from_body * PositionOf(body.mesh, p)));
  WriteJsonFile(dir / "landmarks.json",
                {{"frame", "scan"}, {"units", "mm"}, {"landmarks", points}});
}

TEST(MeasureCli, EveryOutputFromAVirtualScan) {
  TempDir dir;
  WriteScanAndOverrides(dir);
  const auto run =
      MeasureCmd(dir, Q(dir / "scan.ply") + " --units mm -o " + Q(dir / "m.json") + " --csv " +
                          Q(dir / "m.csv") + " --vit " + Q(dir / "m.vit") + " --freesewing " +
                          Q(dir / "fs.json") + " --render " + Q(dir / "m.png") + " --landmarks " +
                          Q(dir / "landmarks.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("geodesics"), std::string::npos) << "no stage table:\n" << run.out;
  const nlohmann::json doc = ReadJsonFile(dir / "m.json");
  EXPECT_EQ(doc["format"], "bespoke-measurements");
  EXPECT_EQ(doc["units"], "mm");
  EXPECT_EQ(doc["measurements"].size() + doc["skipped"].size(), 50u);
  EXPECT_GE(doc["measurements"].size(), 48u) << doc["skipped"].dump();
  for (const nlohmann::json& m : doc["measurements"])
    if (m["name"] == "stature") {
      EXPECT_NEAR(m["value_mm"].get<double>(), 1660.0, 4.0);
    }  // mm, the body's
  EXPECT_TRUE(doc["settings"].contains("measure"));
  EXPECT_EQ(doc["landmark_details"]["crown"]["flags"][0], "override");
  for (const char* f : {"m.csv", "m.vit", "fs.json", "m.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  std::ifstream vit(dir / "m.vit");
  const std::string text((std::istreambuf_iterator<char>(vit)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<m name=\"bust_circ\""), std::string::npos);
}

// A booth's mesh export: the body as a binary STL in metres (its triangles
// range from slivers beside the refined girth rings to 20 mm quads), measured
// at its true datum points. The mesh is sampled over its faces (the message
// says so, and the cleaned cloud is far larger than the vertex count), and
// every girth lies within its ISO 20685-1 class limit of the exact value.
TEST(MeasureCli, AMeshExportIsSampledOverItsFaces) {
  TempDir dir;
  ParametricBodyOptions shape;
  shape.torso_segments = 48, shape.arm_segments = 32, shape.ring_spacing_mm = 20;
  shape.girth_ring_segments = 64, shape.max_girth_deficit_mm = 2.0;
  const Body body = GenerateParametricBody(shape);
  TriangleMesh metres = body.mesh;
  metres.vertices /= 1000;
  WriteMesh({}, metres, dir / "export.stl");
  nlohmann::json points = nlohmann::json::object();
  for (const auto& [name, p] : body.landmarks) points[name] = ToJson(PositionOf(body.mesh, p));
  WriteJsonFile(dir / "landmarks.json",
                {{"frame", "scan"}, {"units", "mm"}, {"landmarks", points}});
  const auto run = MeasureCmd(dir, Q(dir / "export.stl") + " -o " + Q(dir / "m.json") +
                                       " --landmarks " + Q(dir / "landmarks.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("sampled over its faces"), std::string::npos) << run.err;
  const nlohmann::json doc = ReadJsonFile(dir / "m.json");
  EXPECT_GT(doc["input"]["points_cleaned"].get<double>(), 5.0 * body.mesh.num_vertices());
  int judged = 0;
  for (const nlohmann::json& m : doc["measurements"]) {
    const std::string name = m["name"];
    auto it = body.parameters.find(name + "_analytic_mm");
    if (it == body.parameters.end()) it = body.parameters.find(name + "_right_analytic_mm");
    // A girth over the skin (the neck) is a loop through the ring's points, not the ring.
    if (it == body.parameters.end() || m["method"] == "geodesic") continue;
    const bool large = name != "thigh_girth" && name != "knee_girth" && name != "calf_girth" &&
                       name != "ankle_girth" && name.find("arm") == std::string::npos &&
                       name != "elbow_girth" && name != "wrist_girth";
    const double error = m["value_mm"].get<double>() - it->second;
    std::printf("%-18s mesh export %7.1f, exact %7.1f, error %5.1f mm\n", name.c_str(),
                m["value_mm"].get<double>(), it->second, error);
    EXPECT_LE(std::abs(error), large ? 9.0 : 4.0) << name;
    ++judged;
  }
  EXPECT_GE(judged, 10);
}

TEST(MeasureCli, BadInputExitsOneAndWritesNothing) {
  TempDir dir;
  std::ofstream(dir / "bad.ply", std::ios::binary)
      << "ply\nformat ascii 1.0\nelement vertex 9\nend_header\n";
  auto run = MeasureCmd(
      dir, Q(dir / "bad.ply") + " -o " + Q(dir / "m.json") + " --csv " + Q(dir / "m.csv"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bad.ply"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "m.csv"));
  run = MeasureCmd(dir, Q(dir / "bad.ply") + " -o " + Q(dir / "m.txt"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("m.txt"), std::string::npos) << run.err;
  run = MeasureCmd(dir, Q(dir / "bad.ply") + " -o " + Q(dir / "m.json") + " --landmarks " +
                            Q(dir / "none.json"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("none.json"), std::string::npos) << run.err;
  run = MeasureCmd(dir, Q(dir / "bad.ply") + " -o " + Q(dir / "no_such_dir" / "m.json"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("no_such_dir"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace bespoke
