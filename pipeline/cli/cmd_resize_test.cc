// `bespoke draft` and `bespoke resize` as a user runs them: separate
// processes on files on disk. A body 8 % larger than the shirt's standard
// size (every measurement the design binds scaled by 1.08) gets a fitted
// pattern whose bindings and seams match within the report's tolerance;
// a missing measurement, an unknown design or a malformed file exits 1
// naming the problem and leaves no output folder behind. A generated body
// scanned by the virtual scanner is measured and fitted by one command.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "resize/pattern/measurements.h"
#include "tests/support/draft_measurements.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using ::testing::HasSubstr;
using testing::Quote;
using testing::ReadText;
using testing::RunCommand;
using testing::TempDir;

testing::CommandResult Bespoke(const std::string& args, const TempDir& dir) {
  return RunCommand(std::string("'") + BESPOKE_BINARY + "' --quiet " + args, dir.path());
}

TEST(ResizeCli, DraftThenFitAShirtToALargerBody) {
  TempDir dir;
  const auto draft = Bespoke("draft --design shirt -o " + Quote(dir / "draft"), dir);
  ASSERT_EQ(draft.exit_code, 0) << draft.err;
  for (const char* f : {"pattern.json", "pattern.svg", "pattern.dxf", "draft.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "draft" / f)) << f;
  }
  std::ofstream(dir / "big.json")
      << testing::ScaledDraftMeasurements(dir / "draft" / "draft.json", 1.08).dump(1);
  const auto fit = Bespoke("resize --design shirt --measurements " + Quote(dir / "big.json") +
                               " --population 40 --generations 30 -o " + Quote(dir / "fit"),
                           dir);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  for (const char* f :
       {"fitted.json", "fitted.svg", "fitted.dxf", "report.json", "pareto_front.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "fit" / f)) << f;
  }
  const nlohmann::json report = nlohmann::json::parse(ReadText(dir / "fit" / "report.json"));
  const double tolerance_mm = report.at("settings").at("tolerance_mm");
  ASSERT_FALSE(report.at("measurements").empty());
  for (const auto& m : report.at("measurements")) {
    // Each binding reaches the body's value plus the design's ease.
    EXPECT_NEAR(m.at("achieved_mm").get<double>(),
                m.at("body_mm").get<double>() + m.at("ease_mm").get<double>(), tolerance_mm)
        << m.at("binding");
  }
  for (const auto& s : report.at("seams")) {
    EXPECT_LE(std::abs(s.at("mismatch_mm").get<double>()), tolerance_mm) << s.at("seam");
  }
  EXPECT_THAT(ReadText(dir / "fit" / "fitted.svg"), HasSubstr("mm\""));  // 1:1 in millimetres
  EXPECT_THAT(ReadText(dir / "fit" / "fitted.dxf"), HasSubstr("EOF"));
}

// A Valentina DXF-ASTM piece (../shared) has no landmarks or bindings: the
// sidecar of docs/pattern-format.md adds two landmarks (snapped to outline
// vertices 385 mm apart) and an outseam binding with -20 mm ease. A body
// with a 500 mm outseam stretches the piece to 480 mm, and the fitted DXF
// read back with the same sidecar measures 480 mm.
TEST(ResizeCli, FitsAValentinaDxfPieceWithASidecar) {
  BESPOKE_REQUIRE_SHARED(shared);
  TempDir dir;
  const auto dxf = shared / "data/patterns/valentina/smart_pattern_145_ASTM_R12.dxf";
  std::ofstream(dir / "side.json") << R"({"pieces": [{"name": "Kurze Hinterhose",
      "critical": [0, 14, 15, 16],
      "landmarks": [{"name": "waist_cb", "near": [0.3, 419.2]}, {"name": "hem_cb", "near": [0.3, 0.3]}]}],
      "bindings": [{"id": "length", "measurement": "outseam", "ease_mm": -20,
                    "terms": [{"piece": "Kurze Hinterhose", "from": "waist_cb", "to": "hem_cb"}]}]})";
  std::ofstream(dir / "body.json") << R"({"measurements": [{"name": "outseam", "value_mm": 500}]})";
  const std::string common = " --sidecar " + Quote(dir / "side.json") + " --measurements " +
                             Quote(dir / "body.json") + " --population 40 --generations 30 -o ";
  const auto fit = Bespoke("resize --pattern " + Quote(dxf) + common + Quote(dir / "fit"), dir);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const nlohmann::json report = nlohmann::json::parse(ReadText(dir / "fit" / "report.json"));
  ASSERT_EQ(report.at("measurements").size(), 1u);
  const nlohmann::json& m = report.at("measurements")[0];
  EXPECT_NEAR(m.at("base_pattern_mm").get<double>(), 385.0, 1.0);  // the sample as drawn
  EXPECT_NEAR(m.at("target_mm").get<double>(), 480.0, 1e-9);
  EXPECT_NEAR(m.at("achieved_mm").get<double>(), 480.0, 1.0);
  EXPECT_THAT(ReadText(dir / "fit" / "fitted.dxf"), HasSubstr("Kurze Hinterhose"));
  // The written DXF is read again, the landmarks put on the vertices the fit
  // gave them (fitted.json): it already has the length.
  const nlohmann::json fitted = nlohmann::json::parse(ReadText(dir / "fit" / "fitted.json"));
  nlohmann::json side2 = nlohmann::json::parse(ReadText(dir / "side.json"));
  for (nlohmann::json& l : side2["pieces"][0]["landmarks"]) {
    l.erase("near");
    for (const nlohmann::json& f : fitted.at("pieces")[0].at("landmarks"))
      if (f.at("name") == l.at("name")) l["vertex"] = f.at("vertex");
  }
  std::ofstream(dir / "side2.json") << side2.dump();
  const auto again =
      Bespoke("resize --pattern " + Quote(dir / "fit" / "fitted.dxf") + " --sidecar " +
                  Quote(dir / "side2.json") + " --measurements " + Quote(dir / "body.json") +
                  " --population 40 --generations 30 -o " + Quote(dir / "again"),
              dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const nlohmann::json report2 = nlohmann::json::parse(ReadText(dir / "again" / "report.json"));
  EXPECT_NEAR(report2.at("measurements")[0].at("base_pattern_mm").get<double>(), 480.0, 1.0);
  // A sidecar naming a piece the file does not have: exit 1, the names listed.
  std::ofstream(dir / "wrong.json") << R"({"pieces": [{"name": "Sleeve"}]})";
  const auto wrong =
      Bespoke("resize --pattern " + Quote(dxf) + " --sidecar " + Quote(dir / "wrong.json") +
                  " --measurements " + Quote(dir / "body.json") + " -o " + Quote(dir / "w"),
              dir);
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_THAT(wrong.err, HasSubstr("'Sleeve'"));
  EXPECT_THAT(wrong.err, HasSubstr("'Kurze Hinterhose'"));
  EXPECT_FALSE(std::filesystem::exists(dir / "w"));
}

