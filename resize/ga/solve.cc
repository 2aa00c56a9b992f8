#include "resize/ga/solve.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

// Selection of the free genes: genes x free columns.
Sparse Selection(const BlockSet& blocks, const std::vector<bool>& free) {
  std::vector<Eigen::Triplet<double>> t;
  int col = 0;
  for (size_t k = 0; k < blocks.blocks.size(); ++k) {
    if (!free[k]) continue;
    const Block& b = blocks.blocks[k];
    for (int g = 0; g < 2 * b.nu * b.nv; ++g) t.emplace_back(b.offset + g, col++, 1.0);
  }
  Sparse p(blocks.num_genes, col);
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

using Bounds = std::vector<FitnessModel::TurningBound>;

struct State {
  Eigen::VectorXd x, f, shares, c;
  Sparse jc, js;
  double Objective() const { return f.squaredNorm() + shares.squaredNorm(); }
};

void Evaluate(const FitnessModel& model, const Sparse& s, const Eigen::VectorXd& target,
              double share_weight, const Bounds& bounds, bool jacobians, State* st) {
  st->f = s * st->x - target;
  model.Constraints(st->x, &st->c, jacobians ? &st->jc : nullptr);
  if (!bounds.empty()) {
    Eigen::VectorXd cb;
    Sparse jb;
    model.CurveConstraints(st->x, bounds, &cb, jacobians ? &jb : nullptr);
    Eigen::VectorXd c(st->c.size() + cb.size());
    c << st->c, cb;
    st->c = c;
    if (jacobians) {
      Sparse j(st->jc.rows() + jb.rows(), st->jc.cols());
      std::vector<Eigen::Triplet<double>> t;
      for (const Sparse* m : {&st->jc, &jb}) {
        const Eigen::Index offset = m == &jb ? st->jc.rows() : 0;
        for (int k = 0; k < m->outerSize(); ++k)
          for (Sparse::InnerIterator it(*m, k); it; ++it)
            t.emplace_back(it.row() + offset, it.col(), it.value());
      }
      j.setFromTriplets(t.begin(), t.end());
      st->jc = std::move(j);
    }
  }
  if (share_weight > 0)
    model.Shares(st->x, share_weight, &st->shares, jacobians ? &st->js : nullptr);
  else
    st->shares.resize(0);
}

bool Valid(const SolveOptions& o, const FitnessModel& model, const std::vector<bool>& free,
           const Eigen::VectorXd& x) {
  const BlockSet& blocks = model.blocks();
  for (size_t k = 0; k < blocks.blocks.size(); ++k) {
    if (!free[k]) continue;
    if (!BlockValid(blocks.blocks[k], x.data(), o.min_gap_mm)) return false;
    if (o.check_simple) {
      Outline outline;
      EvalOutline(blocks.blocks[k], x.data(), &outline);
      if (FindSelfIntersection(outline).first >= 0) return false;
    }
  }
  return true;
}

// A factorisation whose fill-reducing ordering (AMD, a good part of the
// cost) is computed again only when the matrix's sparsity pattern changes:
// the normal matrix keeps its pattern from one Gauss-Newton step to the
// next. The same ordering gives the same factors as a fresh SimplicialLDLT.
struct Factor {
  Eigen::SimplicialLDLT<Sparse> ldlt;
  std::vector<Sparse::StorageIndex> outer, inner;  // the analysed pattern
};

void Factorize(const Sparse& h, Factor* f) {
  const auto* outer = h.outerIndexPtr();
  const auto* inner = h.innerIndexPtr();
  const bool same = f->outer.size() == static_cast<size_t>(h.outerSize() + 1) &&
                    std::equal(f->outer.begin(), f->outer.end(), outer) &&
                    f->inner.size() == static_cast<size_t>(h.nonZeros()) &&
                    std::equal(f->inner.begin(), f->inner.end(), inner);
  if (!same) {
    f->ldlt.analyzePattern(h);
    f->outer.assign(outer, outer + h.outerSize() + 1);
    f->inner.assign(inner, inner + h.nonZeros());
  }
  f->ldlt.factorize(h);
}

// ldlt^-1 rhs, blocks of columns solved in parallel (each column is solved
// on its own either way, so the result does not depend on the threads).
Eigen::MatrixXd SolveColumns(const Eigen::SimplicialLDLT<Sparse>& ldlt,
                             const Eigen::MatrixXd& rhs) {
  Eigen::MatrixXd out(rhs.rows(), rhs.cols());
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, rhs.cols(), 16),
                    [&](const tbb::blocked_range<Eigen::Index>& r) {
                      const Eigen::Index c = r.begin(), w = r.end() - r.begin();
                      out.middleCols(c, w) = ldlt.solve(rhs.middleCols(c, w));
                    });
  return out;
}

}  // namespace

