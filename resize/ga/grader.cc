#include "resize/ga/grader.h"

#include <Eigen/LU>
#include <cmath>
#include <vector>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// One piece's grid in the grader's unknowns: z[offset .. offset + nu - 2] are
// the log ratios of its x intervals, the next nv - 1 those of its y intervals.
struct Chains {
  int offset = 0;
  std::vector<double> xs, ys;  // base grid lines (mm)
};

std::vector<Chains> Layout(const BlockSet& blocks, int* size) {
  std::vector<Chains> chains;
  int offset = 0;
  for (const Block& b : blocks.blocks) {
    Chains c;
    c.offset = offset;
    const double* g = blocks.base_genes.data() + b.offset;
    for (int i = 0; i < b.nu; ++i) c.xs.push_back(g[2 * i]);
    for (int j = 0; j < b.nv; ++j) c.ys.push_back(g[2 * (j * b.nu) + 1]);
    offset += (b.nu - 1) + (b.nv - 1);
    chains.push_back(std::move(c));
  }
  *size = offset;
  return chains;
}

// Stretched grid lines about the chain's centre.
std::vector<double> Stretch(const std::vector<double>& lines, const double* z) {
  std::vector<double> out(lines.size());
  double total = 0;
  out[0] = 0;
  for (size_t i = 0; i + 1 < lines.size(); ++i) {
    total += (lines[i + 1] - lines[i]) * std::exp(z[i]);
    out[i + 1] = total;
  }
  const double base_centre = 0.5 * (lines.front() + lines.back());
  for (double& v : out) v += base_centre - 0.5 * total;
  return out;
}

Eigen::VectorXd Genes(const BlockSet& blocks, const std::vector<Chains>& chains,
                      const Eigen::VectorXd& z) {
  Eigen::VectorXd genes = blocks.base_genes;
  for (size_t k = 0; k < blocks.blocks.size(); ++k) {
    const Block& b = blocks.blocks[k];
    const Chains& c = chains[k];
    const std::vector<double> xs = Stretch(c.xs, z.data() + c.offset);
    const std::vector<double> ys = Stretch(c.ys, z.data() + c.offset + b.nu - 1);
    for (int j = 0; j < b.nv; ++j)
      for (int i = 0; i < b.nu; ++i) {
        genes[b.offset + 2 * (j * b.nu + i)] = xs[i];
        genes[b.offset + 2 * (j * b.nu + i) + 1] = ys[j];
      }
  }
  return genes;
}

// The soft terms are linear in z: residual = S z.
Eigen::MatrixXd SoftMatrix(const GraderOptions& o, const BlockSet& blocks,
                           const std::vector<Chains>& chains, int size) {
  std::vector<Eigen::VectorXd> rows;
  auto row = [&]() {
    rows.push_back(Eigen::VectorXd::Zero(size));
    return &rows.back();
  };
  for (size_t k = 0; k < blocks.blocks.size(); ++k) {
    const Block& b = blocks.blocks[k];
    const int x0 = chains[k].offset, nx = b.nu - 1, y0 = x0 + nx, ny = b.nv - 1;
    for (auto [start, count] : {std::pair{x0, nx}, std::pair{y0, ny}})
      for (int i = 0; i + 1 < count; ++i) {
        Eigen::VectorXd* r = row();
        (*r)[start + i] = 1;
        (*r)[start + i + 1] = -1;
      }
    Eigen::VectorXd* iso = row();
    for (int i = 0; i < nx; ++i) (*iso)[x0 + i] = std::sqrt(o.isotropy_weight) / nx;
    for (int i = 0; i < ny; ++i) (*iso)[y0 + i] = -std::sqrt(o.isotropy_weight) / ny;
  }
  for (int i = 0; i < size; ++i) (*row())[i] = std::sqrt(o.prior_weight);
  Eigen::MatrixXd s(static_cast<Eigen::Index>(rows.size()), size);
  for (size_t r = 0; r < rows.size(); ++r) s.row(static_cast<Eigen::Index>(r)) = rows[r];
  return s;
}

