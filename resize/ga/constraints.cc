// FitnessModel's hard constraints and share residuals, with their Jacobians
// (objectives.h). Every point of a piece is a fixed weighted sum of control
// points (its stencil), so d / d genes = (d / d point) x stencil weights.
#include <cmath>

#include "resize/ga/objectives.h"

namespace bespoke {
namespace {

double WrapAngle(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}

// d angle(e) / d e for the direction angle of a 2-vector.
Eigen::Vector2d AngleGradient(const Eigen::Vector2d& e) {
  return Eigen::Vector2d(-e.y(), e.x()) / std::max(e.squaredNorm(), 1e-18);
}

Eigen::Vector2d Unit(const Eigen::Vector2d& e) { return e / std::max(e.norm(), 1e-12); }

constexpr double kCornerScaleMm = 100;  // mm of residual per radian of a square corner's change

// Collects one row's gradient with respect to points, spread over genes.
class RowWriter {
 public:
  explicit RowWriter(std::vector<Eigen::Triplet<double>>* t) : t_(t) {}
  void Row(int row) { row_ = row; }
  void Add(const std::vector<std::pair<int, double>>& stencil, const Eigen::Vector2d& g) {
    if (t_ == nullptr) return;
    for (const auto& [c, w] : stencil) {
      t_->emplace_back(row_, 2 * c, w * g.x());
      t_->emplace_back(row_, 2 * c + 1, w * g.y());
    }
  }

