#include "resize/ga/polish.h"

#include "resize/ga/solve.h"
#include "scanners/core/errors.h"

namespace bespoke {

void PolishOptions::Check() const {
  energy.Check();
  if (max_iterations < 0 || !(tolerance_mm > 0) || !(min_gap_mm > 0))
    throw InputError("polish options: iterations >= 0, tolerance and gap > 0");
}

PolishReport Polish(const PolishOptions& o, const FitnessModel& model, Eigen::VectorXd* genes) {
  o.Check();
  Eigen::SparseMatrix<double> s;
  Eigen::VectorXd target;
  GridEnergy(o.energy, model.blocks(), model.Driven(), &s, &target);
  target = s * *genes;
  SolveOptions solve;
  solve.max_iterations = o.max_iterations;
  solve.tolerance_mm = o.tolerance_mm;
  solve.min_gap_mm = o.min_gap_mm;
  const SolveReport r = SolveConstrained(solve, model, s, target, model.Driven(), genes);
  PolishReport report;
  report.iterations = r.iterations;
  report.max_constraint_before_mm = r.max_constraint_before_mm;
  report.max_constraint_after_mm = r.max_constraint_after_mm;
  report.change = r.objective;
  return report;
}

}  // namespace bespoke
