// A small version of the evidence run (docs/resize.md): a few far bodies,
// small GA budget; the full run is eval/bench/resize_evidence.cc.
#include "eval/resize/evidence.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "resize/designs/body_variants.h"
#include "resize/designs/designs.h"

namespace bespoke {
namespace {

TEST(Evidence, FarBodiesFitAndBeatProportionalGrading) {
  ResizeOptions options;
  options.population = 60;
  options.generations = 30;
  for (const std::string& design : DesignNames()) {
    for (std::uint64_t seed : {100u, 101u}) {
      const FitEvidence e = EvaluateFit(options, design, VariedMeasurements(design, seed));
      EXPECT_LE(e.max_binding_error_mm, 1.0) << design << " " << seed;
      EXPECT_LE(e.max_seam_mismatch_mm, 1.0) << design << " " << seed;
      EXPECT_TRUE(e.outlines_simple) << design << " " << seed;
      EXPECT_LT(e.ga_to_draft.mean_mm, e.grading_to_draft.mean_mm) << design << " " << seed;
      // Grading really is off for these bodies (else the test proves nothing).
      EXPECT_GT(e.grading_max_binding_error_mm, 10.0) << design << " " << seed;
    }
  }
}

TEST(Evidence, ComparePatternsIsZeroForIdenticalAndRigidlyMovedPatterns) {
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  Pattern q = p;
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(0.3).toRotationMatrix();
  for (Piece& piece : q.pieces)
    piece.outline =
        ((piece.outline * r.transpose()).rowwise() + Eigen::RowVector2d(50, -20)).eval();
  const PatternDistance d = ComparePatterns(p, q);
  EXPECT_LT(d.max_mm, 1e-9);
  MeasurementSet big = BaseMeasurements("shirt");
  big["chest_girth"] += 100;  // half chest + 12 cm: the front and back widen by 25 mm each
  const PatternDistance e = ComparePatterns(p, DraftDesign("shirt", big));
  EXPECT_GT(e.max_mm, 10.0);
}

}  // namespace
}  // namespace bespoke