 private:
  std::vector<Eigen::Triplet<double>>* t_;
  int row_ = 0;
};

// Length of the polyline through `path` on `o`, its gradient written.
template <typename StencilOf>
double PathLength(const Outline& o, const std::vector<int>& path, double scale, RowWriter* w,
                  const StencilOf& stencil) {
  double length = 0;
  for (size_t k = 0; k + 1 < path.size(); ++k) {
    const Eigen::Vector2d e = o.row(path[k + 1]) - o.row(path[k]);
    length += e.norm();
    const Eigen::Vector2d u = scale * Unit(e);
    w->Add(stencil(path[k + 1]), u);
    w->Add(stencil(path[k]), -u);
  }
  return length;
}

double ChainLength(const Outline& o, const std::vector<int>& path) {
  double length = 0;
  for (size_t k = 0; k + 1 < path.size(); ++k)
    length += (o.row(path[k + 1]) - o.row(path[k])).norm();
  return length;
}

}  // namespace

void FitnessModel::Structure(const Eigen::VectorXd& genes, const std::vector<Outline>& outlines,
                             std::vector<double>* out) const {
  for (const Direction& d : directions_) {
    const Eigen::Vector2d e =
        Point(d.piece, d.b, genes, outlines) - Point(d.piece, d.a, genes, outlines);
    out->push_back(d.unit.x() * e.y() - d.unit.y() * e.x());
  }
  for (size_t c = 0; c < corners_.size(); ++c) {
    const Outline& o = outlines[corners_[c].first];
    const int n = static_cast<int>(o.rows()), v = corners_[c].second;
    const Eigen::Vector2d e0 = o.row(v) - o.row((v - 1 + n) % n),
                          e1 = o.row((v + 1) % n) - o.row(v);
    const double turning = std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
    out->push_back(WrapAngle(turning - corner_turning_[c]) * kCornerScaleMm);
  }
  for (const auto& [p, d] : darts_) {
    const Outline& o = outlines[p];
    out->push_back((o.row(d.leg_a) - o.row(d.apex)).norm() -
                   (o.row(d.leg_b) - o.row(d.apex)).norm());
  }
  for (const Collinear& l : collinear_) {
    const Outline& o = outlines[l.piece];
    const Eigen::Vector2d d = o.row(l.b) - o.row(l.a), q = o.row(l.v) - o.row(l.a);
    out->push_back((d.x() * q.y() - d.y() * q.x()) / std::max(d.norm(), 1e-12));
  }
  for (const NotchData& d : notches_)
    out->push_back((1 - d.fraction) * ChainLength(outlines[d.piece], d.before) -
                   d.fraction * ChainLength(outlines[d.piece], d.after));
}

void FitnessModel::Constraints(const Eigen::VectorXd& genes, Eigen::VectorXd* constraints,
                               Eigen::SparseMatrix<double>* jacobian) const {
  thread_local std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<Eigen::Triplet<double>> triplets;
  RowWriter w(jacobian ? &triplets : nullptr);
  std::vector<double> c;
  auto stencil_of = [&](int piece) {
    return [this, piece](int point) -> const Stencil& { return stencils_[piece][point]; };
  };
  for (size_t b = 0; b < terms_.size(); ++b) {
    w.Row(static_cast<int>(c.size()));
    double value = 0;
    for (const TermData& t : terms_[b]) {
      if (!t.path.empty()) {
        value += t.multiplicity *
                 PathLength(outlines[t.piece], t.path, t.multiplicity, &w, stencil_of(t.piece));
        continue;
      }
      const Eigen::Vector2d e =
          Point(t.piece, t.a, genes, outlines) - Point(t.piece, t.b, genes, outlines);
      value += t.multiplicity * e.norm();
      w.Add(stencils_[t.piece][t.a], t.multiplicity * Unit(e));
      w.Add(stencils_[t.piece][t.b], -t.multiplicity * Unit(e));
    }
    c.push_back(value - targets_[b]);
  }
  for (const SeamData& d : seams_) {
    w.Row(static_cast<int>(c.size()));
    const double la = PathLength(outlines[d.piece_a], d.a, 1, &w, stencil_of(d.piece_a));
    const double lb = PathLength(outlines[d.piece_b], d.b, -1, &w, stencil_of(d.piece_b));
    c.push_back(la - lb - d.ease);
  }
  for (const Direction& d : directions_) {
    w.Row(static_cast<int>(c.size()));
    const Eigen::Vector2d e =
        Point(d.piece, d.b, genes, outlines) - Point(d.piece, d.a, genes, outlines);
    c.push_back(d.unit.x() * e.y() - d.unit.y() * e.x());
    const Eigen::Vector2d g(-d.unit.y(), d.unit.x());
    w.Add(stencils_[d.piece][d.b], g);
    w.Add(stencils_[d.piece][d.a], -g);
  }
  for (size_t k = 0; k < corners_.size(); ++k) {
    w.Row(static_cast<int>(c.size()));
    const auto [p, v] = corners_[k];
    const Outline& o = outlines[p];
    const int n = static_cast<int>(o.rows()), u = (v - 1 + n) % n, x = (v + 1) % n;
    const Eigen::Vector2d e0 = o.row(v) - o.row(u), e1 = o.row(x) - o.row(v);
    const double turning = std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
    c.push_back(WrapAngle(turning - corner_turning_[k]) * kCornerScaleMm);
    const Eigen::Vector2d g0 = kCornerScaleMm * AngleGradient(e0),
                          g1 = kCornerScaleMm * AngleGradient(e1);
    w.Add(stencils_[p][x], g1);
    w.Add(stencils_[p][v], -g1 - g0);
    w.Add(stencils_[p][u], g0);
  }
  for (const auto& [p, d] : darts_) {
    w.Row(static_cast<int>(c.size()));
    const Outline& o = outlines[p];
    const Eigen::Vector2d ea = o.row(d.leg_a) - o.row(d.apex), eb = o.row(d.leg_b) - o.row(d.apex);
    c.push_back(ea.norm() - eb.norm());
    w.Add(stencils_[p][d.leg_a], Unit(ea));
    w.Add(stencils_[p][d.leg_b], -Unit(eb));
    w.Add(stencils_[p][d.apex], Unit(eb) - Unit(ea));
  }
  for (const Collinear& l : collinear_) {
    w.Row(static_cast<int>(c.size()));
    const Outline& o = outlines[l.piece];
    const Eigen::Vector2d d = o.row(l.b) - o.row(l.a), q = o.row(l.v) - o.row(l.a);
    const double length = std::max(d.norm(), 1e-12), cross = d.x() * q.y() - d.y() * q.x();
    c.push_back(cross / length);
    const Eigen::Vector2d gq = Eigen::Vector2d(-d.y(), d.x()) / length;
    const Eigen::Vector2d gd =
        Eigen::Vector2d(q.y(), -q.x()) / length - cross * d / (length * length * length);
    w.Add(stencils_[l.piece][l.v], gq);
    w.Add(stencils_[l.piece][l.b], gd);
    w.Add(stencils_[l.piece][l.a], -gd - gq);
  }
  for (const NotchData& d : notches_) {
    w.Row(static_cast<int>(c.size()));
    const double before =
        PathLength(outlines[d.piece], d.before, 1 - d.fraction, &w, stencil_of(d.piece));
    const double after =
        PathLength(outlines[d.piece], d.after, -d.fraction, &w, stencil_of(d.piece));
    c.push_back((1 - d.fraction) * before - d.fraction * after);
  }
  *constraints = Eigen::Map<Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size()));
  if (jacobian) {
    jacobian->resize(static_cast<Eigen::Index>(c.size()), genes.size());
    jacobian->setFromTriplets(triplets.begin(), triplets.end());
  }
}

