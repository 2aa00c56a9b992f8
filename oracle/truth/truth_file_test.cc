// TRUTH.json: the contracts' measurement document with the oracle's extras,
// written atomically and read back unchanged.
#include "oracle/truth/truth_file.h"

#include <gtest/gtest.h>

#include "oracle/body/parametric_body.h"
#include "scanners/core/json_io.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

TEST(TruthFile, ContractsSchemaWithDatumPointsAndGeometry) {
  ParametricBodyOptions o;
  o.torso_segments = 48;
  o.arm_segments = 32;
  o.ring_spacing_mm = 30;
  o.seed = 4;
  const Body body = GenerateParametricBody(SeededOptions(o));
  const Catalogue& catalogue = Catalogue::Builtin();
  ReferenceOptions options;
  options.keep_geometry = true;
  const ReferenceMeasurements truth = ComputeReferenceMeasurements(options, catalogue, body);
  testing::TempDir dir;
  WriteTruthFile(dir / "truth.json", body, catalogue, options, truth);
  const nlohmann::json doc = ReadJsonFile(dir / "truth.json");
  EXPECT_EQ(doc, TruthDocument(body, catalogue, options, truth));
  EXPECT_EQ(doc["format"], "bespoke-measurements");
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["units"], "mm");
  EXPECT_EQ(doc["frame"], "body");
  EXPECT_EQ(doc["source"], "truth");
  EXPECT_EQ(doc["model"], "parametric");
  EXPECT_EQ(doc["seed"], 4);  // the seed drawn from, not the options' 0 after the draw
  EXPECT_EQ(doc["parameters"]["waist_girth_analytic_mm"].get<double>(),
            body.parameters.at("waist_girth_analytic_mm"));
  EXPECT_EQ(doc["mesh"]["vertices"], body.mesh.num_vertices());
  ASSERT_EQ(doc["landmarks"].size(), body.landmarks.size());
  for (const auto& [name, point] : body.landmarks) {
    const Eigen::Vector3d p = PositionOf(body.mesh, point);
    for (int k = 0; k < 3; ++k)
      EXPECT_DOUBLE_EQ(doc["landmarks"][name][k].get<double>(), p[k]) << name;
    EXPECT_EQ(doc["landmark_surface"][name]["face"], point.face);
  }
  ASSERT_EQ(doc["measurements"].size(), catalogue.measurements().size());
  for (std::size_t i = 0; i < truth.measurements.size(); ++i) {
    const nlohmann::json& m = doc["measurements"][i];
    const MeasurementDef& def = catalogue.Measurement(m["name"].get<std::string>());
    EXPECT_EQ(m["name"], truth.measurements[i].name);
    EXPECT_EQ(m["kind"], ToString(def.kind));
    EXPECT_EQ(m["method"], ToString(def.method));
    EXPECT_EQ(m["datum"], def.datum);
    EXPECT_DOUBLE_EQ(m["value_mm"].get<double>(), truth.measurements[i].value_mm);
    EXPECT_TRUE(m["flags"].is_array());
    if (def.method != MeasurementMethod::kHeight) {
      EXPECT_GE(m["geometry"].size(), 2u) << def.name;
    }
  }
  EXPECT_TRUE(doc["skipped"].empty());
  EXPECT_EQ(doc["settings"]["datum_tolerance_mm"], 20);
  // Without geometry the document has none.
  const ReferenceMeasurements lean =
      ComputeReferenceMeasurements(ReferenceOptions(), catalogue, body);
  const nlohmann::json plain = TruthDocument(body, catalogue, ReferenceOptions(), lean);
  EXPECT_FALSE(plain["measurements"][0].contains("geometry"));
}

}  // namespace
}  // namespace bespoke
