#include "eval/resize/evidence.h"

#include <algorithm>
#include <cmath>

#include "resize/designs/designs.h"
#include "resize/ga/grading.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {

PatternDistance ComparePatterns(const Pattern& a, const Pattern& b) {
  if (a.pieces.size() != b.pieces.size())
    throw InputError("patterns to compare have different piece counts");
  PatternDistance d;
  double sum = 0;
  Eigen::Index count = 0;
  for (size_t p = 0; p < a.pieces.size(); ++p) {
    const OutlineDistanceStats s = CompareOutlines(a.pieces[p].outline, b.pieces[p].outline);
    sum += s.mean_mm * static_cast<double>(a.pieces[p].outline.rows());
    count += a.pieces[p].outline.rows();
    d.max_mm = std::max(d.max_mm, s.max_mm);
  }
  d.mean_mm = sum / static_cast<double>(std::max<Eigen::Index>(count, 1));
  return d;
}

FitEvidence EvaluateFit(const ResizeOptions& options, const std::string& design,
                        const MeasurementSet& given, FitPatterns* patterns) {
  MeasurementSet body = given;
  AddDerivedMeasurements(&body, "body");
  const Pattern base = DraftDesign(design, BaseMeasurements(design));
  const Pattern direct = DraftDesign(design, body);
  const ResizeResult r = ResizePattern(options, base, body, nullptr);
  FitEvidence e;
  for (size_t b = 0; b < r.targets_mm.size(); ++b)
    e.max_binding_error_mm =
        std::max(e.max_binding_error_mm, std::abs(r.achieved_mm[b] - r.targets_mm[b]));
  for (double m : r.seam_mismatch_mm)
    e.max_seam_mismatch_mm = std::max(e.max_seam_mismatch_mm, std::abs(m));
  e.outlines_simple = r.objectives.simple;
  e.shape_deg = r.objectives.shape_deg;
  e.critical_shape_deg = r.objectives.critical_shape_deg;
  double change = 0;
  Eigen::Index vertices = 0;
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const Eigen::VectorXd a = TurningAngles(base.pieces[p].outline);
    const Eigen::VectorXd b = TurningAngles(direct.pieces[p].outline);
    for (Eigen::Index v = 0; v < a.size(); ++v)
      change += std::abs(std::remainder(b[v] - a[v], 2 * M_PI)) * 180.0 / M_PI;
    vertices += a.size();
  }
  e.draft_shape_deg = change / static_cast<double>(std::max<Eigen::Index>(vertices, 1));
  e.ga_to_draft = ComparePatterns(r.fitted, direct);
  e.grading_to_draft = ComparePatterns(r.seed, direct);
  for (const MeasurementBinding& b : base.bindings)
    e.grading_max_binding_error_mm =
        std::max(e.grading_max_binding_error_mm,
                 std::abs(BindingValue(r.seed, b) - body.at(b.measurement) - b.ease_mm));
  e.time_s = r.ga_time_s + r.polish_time_s;
  e.polish_start = r.polish_start;
  if (patterns) *patterns = FitPatterns{r.fitted, direct, r.seed};
  return e;
}

}  // namespace bespoke