// Per term of every binding with several terms: log(term length / its base
// length) - log(binding target / base value), so a girth's change is shared
// by its pieces in proportion, as proportional grading shares it.
Eigen::VectorXd Shares(const FitnessModel& model, const Eigen::VectorXd& genes,
                       const std::vector<double>& base_terms, double weight) {
  const Pattern fitted = ApplyGenes(model.base(), model.blocks(), genes);
  std::vector<double> r;
  size_t k = 0;
  const std::vector<double> targets = model.Targets();
  for (size_t b = 0; b < fitted.bindings.size(); ++b) {
    const MeasurementBinding& binding = fitted.bindings[b];
    if (binding.terms.size() < 2) continue;
    const double ratio = std::log(targets[b] / std::max(BindingValue(model.base(), binding), 1e-9));
    for (const BindingTerm& t : binding.terms) {
      const double length = TermLength(fitted.pieces[fitted.FindPiece(t.piece)], t);
      r.push_back(weight * (std::log(std::max(length, 1e-9) / base_terms[k++]) - ratio));
    }
  }
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

}  // namespace

void GraderOptions::Check() const {
  if (!(isotropy_weight >= 0) || !(prior_weight > 0) || max_iterations < 0 || !(tolerance_mm > 0))
    throw InputError("grader options: weights >= 0 (prior > 0), iterations >= 0, tolerance > 0");
}

GradeResult Grade(const GraderOptions& o, const FitnessModel& model) {
  o.Check();
  const BlockSet& blocks = model.blocks();
  int size = 0;
  const std::vector<Chains> chains = Layout(blocks, &size);
  const Eigen::MatrixXd soft = SoftMatrix(o, blocks, chains, size);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(size);
  std::vector<double> base_terms;
  for (const MeasurementBinding& b : model.base().bindings)
    if (b.terms.size() >= 2)
      for (const BindingTerm& t : b.terms)
        base_terms.push_back(
            std::max(TermLength(model.base().pieces[model.base().FindPiece(t.piece)], t), 1e-9));
  auto shares = [&](const Eigen::VectorXd& zz) {
    return Shares(model, Genes(blocks, chains, zz), base_terms, std::sqrt(o.share_weight));
  };
  auto constraints = [&](const Eigen::VectorXd& zz) {
    Eigen::VectorXd c;
    model.Constraints(Genes(blocks, chains, zz), &c);
    return c;
  };
  constexpr double kRho = 1e4;
  auto merit = [&](const Eigen::VectorXd& zz, const Eigen::VectorXd& c) {
    return (soft * zz).squaredNorm() + shares(zz).squaredNorm() + kRho * c.squaredNorm();
  };
  Eigen::VectorXd c = constraints(z);
  GradeResult result;
  const Eigen::Index m = c.size();
  for (int it = 0; it < o.max_iterations && m > 0; ++it) {
    result.iterations = it + 1;
    const Eigen::VectorXd sh = shares(z);
    Eigen::MatrixXd jc(m, size), js(sh.size(), size);
    const double h = 1e-6;
    for (int j = 0; j < size; ++j) {
      Eigen::VectorXd zp = z;
      zp[j] += h;
      jc.col(j) = (constraints(zp) - c) / h;
      js.col(j) = (shares(zp) - sh) / h;
    }
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(size + m, size + m);
    kkt.topLeftCorner(size, size) = soft.transpose() * soft + js.transpose() * js;
    kkt.topRightCorner(size, m) = jc.transpose();
    kkt.bottomLeftCorner(m, size) = jc;
    kkt.bottomRightCorner(m, m).diagonal().array() -= 1e-9;  // redundant constraints
    Eigen::VectorXd rhs(size + m);
    rhs.head(size) = -(soft.transpose() * (soft * z) + js.transpose() * sh);
    rhs.tail(m) = -c;
    const Eigen::VectorXd step = kkt.fullPivLu().solve(rhs).head(size);
    if (!step.allFinite()) break;
    const double before = merit(z, c);
    bool accepted = false;
    for (double alpha = 1.0; alpha > 1e-3 && !accepted; alpha *= 0.5) {
      const Eigen::VectorXd trial = z + alpha * step;
      const Eigen::VectorXd ct = constraints(trial);
      if (merit(trial, ct) < before) {
        z = trial;
        c = ct;
        accepted = true;
      }
    }
    if (!accepted) break;
    if (c.cwiseAbs().maxCoeff() < o.tolerance_mm && step.cwiseAbs().maxCoeff() < 1e-6) break;
  }
  result.genes = Genes(blocks, chains, z);
  result.max_constraint_mm = m > 0 ? c.cwiseAbs().maxCoeff() : 0.0;
  return result;
}

}  // namespace bespoke
