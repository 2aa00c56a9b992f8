#include "resize/ga/polish.h"

#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <cmath>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

struct Eval {
  Eigen::VectorXd c, s;
};

// Grid intervals of the GA's pick (x0): a barrier keeps every interval above
// 30 % of its starting width, so Gauss-Newton steps do not run into the
// ordering rule (which the line search enforces strictly).
std::vector<double> Gaps(const BlockSet& blocks, const Eigen::VectorXd& x) {
  std::vector<double> gaps;
  for (const Block& b : blocks.blocks) {
    const double* g = x.data() + b.offset;
    for (int j = 0; j < b.nv; ++j)
      for (int i = 0; i + 1 < b.nu; ++i)
        gaps.push_back(g[2 * (j * b.nu + i + 1)] - g[2 * (j * b.nu + i)]);
    for (int i = 0; i < b.nu; ++i)
      for (int j = 0; j + 1 < b.nv; ++j)
        gaps.push_back(g[2 * ((j + 1) * b.nu + i) + 1] - g[2 * (j * b.nu + i) + 1]);
  }
  return gaps;
}

// |soft residuals|^2 at `x` (PolishReport::soft_after).
double SoftObjective(const FitnessModel& model, const PolishOptions& o, const Eigen::VectorXd& x) {
  Eigen::VectorXd c, soft;
  model.Residuals(x, o.angle_scale_mm, o.length_scale_mm, &c, &soft);
  return soft.squaredNorm();
}

Eval Residuals(const FitnessModel& model, const PolishOptions& o, const Eigen::VectorXd& x,
               const std::vector<double>& gaps0, int only_piece = -1,
               const Eigen::VectorXd* reuse_soft = nullptr) {
  Eval e;
  model.Residuals(x, o.angle_scale_mm, o.length_scale_mm, &e.c, &e.s, only_piece, reuse_soft);
  const std::vector<double> gaps = Gaps(model.blocks(), x);
  const Eigen::Index k = e.s.size();
  e.s.conservativeResize(k + static_cast<Eigen::Index>(gaps.size()));
  constexpr double kBarrierMm = 10;
  for (size_t i = 0; i < gaps.size(); ++i) {
    const double floor = 0.3 * gaps0[i];
    e.s[k + static_cast<Eigen::Index>(i)] =
        gaps[i] >= floor ? 0.0 : kBarrierMm * (floor / std::max(gaps[i], 1e-9) - 1.0);
  }
  return e;
}

bool Valid(const FitnessModel& model, const PolishOptions& o, const Eigen::VectorXd& x) {
  for (const Block& b : model.blocks().blocks)
    if (!BlockValid(b, x.data(), o.min_gap_mm)) return false;
  return model.Evaluate(x, true).simple;
}

double Merit(const Eval& e, const Eigen::VectorXd& x, const Eigen::VectorXd& x0,
             const PolishOptions& o) {
  constexpr double kRho = 1e4;
  return e.s.squaredNorm() + o.regularisation * (x - x0).squaredNorm() + kRho * e.c.squaredNorm();
}

}  // namespace

void PolishOptions::Check() const {
  if (max_iterations < 0 || !(tolerance_mm > 0) || !(angle_scale_mm > 0) || !(regularisation > 0) ||
      !(min_gap_mm > 0) || !(length_scale_mm >= 0))
    throw InputError("polish options: iterations >= 0, length scale >= 0, other values > 0");
}

PolishReport Polish(const PolishOptions& o, const FitnessModel& model, Eigen::VectorXd* genes) {
  o.Check();
  PolishReport report;
  const Eigen::VectorXd x0 = *genes;
  Eigen::VectorXd x = x0;
  const std::vector<double> gaps0 = Gaps(model.blocks(), x0);
  Eval current = Residuals(model, o, x, gaps0);
  report.max_constraint_before_mm = current.c.size() ? current.c.cwiseAbs().maxCoeff() : 0.0;
  report.max_constraint_after_mm = report.max_constraint_before_mm;
  if (current.c.size() == 0) {
    report.soft_after = SoftObjective(model, o, x);
    return report;
  }
  const Eigen::Index n = x.size(), m = current.c.size(), k = current.s.size();
  std::vector<int> piece_of(n);  // which piece's block each control coordinate belongs to
  for (size_t b = 0; b < model.blocks().blocks.size(); ++b) {
    const Block& block = model.blocks().blocks[b];
    for (int g = 0; g < 2 * block.nu * block.nv; ++g)
      piece_of[block.offset + g] = static_cast<int>(b);
  }
  double last_step = 0;
  for (int it = 0; it < o.max_iterations; ++it) {
    report.iterations = it + 1;
    // Jacobians by forward differences, one column per control coordinate.
    Eigen::MatrixXd jc(m, n), js(k, n);
    const double h = 1e-5;
    tbb::parallel_for(Eigen::Index(0), n, [&](Eigen::Index j) {
      Eigen::VectorXd xp = x;
      xp[j] += h;
      const Eval ep = Residuals(model, o, xp, gaps0, piece_of[j], &current.s);
      jc.col(j) = (ep.c - current.c) / h;
      js.col(j) = (ep.s - current.s) / h;
    });
    // KKT system of: min |s + Js d|^2 + mu |x + d - x0|^2  s.t.  c + Jc d = 0.
    // When no step length is accepted (merit, ordering, self-intersection),
    // the step is recomputed with Levenberg-Marquardt damping added.
    const Eigen::MatrixXd jtj = js.transpose() * js;
    Eigen::VectorXd rhs(n + m);
    rhs.head(n) = -(js.transpose() * current.s + o.regularisation * (x - x0));
    rhs.tail(m) = -current.c;
    const double merit = Merit(current, x, x0, o);
    bool accepted = false;
    for (double damping : {0.0, 1e-2, 1.0, 1e2, 1e4}) {
      Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
      kkt.topLeftCorner(n, n) = jtj;
      kkt.topLeftCorner(n, n).diagonal().array() += o.regularisation + damping;
      kkt.topRightCorner(n, m) = jc.transpose();
      kkt.bottomLeftCorner(m, n) = jc;
      kkt.bottomRightCorner(m, m).diagonal().array() -= 1e-9;  // redundant constraints
      Eigen::VectorXd step = kkt.partialPivLu().solve(rhs).head(n);
      if (!step.allFinite()) step = kkt.fullPivLu().solve(rhs).head(n);
      if (!step.allFinite()) continue;
      for (double alpha = 1.0; alpha > 1e-3 && !accepted; alpha *= 0.5) {
        const Eigen::VectorXd trial = x + alpha * step;
        const Eval e = Residuals(model, o, trial, gaps0);
        if (Merit(e, trial, x0, o) < merit && Valid(model, o, trial)) {
          last_step = (alpha * step).cwiseAbs().maxCoeff();
          x = trial;
          current = e;
          accepted = true;
        }
      }
      if (accepted) break;
    }
    if (!accepted) break;
    report.max_constraint_after_mm = current.c.cwiseAbs().maxCoeff();
    if (report.max_constraint_after_mm < o.tolerance_mm && last_step < 1e-3) break;
  }
  report.max_constraint_after_mm = current.c.cwiseAbs().maxCoeff();
  report.soft_after = SoftObjective(model, o, x);
  *genes = x;
  return report;
}

}  // namespace bespoke
