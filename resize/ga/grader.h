// The graded start: the base pattern graded to the body the way a grader
// grades, before the GA and the polish refine it.
//
// A grader moves a piece's cardinal points in x and y by grade rules that
// change smoothly over the piece; lines along the grid stay straight and
// level, so chest, waist and hem lines stay perpendicular to a vertical
// grain and folds and square corners stay. Here every driven piece's
// control grid (block.h) moves so as to minimise the grid energy
// (grid_energy.h: a smooth stretch, rows and columns stretched alike, edges
// keeping their direction), plus, for every binding with several terms,
// share_weight x (term / base term - target / base value)^2 (a girth's
// change shared by its pieces in proportion, as proportional grading
// shares it), subject to every binding, every seam's total length and every
// structure rule (folds, level lines, grain lines, square corners, darts)
// being met (solve.h). A grid that only needs its lines moved as a whole
// stays rectilinear (x' = f(x), y' = g(y)); where the bindings ask more (a
// waist that grows faster than the chest takes out a side seam's
// suppression), the change spreads smoothly over the grid. An interval no
// binding reaches takes the stretch of its bound neighbours; a piece's axis
// nothing drives follows its other axis (the isotropy term); a piece no
// binding or seam reaches is not touched.
#ifndef BESPOKE_RESIZE_GA_GRADER_H_
#define BESPOKE_RESIZE_GA_GRADER_H_

#include <Eigen/Core>

#include "resize/ga/grid_energy.h"
#include "resize/ga/objectives.h"

namespace bespoke {

struct GraderOptions {
  GridEnergyOptions energy;  // the smoothness of the grade (grid_energy.h)
  // Weight keeping every term of a several-term binding at the binding's own
  // ratio (a girth's change shared by its pieces in proportion). Default 1.
  double share_weight = 1;
  int max_iterations = 40;     // Gauss-Newton steps. Default 40.
  double tolerance_mm = 0.01;  // constraint tolerance (mm). Default 0.01 mm.
  double min_gap_mm = 0.1;     // grid ordering gap (mm). Default 0.1 mm.
  void Check() const;          // InputError for values out of range
};

struct GradeResult {
  Eigen::VectorXd genes;         // the graded control grids (model.blocks() layout, mm)
  double max_constraint_mm = 0;  // largest binding, seam or structure error left (mm)
  int iterations = 0;
};

// Grades model.base() to the model's targets, starting from its base grids.
GradeResult Grade(const GraderOptions& options, const FitnessModel& model);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_GRADER_H_
