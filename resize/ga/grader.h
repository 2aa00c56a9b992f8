// The graded start: the base pattern graded to the body the way a grader
// grades, before the GA and the polish refine it.
//
// Each piece's control grid (block.h) is kept rectilinear: its vertical grid
// lines move as a whole along x and its horizontal ones along y, so the
// piece is stretched by a piecewise-linear map x' = f(x), y' = g(y). That
// keeps lines along the grid straight and level (a chest, waist or hem line
// stays perpendicular to a vertical grain; folds and square corners stay),
// as grade rules that move cardinal points in x and y do. The unknowns are
// the log stretch ratios of every grid interval; the grader solves
//
//   minimise   sum over neighbouring intervals (log r_i - log r_{i+1})^2
//            + isotropy_weight x sum over pieces (mean log r_x - mean log r_y)^2
//            + prior_weight x sum (log r_i)^2
//            + share_weight x sum over terms of several-term bindings
//                (log(term / base term) - log(target / base value))^2
//   subject to every binding and every seam's total length being met
//
// by Gauss-Newton steps on the KKT system (constraint Jacobian by forward
// differences). The smoothness term makes an interval no binding reaches take
// the ratio of the nearest bound intervals along its chain (interpolated
// between them, constant beyond them); a piece's axis that no binding or seam
// drives follows its other axis (the isotropy term), and a piece nothing
// drives at all keeps its size (the prior).
#ifndef BESPOKE_RESIZE_GA_GRADER_H_
#define BESPOKE_RESIZE_GA_GRADER_H_

#include <Eigen/Core>

#include "resize/ga/objectives.h"

namespace bespoke {

struct GraderOptions {
  double isotropy_weight = 0.01;  // weight of the x / y ratio agreement per piece. Default 0.01.
  // Weight keeping every term of a several-term binding at the binding's own
  // ratio (a girth's change shared by its pieces in proportion). Default 1.
  double share_weight = 1;
  double prior_weight = 1e-4;  // weight pulling ratios to 1 (unchanged). Default 1e-4.
  int max_iterations = 30;     // Gauss-Newton steps. Default 30.
  double tolerance_mm = 0.01;  // constraint tolerance (mm). Default 0.01 mm.
  void Check() const;          // InputError for negative weights or tolerance <= 0
};

struct GradeResult {
  Eigen::VectorXd genes;         // the graded control grids (model.blocks() layout, mm)
  double max_constraint_mm = 0;  // largest binding or seam-length error left (mm)
  int iterations = 0;
};

// Grades model.base() to the model's targets.
GradeResult Grade(const GraderOptions& options, const FitnessModel& model);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_GRADER_H_