void FitnessModel::CurveConstraints(const Eigen::VectorXd& genes,
                                    const std::vector<TurningBound>& bounds,
                                    Eigen::VectorXd* constraints,
                                    Eigen::SparseMatrix<double>* jacobian) const {
  thread_local std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<Eigen::Triplet<double>> triplets;
  RowWriter w(jacobian ? &triplets : nullptr);
  constraints->resize(static_cast<Eigen::Index>(bounds.size()));
  for (size_t k = 0; k < bounds.size(); ++k) {
    w.Row(static_cast<int>(k));
    const int p = bounds[k].piece, v = bounds[k].vertex;
    const Outline& o = outlines[p];
    const int n = static_cast<int>(o.rows()), u = (v - 1 + n) % n, x = (v + 1) % n;
    const Eigen::Vector2d e0 = o.row(v) - o.row(u), e1 = o.row(x) - o.row(v);
    const double turning = std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
    (*constraints)[static_cast<Eigen::Index>(k)] =
        WrapAngle(turning - bounds[k].bound_rad) * kCornerScaleMm;
    const Eigen::Vector2d g0 = kCornerScaleMm * AngleGradient(e0),
                          g1 = kCornerScaleMm * AngleGradient(e1);
    w.Add(stencils_[p][x], g1);
    w.Add(stencils_[p][v], -g1 - g0);
    w.Add(stencils_[p][u], g0);
  }
  if (jacobian) {
    jacobian->resize(static_cast<Eigen::Index>(bounds.size()), genes.size());
    jacobian->setFromTriplets(triplets.begin(), triplets.end());
  }
}

void FitnessModel::Shares(const Eigen::VectorXd& genes, double weight, Eigen::VectorXd* residuals,
                          Eigen::SparseMatrix<double>* jacobian) const {
  thread_local std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<Eigen::Triplet<double>> triplets;
  RowWriter w(jacobian ? &triplets : nullptr);
  std::vector<double> r;
  for (size_t b = 0; b < terms_.size(); ++b) {
    if (terms_[b].size() < 2) continue;
    double base_value = 0;
    for (const TermData& t : terms_[b]) base_value += t.multiplicity * t.base_length;
    const double ratio = targets_[b] / std::max(base_value, 1e-9);
    for (const TermData& t : terms_[b]) {
      w.Row(static_cast<int>(r.size()));
      const double scale = weight / std::max(t.base_length, 1e-9);
      double length;
      if (!t.path.empty()) {
        length = PathLength(outlines[t.piece], t.path, scale, &w,
                            [&](int point) -> const Stencil& { return stencils_[t.piece][point]; });
      } else {
        const Eigen::Vector2d e =
            Point(t.piece, t.a, genes, outlines) - Point(t.piece, t.b, genes, outlines);
        length = e.norm();
        w.Add(stencils_[t.piece][t.a], scale * Unit(e));
        w.Add(stencils_[t.piece][t.b], -scale * Unit(e));
      }
      r.push_back(scale * length - weight * ratio);
    }
  }
  *residuals = Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
  if (jacobian) {
    jacobian->resize(static_cast<Eigen::Index>(r.size()), genes.size());
    jacobian->setFromTriplets(triplets.begin(), triplets.end());
  }
}

}  // namespace bespoke
