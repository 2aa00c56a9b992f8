#include "resize/ga/resize.h"

#include <gtest/gtest.h>

#include "eval/resize/evidence.h"
#include "resize/designs/body_variants.h"
#include "resize/designs/designs.h"
#include "resize/ga/grading.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double MaxVertexMove(const Pattern& a, const Pattern& b) {
  double worst = 0;
  for (size_t p = 0; p < a.pieces.size(); ++p)
    worst =
        std::max(worst, (a.pieces[p].outline - b.pieces[p].outline).rowwise().norm().maxCoeff());
  return worst;
}

ResizeOptions Small() {
  ResizeOptions o;
  o.population = 60;
  o.generations = 30;
  return o;
}

TEST(Resize, BaseMeasurementsGiveTheBasePatternBack) {
  for (const std::string& design : DesignNames()) {
    const MeasurementSet base = BaseMeasurements(design);
    const Pattern pattern = DraftDesign(design, base);
    const ResizeResult r = ResizePattern(Small(), pattern, base, nullptr);
    EXPECT_LT(MaxVertexMove(pattern, r.fitted), 0.5) << design;
  }
}

TEST(Resize, FarBodyMeetsMeasurementsAndSeams) {
  const MeasurementSet body = VariedMeasurements("shirt", 3);
  const Pattern pattern = DraftDesign("shirt", BaseMeasurements("shirt"));
  const ResizeResult r = ResizePattern(Small(), pattern, body, nullptr);
  for (size_t b = 0; b < r.targets_mm.size(); ++b)
    EXPECT_NEAR(r.achieved_mm[b], r.targets_mm[b], 1.0) << pattern.bindings[b].id;
  for (size_t s = 0; s < r.seam_mismatch_mm.size(); ++s)
    EXPECT_LT(std::abs(r.seam_mismatch_mm[s]), 1.0) << pattern.seams[s].name;
  EXPECT_TRUE(r.objectives.simple);
}

TEST(Resize, TrousersFollowALongerRise) {
  // Same legs and girths, a 50 mm longer rise: only the rise bindings see
  // it. They are met, and the fit is closer to the trousers drafted for that
  // body than proportional grading (which scales the whole front and back by
  // the rise's ratio) and than the unchanged standard pattern (8.1, 45 and
  // 11.6 mm mean when written: the seat line tilts, so the side seam takes
  // only part of the drop, docs/resize.md).
  MeasurementSet body = BaseMeasurements("trousers");
  body.erase("body_rise");  // derived by ResizePattern and EvaluateFit
  body["waist_height"] += 50;
  FitPatterns patterns;
  const FitEvidence e = EvaluateFit(Small(), "trousers", body, &patterns);
  EXPECT_LE(e.max_binding_error_mm, 1.0);
  EXPECT_LE(e.max_seam_mismatch_mm, 1.0);
  const Pattern base = DraftDesign("trousers", BaseMeasurements("trousers"));
  const double unchanged = ComparePatterns(base, patterns.direct).mean_mm;
  EXPECT_GT(unchanged, 10.0);  // the longer rise really changes the draft
  EXPECT_LT(e.ga_to_draft.mean_mm, unchanged);
  EXPECT_LT(e.ga_to_draft.mean_mm, 0.5 * e.grading_to_draft.mean_mm);
  for (const MeasurementBinding& b : base.bindings)
    if (b.measurement == "body_rise")
      EXPECT_NEAR(BindingValue(patterns.fitted, b), 300 + b.ease_mm, 1.0) << b.id;
}

TEST(Resize, FixedStyleDimensionsAreKept) {
  // The trousers' hem widths are fixed style widths of the draft (210 and
  // 250 mm for any body), bound as fixed; grading scales them, the fit keeps
  // them.
  const MeasurementSet body = VariedMeasurements("trousers", 100);
  FitPatterns patterns;
  EvaluateFit(Small(), "trousers", body, &patterns);
  auto hem = [](const Pattern& p, const char* piece) {
    const Piece& q = p.pieces[p.FindPiece(piece)];
    return (q.LandmarkPosition(q.FindLandmark("hem_in")) -
            q.LandmarkPosition(q.FindLandmark("hem_out")))
        .norm();
  };
  for (const char* piece : {"front", "back"}) {
    const double drafted = hem(patterns.direct, piece);
    EXPECT_GT(std::abs(hem(patterns.grading, piece) - drafted), 20.0) << piece;
    EXPECT_NEAR(hem(patterns.fitted, piece), drafted, 1.0) << piece;
  }
}

TEST(Resize, PolishAndGraderOptionsRejectBadValues) {
  PolishOptions o;
  o.energy.shear_weight = -1;
  EXPECT_THROW(o.Check(), InputError);
  GraderOptions g;
  g.energy.prior_weight = 0;
  EXPECT_THROW(g.Check(), InputError);
  g = GraderOptions();
  g.share_weight = -1;
  EXPECT_THROW(g.Check(), InputError);
  EXPECT_NO_THROW(GraderOptions().Check());
  EXPECT_NO_THROW(PolishOptions().Check());
}

TEST(Resize, DeterministicForASeed) {
  const MeasurementSet body = VariedMeasurements("trousers", 5);
  const Pattern pattern = DraftDesign("trousers", BaseMeasurements("trousers"));
  ResizeOptions o = Small();
  o.polish = false;
  const ResizeResult a = ResizePattern(o, pattern, body, nullptr);
  const ResizeResult b = ResizePattern(o, pattern, body, nullptr);
  EXPECT_EQ(MaxVertexMove(a.fitted, b.fitted), 0.0);
}

// Evaluation runs in parallel, every random draw in one thread: one thread
// and several give the same answer, bit for bit.
TEST(Resize, SameAnswerWhateverTheThreadCount) {
  const MeasurementSet body = VariedMeasurements("shirt", 3);
  const Pattern pattern = DraftDesign("shirt", BaseMeasurements("shirt"));
  ResizeOptions o = Small();
  auto run = [&](int threads) {
    o.threads = threads;
    return ResizePattern(o, pattern, body, nullptr);
  };
  const ResizeResult one = run(1), several = run(3);
  EXPECT_EQ(MaxVertexMove(one.fitted, several.fitted), 0.0);
  EXPECT_EQ(one.ga_objectives.shape_deg, several.ga_objectives.shape_deg);
  EXPECT_EQ(one.ga_objectives.seam, several.ga_objectives.seam);
  ASSERT_EQ(one.front.size(), several.front.size());
  for (size_t i = 0; i < one.front.size(); ++i)
    EXPECT_EQ(one.front[i].measurement_mm, several.front[i].measurement_mm) << i;
}

TEST(Resize, UnknownOrMissingMeasurementIsInputError) {
  Pattern pattern = DraftDesign("shirt", BaseMeasurements("shirt"));
  MeasurementSet body = BaseMeasurements("shirt");
  body.erase("chest_girth");
  EXPECT_THROW(ResizePattern(Small(), pattern, body, nullptr), InputError);
  pattern.bindings[0].measurement = "chest_circ";
  EXPECT_THROW(ResizePattern(Small(), pattern, BaseMeasurements("shirt"), nullptr), InputError);
}

}  // namespace
}  // namespace bespoke
