// Constrained Gauss-Newton (sequential quadratic programming) on control
// grids, shared by the graded start (grader.h) and the polish (polish.h):
//
//   minimise   |S genes - target|^2 + |shares(genes)|^2
//   subject to FitnessModel::Constraints(genes) = 0  (bindings, seams, structure)
//              and, with keep_curves, every curve keeping its inflections
//              (FitnessModel::CurveViolations: the vertices that break the
//              rule are held at their bounds and the problem solved again,
//              up to 4 rounds; an active-set method for the inequalities)
//
// moving only the genes of the pieces marked free. S is a fixed sparse
// matrix (grid_energy.h), shares are FitnessModel::Shares with
// `share_weight` (0 = none). Each step solves the linearised problem's KKT
// system through the Schur complement of the sparse normal matrix (analytic
// Jacobians, so the cost follows the free control points, not their square);
// steps are shortened until an exact-penalty merit |residuals|^2 +
// rho |constraints|_1 falls, every free grid stays ordered and (optionally)
// every free outline simple; Levenberg-Marquardt damping is added when no
// step length is accepted.
#ifndef BESPOKE_RESIZE_GA_SOLVE_H_
#define BESPOKE_RESIZE_GA_SOLVE_H_

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "resize/ga/objectives.h"

namespace bespoke {

struct SolveOptions {
  int max_iterations = 30;       // Gauss-Newton steps. Default 30.
  double tolerance_mm = 0.01;    // constraint tolerance (mm). Default 0.01 mm.
  double min_gap_mm = 0.1;       // grid ordering gap kept (mm). Default 0.1 mm.
  double share_weight = 0;       // weight of the share residuals (0 = none). Default 0.
  double regularisation = 1e-9;  // added to the normal matrix's diagonal. Default 1e-9.
  bool check_simple = true;  // refuse steps that make a free outline self-intersect. Default on.
  bool keep_curves = true;   // no new inflections (see above). Default on.
  void Check() const;        // InputError for values out of range
};

struct SolveReport {
  int iterations = 0;
  double max_constraint_before_mm = 0;
  double max_constraint_after_mm = 0;
  double objective = 0;  // |S genes - target|^2 + |shares|^2 at the end
  int curve_bounds = 0;  // curve vertices held at their bounds
};

// `s`: #rows x #genes, `target`: #rows, `free`: one flag per piece; `genes`
// (#genes, mm) is the start and receives the answer.
SolveReport SolveConstrained(const SolveOptions& options, const FitnessModel& model,
                             const Eigen::SparseMatrix<double>& s, const Eigen::VectorXd& target,
                             const std::vector<bool>& free, Eigen::VectorXd* genes);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_SOLVE_H_
