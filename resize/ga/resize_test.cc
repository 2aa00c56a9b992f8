#include "resize/ga/resize.h"

#include <gtest/gtest.h>

#include <cmath>

#include "eval/resize/evidence.h"
#include "resize/designs/body_variants.h"
#include "resize/designs/designs.h"
#include "resize/ga/grading.h"
#include "resize/pattern/design_points.h"
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

// With the graded start as the shape reference, the graded start itself has
// no shape change and the proportional seed (the base scaled) has some; with
// the base as reference (the thesis), the seed, the base scaled per piece
// in x and y, has less than the graded start.
TEST(Resize, ShapeIsMeasuredFromTheGradedStart) {
  const MeasurementSet body = VariedMeasurements("shirt", 3);
  const Pattern pattern = DraftDesign("shirt", BaseMeasurements("shirt"));
  ResizeOptions o = Small();
  o.generations = 0;
  const ResizeResult graded = ResizePattern(o, pattern, body, nullptr);
  EXPECT_EQ(graded.shape_reference, "graded start");
  EXPECT_NEAR(graded.graded_objectives.shape_deg, 0, 1e-9);
  EXPECT_GT(graded.seed_objectives.shape_deg, 0.05);
  o.shape_from_graded = false;
  const ResizeResult base = ResizePattern(o, pattern, body, nullptr);
  EXPECT_EQ(base.shape_reference, "base");
  EXPECT_LT(base.seed_objectives.shape_deg, base.graded_objectives.shape_deg);
  EXPECT_GT(base.graded_objectives.shape_deg, 0.05);
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

// A 300 x 100 mm panel with a curved top edge (31 points, 10 mm up in the
// middle) and a notch on it at x = 200, a third of the edge from the top
// right corner; corner landmarks; inside landmarks at x = 0, 100 and 300
// carry two width bindings: the left 100 mm doubled (chest girth 200), the
// right 200 mm kept (fixed). The notch is a critical point, so a grid line
// passes through it; the grain is vertical.
Pattern NotchedPanel() {
  Piece piece;
  piece.name = "panel";
  std::vector<Eigen::Vector2d> points = {{0, 0}, {100, 0}, {300, 0}};
  for (int k = 0; k <= 30; ++k) {
    const double x = 300 - 10 * k;
    points.push_back({x, 100 + 10 * std::sin(M_PI * x / 300)});
  }
  piece.outline.resize(static_cast<Eigen::Index>(points.size()), 2);
  for (size_t i = 0; i < points.size(); ++i)
    piece.outline.row(static_cast<Eigen::Index>(i)) = points[i];
  piece.landmarks = {{"bl", "", 0, {}},       {"br", "", 2, {}},      {"tr", "", 3, {}},
                     {"tl", "", 33, {}},      {"l", "", -1, {0, 50}}, {"m", "", -1, {100, 50}},
                     {"r", "", -1, {300, 50}}};
  piece.critical = {0, 1, 2, 3, 13, 33};
  piece.notches = {13};
  piece.has_grain = true;
  piece.grain_start = {150, 20};
  piece.grain_end = {150, 80};
  Pattern p;
  p.name = "panel";
  p.pieces = {piece};
  MeasurementBinding left;
  left.id = "left";
  left.measurement = "chest_girth";
  left.terms = {{"panel", "l", "m", BindingTerm::Path::kStraight, 1}};
  MeasurementBinding right;
  right.id = "right";
  right.fixed = true;
  right.fixed_mm = 200;
  right.terms = {{"panel", "m", "r", BindingTerm::Path::kStraight, 1}};
  p.bindings = {left, right};
  return p;
}

TEST(Resize, NotchKeepsItsFractionWhenStretchedUnevenly) {
  const Pattern base = NotchedPanel();
  const std::vector<NotchRun> runs = NotchRuns(base, 0);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_NEAR(runs[0].fraction, 1.0 / 3, 0.01);
  ResizeOptions o = Small();
  o.generations = 0;
  const MeasurementSet body = {{"chest_girth", 200}};
  const ResizeResult r = ResizePattern(o, base, body, nullptr);
  EXPECT_NEAR(r.achieved_mm[0], 200, 0.1);
  EXPECT_NEAR(r.achieved_mm[1], 200, 0.1);
  EXPECT_LT(std::abs(NotchShift(r.fitted.pieces[0].outline, runs[0])), 0.1);
  EXPECT_LT(std::abs(NotchShift(r.graded.pieces[0].outline, runs[0])), 0.1);
  // Without the notch the same fit leaves it where the grid carries it (49
  // mm short of its third when written).
  Pattern plain = base;
  plain.pieces[0].notches.clear();
  const ResizeResult q = ResizePattern(o, plain, body, nullptr);
  EXPECT_GT(std::abs(NotchShift(q.fitted.pieces[0].outline, runs[0])), 20.0);
}

TEST(Resize, NotchesMatchedAcrossASeamStayMatched) {
  // A band sewn onto the panel's curved top edge (the same 31 points, so
  // stitch i pairs equal points), with the matching notch at x = 200: the
  // panel's left half doubles, the band follows only through the seam.
  Pattern p = NotchedPanel();
  Piece band;
  band.name = "band";
  band.outline.resize(33, 2);
  for (int k = 0; k <= 30; ++k) band.outline.row(k) = p.pieces[0].outline.row(33 - k);
  band.outline.row(31) << 300, 200;
  band.outline.row(32) << 0, 200;
  band.landmarks = {{"bl", "", 0, {}}, {"br", "", 30, {}}, {"tr", "", 31, {}}, {"tl", "", 32, {}}};
  band.critical = {0, 20, 30, 31, 32};
  band.notches = {20};
  band.has_grain = true;
  band.grain_start = {150, 150};
  band.grain_end = {150, 190};
  p.pieces.push_back(band);
  Seam seam;
  seam.name = "top";
  seam.a = {"panel", 3, 33, true};
  seam.b = {"band", 30, 0, false};
  p.seams = {seam};
  ResizeOptions o = Small();
  o.generations = 0;
  const ResizeResult r = ResizePattern(o, p, {{"chest_girth", 200}}, nullptr);
  EXPECT_LT(std::abs(r.seam_mismatch_mm[0]), 0.1);
  const Outline &a = r.fitted.pieces[0].outline, &b = r.fitted.pieces[1].outline;
  // Along the seam from its start (the panel's top right, the band's
  // bottom right) to each notch: the same length.
  const double to_a = OutlineDistance(a, 3, 13), to_b = OutlineDistance(b, 30, 20, false);
  EXPECT_GT(to_a, 100 + 30);  // the seam really changed (100 mm in the base)
  EXPECT_NEAR(to_a, to_b, 0.1);
  // Without the notches the two places part (85 and 134 mm when written).
  Pattern plain = p;
  for (Piece& piece : plain.pieces) piece.notches.clear();
  const ResizeResult q = ResizePattern(o, plain, {{"chest_girth", 200}}, nullptr);
  EXPECT_GT(std::abs(OutlineDistance(q.fitted.pieces[0].outline, 3, 13) -
                     OutlineDistance(q.fitted.pieces[1].outline, 30, 20, false)),
            20.0);
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

TEST(Resize, NoBindingsSaysWhereToNameThem) {
  Pattern pattern = DraftDesign("shirt", BaseMeasurements("shirt"));
  pattern.bindings.clear();
  try {
    ResizePattern(Small(), pattern, BaseMeasurements("shirt"), nullptr);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--sidecar"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bespoke
