// How good a made-to-measure fit is: the checks of issue 6's evidence for one
// body, comparing the GA's result and plain proportional grading with the
// design drafted directly for that body's measurements.
//
// Outline distance: per piece, corresponding vertices after the best rigid
// alignment (geometry.h CompareOutlines); the mean is over all vertices of
// all pieces, the max over all of them (mm). Needs a built-in design, whose
// drafts correspond vertex by vertex for any measurements.
#ifndef BESPOKE_EVAL_RESIZE_EVIDENCE_H_
#define BESPOKE_EVAL_RESIZE_EVIDENCE_H_

#include <string>

#include "resize/ga/resize.h"

namespace bespoke {

struct PatternDistance {
  double mean_mm = 0;
  double max_mm = 0;
};

// Throws InputError when the patterns' pieces or vertex counts differ.
PatternDistance ComparePatterns(const Pattern& a, const Pattern& b);

// Distance between two outlines that need not correspond vertex by vertex
// (two drafts of a piece by another system, with their own sampling): `b` is
// rigidly aligned onto `a` (rotation + translation, iterative closest points
// from the centroids), then the mean and max over both outlines, sampled
// every `step_mm` of arc length, of each sample's distance to the other
// outline (mm). With `placement`, the rigid map [R | t] that aligned `b`
// (b's point p lands at R p + t).
PatternDistance CompareOutlineShapes(const Outline& a, const Outline& b, double step_mm = 2,
                                     Eigen::Matrix<double, 2, 3>* placement = nullptr);

struct FitEvidence {
  double max_binding_error_mm = 0;   // largest |achieved - target|
  double max_seam_mismatch_mm = 0;   // largest |length(a) - length(b) - ease|
  bool outlines_simple = true;       // no fitted outline self-intersects
  double shape_deg = 0;              // mean turning-angle change (deg)
  double draft_shape_deg = 0;        // the same for the direct draft vs the base draft (deg)
  double critical_shape_deg = 0;     // at critical points (deg)
  PatternDistance ga_to_draft;       // fitted vs drafted for the body
  PatternDistance grading_to_draft;  // proportional grading vs drafted for the body
  PatternDistance graded_to_draft;   // the graded start vs drafted for the body
  double grading_max_binding_error_mm = 0;
  // Structure of the fit against the base (report.h StructureChanges), worst
  // over the pieces: kink on a straight run (mm), tilt of a level line, fold
  // or grain line (deg), a notch's shift from its fraction of its run (mm),
  // and the new inflections summed over the pieces.
  double max_kink_mm = 0;
  double max_tilt_deg = 0;
  double max_notch_shift_mm = 0;
  int new_inflections = 0;
  // The first sleeve's cap height (design_points.h) on the fit, the graded
  // start and the direct draft (mm); 0 for a design without a sleeve.
  double cap_fit_mm = 0, cap_graded_mm = 0, cap_draft_mm = 0;
  double time_s = 0;         // GA + polish
  std::string polish_start;  // "ga" or "graded" (ResizeResult::polish_start)
  // Every check of the evidence run met: bindings and seams within 1 mm,
  // simple outlines, closer to the draft than grading, no kink > 1 mm, no
  // tilt > 0.5 deg, no notch shift > 1 mm, no new inflection.
  bool Passes() const;
};

// The three patterns EvaluateFit compares (for inspecting a result).
struct FitPatterns {
  Pattern fitted;   // GA + polish
  Pattern direct;   // drafted for the body
  Pattern grading;  // proportional grading (Algorithm 6)
};

// Resizes DraftDesign(design, base) to `body` and compares with
// DraftDesign(design, body) and with ProportionalGrade. Derived measurements
// are added to `body` first (AddDerivedMeasurements). With `patterns`, the
// compared patterns are returned there.
FitEvidence EvaluateFit(const ResizeOptions& options, const std::string& design,
                        const MeasurementSet& body, FitPatterns* patterns = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_RESIZE_EVIDENCE_H_
