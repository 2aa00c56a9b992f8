#include "eval/resize/evidence.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "resize/designs/designs.h"
#include "resize/ga/grading.h"
#include "resize/ga/report.h"
#include "resize/pattern/design_points.h"
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

namespace {

std::vector<Eigen::Vector2d> Sample(const Outline& o, double step) {
  std::vector<Eigen::Vector2d> points;
  const Eigen::Index n = o.rows();
  for (Eigen::Index v = 0; v < n; ++v) {
    const Eigen::Vector2d a = o.row(v), b = o.row((v + 1) % n);
    const int k = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int i = 0; i < k; ++i) points.push_back(a + (b - a) * (static_cast<double>(i) / k));
  }
  return points;
}

double ToOutline(const Eigen::Vector2d& p, const Outline& o) {
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Index n = o.rows();
  for (Eigen::Index v = 0; v < n; ++v) {
    const Eigen::Vector2d a = o.row(v), d = Eigen::Vector2d(o.row((v + 1) % n)) - a;
    const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

}  // namespace

PatternDistance CompareOutlineShapes(const Outline& a, const Outline& b_in, double step_mm,
                                     Eigen::Matrix<double, 2, 3>* placement) {
  const std::vector<Eigen::Vector2d> sa = Sample(a, 4 * step_mm);
  Outline b = b_in;
  Eigen::Vector2d ca = Eigen::Vector2d::Zero(), cb = Eigen::Vector2d::Zero();
  for (const auto& p : sa) ca += p;
  ca /= static_cast<double>(sa.size());
  std::vector<Eigen::Vector2d> sb = Sample(b, 4 * step_mm);
  for (const auto& p : sb) cb += p;
  cb /= static_cast<double>(sb.size());
  b.rowwise() += (ca - cb).transpose();
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();  // b = rotation b_in + shift
  Eigen::Vector2d shift = ca - cb;
  for (int it = 0; it < 40; ++it) {
    sb = Sample(b, 4 * step_mm);
    // Pairs: every sample of b with its nearest sample of a.
    Eigen::Vector2d mb = Eigen::Vector2d::Zero(), ma = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> pa(sb.size());
    for (size_t i = 0; i < sb.size(); ++i) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& q : sa)
        if ((q - sb[i]).squaredNorm() < best) best = (q - sb[i]).squaredNorm(), pa[i] = q;
      mb += sb[i];
      ma += pa[i];
    }
    mb /= static_cast<double>(sb.size());
    ma /= static_cast<double>(sb.size());
    Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
    for (size_t i = 0; i < sb.size(); ++i) h += (sb[i] - mb) * (pa[i] - ma).transpose();
    const double angle = std::atan2(h(0, 1) - h(1, 0), h(0, 0) + h(1, 1));
    Eigen::Matrix2d r;
    r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    for (Eigen::Index v = 0; v < b.rows(); ++v)
      b.row(v) = (r * (Eigen::Vector2d(b.row(v)) - mb) + ma).transpose();
    rotation = r * rotation;
    shift = r * (shift - mb) + ma;
    if (std::abs(angle) < 1e-7 && (ma - mb).norm() < 1e-6) break;
  }
  PatternDistance d;
  double sum = 0;
  size_t count = 0;
  const Outline& bb = b;
  for (const auto& [from, to] : {std::pair{&a, &bb}, std::pair{&bb, &a}})
    for (const Eigen::Vector2d& p : Sample(*from, step_mm)) {
      const double e = ToOutline(p, *to);
      sum += e;
      d.max_mm = std::max(d.max_mm, e);
      ++count;
    }
  d.mean_mm = sum / static_cast<double>(std::max<size_t>(count, 1));
  if (placement != nullptr) *placement << rotation, shift;
  return d;
}

bool FitEvidence::Passes() const {
  return max_binding_error_mm <= 1 && max_seam_mismatch_mm <= 1 && outlines_simple &&
         ga_to_draft.mean_mm < grading_to_draft.mean_mm && max_kink_mm <= 1 &&
         max_tilt_deg <= 0.5 && max_notch_shift_mm <= 1 && new_inflections == 0;
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
  e.graded_to_draft = ComparePatterns(r.graded, direct);
  for (const StructureFigures& s : StructureChanges(base, r.fitted)) {
    e.max_kink_mm = std::max(e.max_kink_mm, s.max_kink_mm);
    e.max_tilt_deg =
        std::max({e.max_tilt_deg, s.max_level_tilt_deg, s.max_fold_tilt_deg, s.max_grain_tilt_deg});
    e.max_notch_shift_mm = std::max(e.max_notch_shift_mm, s.max_notch_shift_mm);
    e.new_inflections += s.new_inflections;
  }
  for (const DesignDimension& d : FindDesignDimensions(base))
    if (d.kind == DesignDimension::Kind::kCapHeight) {
      e.cap_fit_mm = MeasureDesignDimension(r.fitted, d);
      e.cap_graded_mm = MeasureDesignDimension(r.graded, d);
      e.cap_draft_mm = MeasureDesignDimension(direct, d);
      break;
    }
  for (size_t b = 0; b < base.bindings.size(); ++b)
    e.grading_max_binding_error_mm =
        std::max(e.grading_max_binding_error_mm,
                 std::abs(BindingValue(r.seed, base.bindings[b]) - r.targets_mm[b]));
  e.time_s = r.ga_time_s + r.polish_time_s;
  e.polish_start = r.polish_start;
  if (patterns) *patterns = FitPatterns{r.fitted, direct, r.seed};
  return e;
}

}  // namespace bespoke
