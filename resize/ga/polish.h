// Final polish of the GA's pick (a deviation from the thesis, which stops at
// the GA and reports measurement errors of 1.8-2.9): constrained Gauss-Newton
// (sequential quadratic programming) on the control points.
//
//   minimise   |soft(x)|^2 + mu |x - x_pick|^2
//   subject to constraints(x) = 0
// where constraints are every binding's error and every seam's total length
// mismatch (mm) and soft residuals are the shape, paired-seam and relative
// edge-length terms of FitnessModel::Residuals. Each step solves the KKT system of the linearised
// problem (Jacobians by forward differences); steps are halved until the
// merit |soft|^2 + rho |constraints|^2 falls and the grid stays ordered and
// no outline self-intersects. Stops when the largest constraint is below
// `tolerance_mm` and the step is tiny, or after `max_iterations`.
#ifndef BESPOKE_RESIZE_GA_POLISH_H_
#define BESPOKE_RESIZE_GA_POLISH_H_

#include <Eigen/Core>

#include "resize/ga/objectives.h"

namespace bespoke {

struct PolishOptions {
  int max_iterations = 60;       // default 60
  double tolerance_mm = 0.01;    // constraint tolerance (mm). Default 0.01 mm.
  double angle_scale_mm = 100;   // mm per radian of turning-angle change. Default 100.
  double regularisation = 1e-4;  // mu, keeps unused control points put. Default 1e-4.
  // mm per unit of relative edge-length change (length / base length - 1):
  // keeps the design's dimensions that no binding or seam asks to change (a
  // drafting system's fixed hem widths, band depths, overlaps, ...) and lets
  // long edges rather than short ones absorb a change. 0 = off. Default 30.
  double length_scale_mm = 30;
  double min_gap_mm = 0.1;  // grid ordering gap. Default 0.1 mm.
  void Check() const;       // InputError for non-positive values (length_scale_mm may be 0)
};

struct PolishReport {
  int iterations = 0;
  double max_constraint_before_mm = 0;
  double max_constraint_after_mm = 0;
  // |soft residuals|^2 of FitnessModel::Residuals at the end (mm^2; without
  // the ordering barrier and the pull to the start): what the polish
  // minimises, comparable between starts.
  double soft_after = 0;
};

// Polishes `genes` in place.
PolishReport Polish(const PolishOptions& options, const FitnessModel& model,
                    Eigen::VectorXd* genes);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_POLISH_H_
