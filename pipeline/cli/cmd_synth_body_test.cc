// `bespoke synth-body` and `bespoke synth-set` as a user runs them: separate
// processes on files on disk. Issue 3's "done when": synth-body + scan-sim
// give, from a seed, a noisy scan with holes and a truth file with exact
// datum points and reference measurements (built-in body everywhere,
// MakeHuman where ../shared is present). Bad input: exit 1, the problem named
// on stderr, nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/body.h"
#include "oracle/body/mesh_checks.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using testing::TempDir;

struct ProcessResult {
  int exit_code = -1;
  std::string err;
};

ProcessResult Bespoke(const TempDir& dir, const std::string& args) {
  const auto err = dir / "stderr.txt";
  const std::string command =
      std::string("'") + BESPOKE_BINARY + "' -q " + args + " > /dev/null 2> '" + err.string() + "'";
  const int status = std::system(command.c_str());
  ProcessResult run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  run.err = ss.str();
  return run;
}

std::string Q(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// A lighter parametric mesh than the default (same girth rings).
const char* kLight =
    " --param torso_segments=48 --param arm_segments=32 --param ring_spacing_mm=30";

void ExpectAllDatumPoints(const nlohmann::json& truth) {
  for (const LandmarkDef& l : Catalogue::Builtin().landmarks()) {
    ASSERT_TRUE(truth["landmarks"].contains(l.name)) << l.name;
    EXPECT_EQ(truth["landmarks"][l.name].size(), 3u);
  }
}

TEST(SynthBodyCli, ParametricBodyAndDatumPointsOnly) {
  TempDir dir;
  const ProcessResult r =
      Bespoke(dir, "synth-body --seed 2" + std::string(kLight) + " -o " + Q(dir / "body.obj") +
                       " --truth " + Q(dir / "truth.json") + " --skip-reference");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh mesh = ReadMesh(ReadOptions(), dir / "body.obj");
  const MeshTopology topology = AnalyzeTopology(mesh.mesh);
  EXPECT_TRUE(topology.IsClosedSphere()) << topology.Describe();
  const nlohmann::json truth = ReadJsonFile(dir / "truth.json");
  EXPECT_EQ(truth["model"], "parametric");
  EXPECT_EQ(truth["seed"], 2);
  EXPECT_EQ(truth["parameters"]["torso_segments"], 48);
  ExpectAllDatumPoints(truth);
  EXPECT_TRUE(truth["measurements"].empty());
  ASSERT_EQ(truth["skipped"].size(), 1u);
  EXPECT_NE(truth["skipped"][0]["reason"].get<std::string>().find("--skip-reference"),
            std::string::npos);
  // The mesh as written is the mesh the datum points refer to (body frame, mm).
  EXPECT_NEAR(mesh.mesh.vertices.col(2).maxCoeff(), truth["landmarks"]["crown"][2].get<double>(),
              1e-3);
}

// The oracle end to end on the built-in body: full truth, then a scan.
TEST(SynthBodyCli, SynthBodyThenScanSimGiveANoisyScanWithHolesAndItsTruth) {
  TempDir dir;
  ProcessResult r = Bespoke(dir, "synth-body --seed 1" + std::string(kLight) + " -o " +
                                     Q(dir / "body.obj") + " --truth " + Q(dir / "truth.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json truth = ReadJsonFile(dir / "truth.json");
  ExpectAllDatumPoints(truth);
  EXPECT_TRUE(truth["skipped"].empty());
  ASSERT_EQ(truth["measurements"].size(), Catalogue::Builtin().measurements().size());
  for (const auto& m : truth["measurements"]) {
    EXPECT_GT(m["value_mm"].get<double>(), 0) << m["name"];
    EXPECT_TRUE(m["flags"].empty()) << m["name"] << " " << m["flags"];
    // Against the construction, within 0.5 mm; the upper arm's datum point
    // is placed by its definition (midway between shoulder point and elbow,
    // below) and the thigh's by MakeHuman's rule (20 mm below the crotch,
    // oracle/synth/rule_landmarks.h), not on the construction's rings.
    if (m["kind"] == "girth" && m["name"] != "upper_arm_girth" && m["name"] != "thigh_girth") {
      const std::string name = m["name"];
      const MeasurementDef& def = Catalogue::Builtin().Measurement(name);
      const std::string side = def.side == "right" ? "_right" : "";
      const double ring = truth["parameters"][name + side + "_analytic_mm"].get<double>();
      // The neck girth is the tape over the skin through four points of the
      // neck-base ring: at most the ring, and within 3 mm of it.
      if (def.method == MeasurementMethod::kGeodesic) {
        EXPECT_LE(m["value_mm"].get<double>(), ring + 0.5) << name;
        EXPECT_GE(m["value_mm"].get<double>(), ring - 3) << name;
      } else if (name == "under_bust_girth") {
        // By its definition, the first corner of the front profile under
        // the bust (oracle/truth/defined_landmarks.h): on the parametric
        // body the breast's lower edge, at or above the construction's
        // under-bust ring and below the bust.
        EXPECT_GE(m["value_mm"].get<double>(), ring - 0.5) << name;
        EXPECT_LT(m["value_mm"].get<double>(),
                  truth["parameters"]["bust_girth_analytic_mm"].get<double>())
            << name;
      } else {
        EXPECT_NEAR(m["value_mm"].get<double>(), ring, 0.5) << name;
      }
    }
  }
  const auto at = [&](const char* name) {
    const auto& p = truth["landmarks"][name];
    return Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  const Eigen::Vector3d shoulder = at("shoulder_right"), elbow = at("elbow_right");
  EXPECT_NEAR((at("upper_arm_right") - shoulder).dot((elbow - shoulder).normalized()),
              0.5 * (elbow - shoulder).norm(), 0.5);  // mm
  // Any reader of the contracts' measurement documents takes it (here the
  // resize stage's), core names included.
  const MeasurementSet values = ReadMeasurements(dir / "truth.json");
  for (const std::string& name : CoreMeasurementNames()) EXPECT_EQ(values.count(name), 1u) << name;

  r = Bespoke(dir, "scan-sim " + Q(dir / "body.obj") + " -o " + Q(dir / "scan.ply") + " --truth " +
                       Q(dir / "truth.json") + " --seed 5 --resolution 120x90 --units mm --labels");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Scan scan = ReadScan(ReadOptions(), dir / "scan.ply");
  const Mesh body = ReadMesh(ReadOptions(), dir / "body.obj");
  ASSERT_EQ(scan.cloud.scalars.count("source"), 1u);
  const Eigen::VectorXd& source = scan.cloud.scalars.at("source");
  // Noise: body points lie off the surface by about the 1 mm sigma.
  double sum_sq = 0;
  int n = 0;
  for (Eigen::Index i = 0; i < scan.cloud.size() && n < 150; i += 97) {
    if (source[i] != 0) continue;  // 0: body (scan_sim's labels)
    const Eigen::Vector3d p = scan.cloud.points.row(i).transpose();
    const double d = (PositionOf(body.mesh, ClosestSurfacePoint(body.mesh, p)) - p).norm();
    sum_sq += d * d, ++n;
  }
  ASSERT_GT(n, 100);
  const double rms = std::sqrt(sum_sq / n);
  EXPECT_GT(rms, 0.3);
  EXPECT_LT(rms, 1.5);
  // Holes: body vertices with no body point within 10 mm, near the crotch
  // point (between the thighs, hidden from every sensor) against near the
  // bust point (the front of the chest, in full view).
  const auto landmark = [&](const char* name) {
    const auto& p = truth["landmarks"][name];
    return Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  const auto uncovered_near = [&](const Eigen::Vector3d& centre, int* total) {
    std::vector<Eigen::Vector3d> points;
    for (Eigen::Index i = 0; i < scan.cloud.size(); ++i)
      if (source[i] == 0 && (scan.cloud.points.row(i).transpose() - centre).norm() < 80)
        points.push_back(scan.cloud.points.row(i).transpose());
    int uncovered = 0;
    *total = 0;
    for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v) {
      const Eigen::Vector3d q = body.mesh.vertices.row(v).transpose();
      if ((q - centre).norm() > 50) continue;
      ++*total;
      double nearest = 1e9;
      for (const auto& p : points) nearest = std::min(nearest, (p - q).norm());
      uncovered += nearest > 10;
    }
    return uncovered;
  };
  int crotch_total = 0, bust_total = 0;
  const int crotch_holes = uncovered_near(landmark("crotch"), &crotch_total);
  const int bust_holes = uncovered_near(landmark("bust_right"), &bust_total);
  std::printf(
      "vertices with no scan point within 10 mm: %d of %d near the crotch, %d of %d near the "
      "bust\n",
      crotch_holes, crotch_total, bust_holes, bust_total);
  EXPECT_GT(crotch_holes, crotch_total / 5);
  EXPECT_EQ(bust_holes, 0);
  // The truth carried into the scan's frame, measurements unchanged.
  const nlohmann::json carried = ReadJsonFile(dir / "scan.truth.json");
  EXPECT_EQ(carried["frame"], "scanner");
  EXPECT_EQ(carried["measurements"], truth["measurements"]);
  ExpectAllDatumPoints(carried);
}

TEST(SynthBodyCli, BadInputIsExitOneAndNothingWritten) {
  TempDir dir;
  const std::string out = " -o " + Q(dir / "body.obj");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"synth-body --model smpl" + out, "'smpl'"},
      {"synth-body --param no_such_size=3" + out, "no_such_size"},
      {"synth-body --param waist_girth_mm=wide" + out, "not a number"},
      {"synth-body --param waist_girth_mm=10" + out, "waist_girth_mm"},
      {"synth-body -o " + Q(dir / "body.xyz"), "body.xyz"},
      {"synth-body" + out + " --truth " + Q(dir / "truth.txt"), "truth.txt"},
      {"synth-body" + out + " --skip-reference", "--skip-reference"},
      {"synth-body" + out + " --truth " + Q(dir / "nowhere" / "truth.json"),
       "folder does not exist"},
      {"synth-body --model makehuman --makehuman-dir " + Q(dir / "nowhere") + out, "nowhere"},
      {"synth-set --count 0 -o " + Q(dir / "set"), "count"},
  };
  for (const auto& [args, named] : cases) {
    const ProcessResult r = Bespoke(dir, args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << "\n" << r.err;
    for (const char* f : {"body.obj", "body.xyz", "truth.txt", "set"})
      EXPECT_FALSE(std::filesystem::exists(dir / f)) << args;
  }
}

TEST(SynthSetCli, TwoParametricSubjects) {
  TempDir dir;
  const ProcessResult r = Bespoke(
      dir, "synth-set --count 2 --seed 3 --skip-reference --resolution 40x30" +
               std::string(kLight) + " -o " + Q(dir / "set") + " --preview " + Q(dir / "set.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json set = ReadJsonFile(dir / "set" / "set.json");
  ASSERT_EQ(set["subjects"].size(), 2u);
  EXPECT_EQ(set["subjects"][0]["seed"], 3001);
  EXPECT_EQ(set["subjects"][1]["seed"], 3002);
  for (const char* s : {"subject_000", "subject_001"})
    for (const char* f :
         {"body.obj", "truth.json", "scan.ply", "scan.scan.json", "scan.truth.json"})
      EXPECT_TRUE(std::filesystem::exists(dir / "set" / s / f)) << s << "/" << f;
  EXPECT_TRUE(std::filesystem::exists(dir / "set.png"));
  // The same seed through synth-body gives the same body.
  const ProcessResult again =
      Bespoke(dir, "synth-body --seed 3001" + std::string(kLight) + " -o " + Q(dir / "b.obj"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(ReadMesh(ReadOptions(), dir / "b.obj").mesh.vertices,
            ReadMesh(ReadOptions(), dir / "set" / "subject_000" / "body.obj").mesh.vertices);
}

TEST(SynthSetCli, MakeHumanSubjectWithReferenceMeasurements) {
  BESPOKE_REQUIRE_SHARED(shared);
  TempDir dir;
  const ProcessResult r =
      Bespoke(dir, "synth-set --count 1 --seed 2 --model makehuman --makehuman-dir " +
                       Q(shared / "data" / "bodies" / "makehuman") + " --resolution 60x45 -o " +
                       Q(dir / "set"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json truth = ReadJsonFile(dir / "set" / "subject_000" / "truth.json");
  EXPECT_EQ(truth["model"], "makehuman");
  ExpectAllDatumPoints(truth);
  EXPECT_TRUE(truth["skipped"].empty());
  EXPECT_EQ(truth["measurements"].size(), Catalogue::Builtin().measurements().size());
  EXPECT_NEAR(ReadMeasurements(dir / "set" / "subject_000" / "truth.json").at("stature"),
              truth["parameters"]["stature_mm"].get<double>(), 0.01);
  EXPECT_TRUE(std::filesystem::exists(dir / "set" / "subject_000" / "scan.ply"));
}

}  // namespace
}  // namespace bespoke
