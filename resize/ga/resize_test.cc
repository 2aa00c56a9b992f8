#include "resize/ga/resize.h"

#include <gtest/gtest.h>

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

TEST(Resize, DeterministicForASeed) {
  const MeasurementSet body = VariedMeasurements("trousers", 5);
  const Pattern pattern = DraftDesign("trousers", BaseMeasurements("trousers"));
  ResizeOptions o = Small();
  o.polish = false;
  const ResizeResult a = ResizePattern(o, pattern, body, nullptr);
  const ResizeResult b = ResizePattern(o, pattern, body, nullptr);
  EXPECT_EQ(MaxVertexMove(a.fitted, b.fitted), 0.0);
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
