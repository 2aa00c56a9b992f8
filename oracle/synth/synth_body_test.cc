// The common front of synth-body, synth-set and accuracy: the same seed and
// parameters give the same body; bad models, parameters and data are
// InputErrors naming the problem.
#include "oracle/synth/synth_body.h"

#include <gtest/gtest.h>

#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

std::string ErrorOf(const SynthBodyOptions& o) {
  try {
    GenerateSynthBody(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SynthBody, ParametricSeedsAndParameters) {
  SynthBodyOptions o;
  o.seed = 6;
  o.params = {"torso_segments=48", "arm_segments=32", "ring_spacing_mm=30"};
  SynthBodyGenerator generator;
  const Body a = generator.Generate(o), b = generator.Generate(o);
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);  // deterministic
  EXPECT_EQ(a.model, "parametric");
  o.params.push_back("waist_girth_mm=700");
  const Body c = generator.Generate(o);
  EXPECT_NEAR(c.parameters.at("waist_girth_analytic_mm"), 700, 1e-9);
  EXPECT_DOUBLE_EQ(c.parameters.at("stature_mm"),
                   a.parameters.at("stature_mm"));  // the rest of the draw kept
  o.seed = 7;
  o.params.pop_back();
  EXPECT_NE(generator.Generate(o).parameters.at("stature_mm"), a.parameters.at("stature_mm"));
}

TEST(SynthBody, BadInputNamesTheProblem) {
  SynthBodyOptions o;
  o.model = "smpl";
  EXPECT_NE(ErrorOf(o).find("'smpl'"), std::string::npos);
  o.model = "parametric";
  o.params = {"waist_girth_mm"};
  EXPECT_NE(ErrorOf(o).find("name=value"), std::string::npos);
  o.params = {"waist_girth_mm=wide"};
  EXPECT_NE(ErrorOf(o).find("'wide' is not a number"), std::string::npos);
  o.params = {"no_such_size=3"};
  EXPECT_NE(ErrorOf(o).find("no_such_size"), std::string::npos);
  o.model = "makehuman";
  o.params = {};
  o.makehuman_dir = "/nonexistent/makehuman";
  EXPECT_NE(ErrorOf(o).find("/nonexistent/makehuman"), std::string::npos);
  EXPECT_EQ(ParseNamedValue("gender=0.25"), (std::pair<std::string, double>{"gender", 0.25}));
}

TEST(SynthBody, MakeHumanFromSharedData) {
  BESPOKE_REQUIRE_SHARED(shared);
  SynthBodyOptions o;
  o.model = "makehuman";
  o.makehuman_dir = shared / "data" / "bodies" / "makehuman";
  o.seed = 3;
  o.params = {"gender=1", "stature_mm=1800"};
  SynthBodyGenerator generator;
  const Body body = generator.Generate(o);
  EXPECT_EQ(body.model, "makehuman");
  EXPECT_EQ(body.parameters.at("gender"), 1);
  EXPECT_NEAR(body.mesh.vertices.col(2).maxCoeff(), 1800, 0.01);
  o.params = {"no_such=1"};
  EXPECT_THROW(generator.Generate(o), InputError);
}

}  // namespace
}  // namespace bespoke
