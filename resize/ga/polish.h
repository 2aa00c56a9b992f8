// Final polish of the GA's pick (a deviation from the thesis, which stops at
// the GA and reports measurement errors of 1.8-2.9): the pick is projected
// onto the constraints, i.e. the nearest pattern that meets every binding,
// every seam's total length and every structure rule exactly, near in the
// grid energy of the change from the pick (grid_energy.h), so a correction
// spreads smoothly over the grid instead of pulling single points:
//
//   minimise   |S (genes - genes_pick)|^2
//   subject to FitnessModel::Constraints(genes) = 0
//
// solved by constrained Gauss-Newton on the pieces a binding or seam reaches
// (solve.h).
#ifndef BESPOKE_RESIZE_GA_POLISH_H_
#define BESPOKE_RESIZE_GA_POLISH_H_

#include <Eigen/Core>

#include "resize/ga/grid_energy.h"
#include "resize/ga/objectives.h"

namespace bespoke {

struct PolishOptions {
  GridEnergyOptions energy;    // the metric of the correction (grid_energy.h)
  int max_iterations = 30;     // Gauss-Newton steps. Default 30.
  double tolerance_mm = 0.01;  // constraint tolerance (mm). Default 0.01 mm.
  double min_gap_mm = 0.1;     // grid ordering gap (mm). Default 0.1 mm.
  void Check() const;          // InputError for values out of range
};

struct PolishReport {
  int iterations = 0;
  double max_constraint_before_mm = 0;
  double max_constraint_after_mm = 0;
  double change = 0;  // |S (genes - genes_pick)|^2 at the end (grid energy of the correction)
};

// Polishes `genes` (#genes, mm) in place.
PolishReport Polish(const PolishOptions& options, const FitnessModel& model,
                    Eigen::VectorXd* genes);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_POLISH_H_