void SolveOptions::Check() const {
  if (max_iterations < 0 || !(tolerance_mm > 0) || !(min_gap_mm > 0) || !(share_weight >= 0) ||
      !(regularisation >= 0))
    throw InputError("solver options: iterations >= 0, tolerance and gap > 0, weights >= 0");
}

namespace {

// Constrained Gauss-Newton with a fixed set of curve bounds.
SolveReport Solve(const SolveOptions& o, const FitnessModel& model, const Sparse& s,
                  const Eigen::VectorXd& target, const std::vector<bool>& free,
                  const Bounds& bounds, Eigen::VectorXd* genes) {
  const Sparse p = Selection(model.blocks(), free);
  const Sparse sp = s * p;
  const Sparse sts = sp.transpose() * sp;
  State st;
  st.x = *genes;
  Evaluate(model, s, target, o.share_weight, bounds, true, &st);
  SolveReport report;
  report.max_constraint_before_mm = st.c.size() ? st.c.cwiseAbs().maxCoeff() : 0.0;
  const Eigen::Index n = p.cols(), m = st.c.size();
  double rho = 1;  // exact-penalty weight, kept above the multipliers
  auto merit = [&](const State& z) { return z.Objective() + rho * z.c.lpNorm<1>(); };
  double damping = 0;
  Factor factor;
  for (int it = 0; it < o.max_iterations && n > 0; ++it) {
    report.iterations = it + 1;
    const Sparse jc = st.jc * p;
    Sparse h = sts;
    Eigen::VectorXd g = sp.transpose() * st.f;
    if (st.shares.size() > 0) {
      const Sparse js = st.js * p;
      h += Sparse(js.transpose() * js);
      g += js.transpose() * st.shares;
    }
    bool accepted = false;
    for (int attempt = 0; attempt < 6 && !accepted; ++attempt) {
      Sparse hd = h;
      for (Eigen::Index k = 0; k < n; ++k) hd.coeffRef(k, k) += o.regularisation + damping;
      hd.makeCompressed();
      Factorize(hd, &factor);
      const Eigen::SimplicialLDLT<Sparse>& ldlt = factor.ldlt;
      if (ldlt.info() != Eigen::Success) {
        damping = std::max(1e-6, 10 * damping);
        continue;
      }
      const Eigen::VectorXd u = ldlt.solve(g);
      Eigen::VectorXd dx = -u;
      if (m > 0) {
        const Eigen::MatrixXd z = SolveColumns(ldlt, Eigen::MatrixXd(jc.transpose()));
        Eigen::MatrixXd schur = jc * z;
        schur.diagonal().array() += 1e-9 * (1 + schur.diagonal().cwiseAbs().maxCoeff());
        const Eigen::VectorXd y = schur.ldlt().solve(st.c - jc * u);
        if (!y.allFinite()) {
          damping = std::max(1e-6, 10 * damping);
          continue;
        }
        rho = std::max(rho, 2 * y.cwiseAbs().maxCoeff() + 1e-3);
        dx -= z * y;
      }
      const double before = merit(st);
      for (double alpha = 1.0; alpha > 1e-4 && !accepted; alpha *= 0.5) {
        State trial;
        trial.x = st.x + alpha * (p * dx);
        if (!Valid(o, model, free, trial.x)) continue;
        Evaluate(model, s, target, o.share_weight, bounds, false, &trial);
        const double after = merit(trial);
        if (after < before) {
          const double moved = (alpha * dx).cwiseAbs().maxCoeff();
          st.x = trial.x;
          Evaluate(model, s, target, o.share_weight, bounds, true, &st);
          accepted = true;
          damping *= 0.1;
          // Converged: constraints met and the step or the gain negligible.
          if (st.c.cwiseAbs().maxCoeff() < o.tolerance_mm &&
              (moved < 1e-3 || before - after < 1e-6 * (1 + before)))
            it = o.max_iterations;
        }
      }
      if (!accepted) damping = std::max(1e-6, 100 * damping);
    }
    if (!accepted) break;
  }
  report.max_constraint_after_mm = m > 0 ? st.c.cwiseAbs().maxCoeff() : 0.0;
  report.objective = st.Objective();
  *genes = st.x;
  return report;
}

}  // namespace

SolveReport SolveConstrained(const SolveOptions& o, const FitnessModel& model, const Sparse& s,
                             const Eigen::VectorXd& target, const std::vector<bool>& free,
                             Eigen::VectorXd* genes) {
  o.Check();
  Bounds bounds;
  SolveReport report = Solve(o, model, s, target, free, bounds, genes);
  const double before = report.max_constraint_before_mm;
  for (int round = 0; round < 4 && o.keep_curves; ++round) {
    const Bounds more = model.CurveViolations(*genes);
    if (more.empty()) break;
    bounds.insert(bounds.end(), more.begin(), more.end());
    report = Solve(o, model, s, target, free, bounds, genes);
  }
  report.max_constraint_before_mm = before;
  report.curve_bounds = static_cast<int>(bounds.size());
  return report;
}

}  // namespace bespoke
