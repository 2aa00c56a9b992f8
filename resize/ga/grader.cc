#include "resize/ga/grader.h"

#include "resize/ga/solve.h"
#include "scanners/core/errors.h"

namespace bespoke {

void GraderOptions::Check() const {
  energy.Check();
  if (!(share_weight >= 0) || max_iterations < 0 || !(tolerance_mm > 0) || !(min_gap_mm > 0))
    throw InputError("grader options: share weight >= 0, iterations >= 0, tolerance and gap > 0");
}

GradeResult Grade(const GraderOptions& o, const FitnessModel& model) {
  o.Check();
  Eigen::SparseMatrix<double> s;
  Eigen::VectorXd target;
  GridEnergy(o.energy, model.blocks(), model.Driven(), &s, &target);
  SolveOptions solve;
  solve.max_iterations = o.max_iterations;
  solve.tolerance_mm = o.tolerance_mm;
  solve.min_gap_mm = o.min_gap_mm;
  solve.share_weight = o.share_weight;
  GradeResult result;
  result.genes = model.blocks().base_genes;
  const SolveReport report =
      SolveConstrained(solve, model, s, target, model.Driven(), &result.genes);
  result.max_constraint_mm = report.max_constraint_after_mm;
  result.iterations = report.iterations;
  return result;
}

}  // namespace bespoke