// synth-body + scan-sim give a scan; `resize --scan` measures it (the
// pipeline's scan job) and fits the shirt to those measurements: the
// measurement document is written beside the fit, and every binding's
// target is the scan's value plus the design's ease.
TEST(ResizeCli, FitsADesignToAScanFromOneCommand) {
  TempDir dir;
  auto r = Bespoke(
      "synth-body --seed 4 --param torso_segments=48 --param arm_segments=32 "
      "--param ring_spacing_mm=30 --skip-reference -o " +
          Quote(dir / "body.obj") + " --truth " + Quote(dir / "truth.json"),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Bespoke("scan-sim " + Quote(dir / "body.obj") + " -o " + Quote(dir / "scan.ply") +
                  " --seed 5 --resolution 160x120 --units mm",
              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = Bespoke("resize --design shirt --scan " + Quote(dir / "scan.ply") +
                  " --population 40 --generations 20 -o " + Quote(dir / "fit"),
              dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"measurements.json", "fitted.json", "fitted.svg", "fitted.dxf",
                        "report.json", "report.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "fit" / f)) << f;
  }
  const MeasurementSet measured = ReadMeasurements(dir / "fit" / "measurements.json");
  const nlohmann::json report = nlohmann::json::parse(ReadText(dir / "fit" / "report.json"));
  EXPECT_EQ(report.at("settings").at("scan").get<std::string>(), (dir / "scan.ply").string());
  ASSERT_FALSE(report.at("measurements").empty());
  for (const auto& m : report.at("measurements")) {
    const std::string name = m.at("measurement");
    if (name.front() == '(') continue;  // fixed or following another binding
    ASSERT_EQ(measured.count(name), 1u) << name;
    EXPECT_DOUBLE_EQ(m.at("body_mm").get<double>(), measured.at(name)) << name;
  }
}

// A scan that cannot be read: exit 1 naming it, no output folder, and
// --scan with --measurements is refused.
TEST(ResizeCli, BadScanExitsOneNamingTheFileAndWritesNothing) {
  TempDir dir;
  std::ofstream(dir / "broken.ply") << "ply\nformat ascii 1.0\nelement vertex 5\n";
  auto r = Bespoke(
      "resize --design shirt --scan " + Quote(dir / "broken.ply") + " -o " + Quote(dir / "out"),
      dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("broken.ply"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  std::ofstream(dir / "m.json") << R"({"measurements": []})";
  r = Bespoke("resize --design shirt --scan " + Quote(dir / "broken.ply") + " --measurements " +
                  Quote(dir / "m.json") + " -o " + Quote(dir / "out"),
              dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("--scan"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(ResizeCli, BadInputExitsOneNamingTheProblemAndWritesNothing) {
  TempDir dir;
  std::ofstream(dir / "empty.json")
      << R"({"format": "bespoke-measurements", "version": 1, "units": "mm",
                                          "measurements": []})";
  auto r = Bespoke("resize --design shirt --measurements " + Quote(dir / "empty.json") + " -o " +
                       Quote(dir / "a"),
                   dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("chest_girth"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a"));

  r = Bespoke("draft --design kilt -o " + Quote(dir / "b"), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("kilt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b"));

  std::ofstream(dir / "broken.json") << "{\"measurements\": [";
  r = Bespoke("resize --design trousers --measurements " + Quote(dir / "broken.json") + " -o " +
                  Quote(dir / "c"),
              dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("broken.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "c"));
}

}  // namespace
}  // namespace bespoke
