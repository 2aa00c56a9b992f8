#include "resize/ga/objectives.h"

#include <cmath>

#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

constexpr double kDeg = 180.0 / M_PI;

double Turning(const Outline& o, const std::vector<int>& idx, size_t k) {
  const Eigen::Vector2d a = o.row(idx[k]) - o.row(idx[k - 1]);
  const Eigen::Vector2d b = o.row(idx[k + 1]) - o.row(idx[k]);
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

double WrapAngle(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}

// Edge lengths along a seam side.
void SeamEdges(const Outline& o, const std::vector<int>& idx, std::vector<double>* edges) {
  edges->resize(idx.size() - 1);
  for (size_t k = 0; k + 1 < idx.size(); ++k)
    (*edges)[k] = (o.row(idx[k + 1]) - o.row(idx[k])).norm();
}

}  // namespace

FitnessModel::FitnessModel(const Pattern& base, const BlockSet& blocks, const MeasurementSet& body,
                           const Pattern* structure)
    : base_(base), blocks_(blocks) {
  const Pattern& ref = structure ? *structure : base;
  for (size_t p = 0; p < ref.pieces.size(); ++p) {
    const Piece& piece = ref.pieces[p];
    const int k = static_cast<int>(p);
    for (const StraightRun& r : piece.straight)
      if (r.fold) {
        const Eigen::Vector2d d = piece.outline.row(r.to) - piece.outline.row(r.from);
        directions_.push_back({k, 0, r.from, r.to, d.normalized()});
      }
    for (const LevelLine& l : piece.level_lines) {
      const int a = piece.FindLandmark(l.from), b = piece.FindLandmark(l.to);
      const Eigen::Vector2d d = piece.LandmarkPosition(b) - piece.LandmarkPosition(a);
      directions_.push_back({k, 1, a, b, d.normalized()});
    }
    if (piece.has_grain)
      directions_.push_back({k, 2, 0, 0, (piece.grain_end - piece.grain_start).normalized()});
    const Eigen::VectorXd turning = TurningAngles(piece.outline);
    for (int v : piece.right_angles) {
      corners_.push_back({k, v});
      corner_turning_.push_back(turning[v]);
    }
    for (const Dart& d : piece.darts) darts_.push_back({k, d});
  }
  num_structure_ = static_cast<int>(directions_.size() + corners_.size() + darts_.size());
  for (const MeasurementBinding& b : base.bindings) targets_.push_back(BindingTarget(b, body));
  for (const Piece& piece : base.pieces) {
    base_turning_.push_back(TurningAngles(piece.outline));
    const Eigen::Index n = piece.outline.rows();
    Eigen::VectorXd direction(n), length(n);
    for (Eigen::Index v = 0; v < n; ++v) {
      const Eigen::Vector2d e = piece.outline.row((v + 1) % n) - piece.outline.row(v);
      direction[v] = std::atan2(e.y(), e.x());
      length[v] = std::max(e.norm(), 1e-3);  // guards the relative change below
    }
    base_direction_.push_back(direction);
    base_length_.push_back(length);
  }
  for (const Seam& seam : base.seams) {
    SeamData d;
    d.piece_a = base.FindPiece(seam.a.piece);
    d.piece_b = base.FindPiece(seam.b.piece);
    const Outline& oa = base.pieces[d.piece_a].outline;
    const Outline& ob = base.pieces[d.piece_b].outline;
    d.a = SeamIndices(seam.a, static_cast<int>(oa.rows()));
    d.b = SeamIndices(seam.b, static_cast<int>(ob.rows()));
    d.ease = seam.ease_mm;
    std::vector<double> la, lb;
    SeamEdges(oa, d.a, &la);
    SeamEdges(ob, d.b, &lb);
    double base_diff = 0;
    for (size_t k = 0; k < la.size(); ++k) base_diff += la[k] - lb[k];
    const double spread = (seam.ease_mm - base_diff) / static_cast<double>(la.size());
    for (size_t k = 0; k < la.size(); ++k) d.edge_target.push_back(la[k] - lb[k] + spread);
    for (size_t k = 1; k + 1 < d.a.size(); ++k)
      d.angle_base.push_back(WrapAngle(Turning(oa, d.a, k) - Turning(ob, d.b, k)));
    seams_.push_back(std::move(d));
  }
}

void FitnessModel::Outlines(const Eigen::VectorXd& genes, std::vector<Outline>* outlines) const {
  outlines->resize(blocks_.blocks.size());
  for (size_t k = 0; k < blocks_.blocks.size(); ++k)
    EvalOutline(blocks_.blocks[k], genes.data(), &(*outlines)[k]);
}

double FitnessModel::BindingAchieved(size_t bi, const Eigen::VectorXd& genes,
                                     const std::vector<Outline>& outlines) const {
  double value = 0;
  for (const BindingTerm& t : base_.bindings[bi].terms) {
    const int p = base_.FindPiece(t.piece);
    const Piece& piece = base_.pieces[p];
    const Block& block = blocks_.blocks[p];
    const int a = piece.FindLandmark(t.from), b = piece.FindLandmark(t.to);
    auto position = [&](int l) -> Eigen::Vector2d {
      const int v = piece.landmarks[l].vertex;
      if (v >= 0) return outlines[p].row(v).transpose();
      return EvalParam(block, genes.data(), block.inside[l]);
    };
    const double length =
        t.path == BindingTerm::Path::kOutline
            ? OutlineDistance(outlines[p], piece.landmarks[a].vertex, piece.landmarks[b].vertex)
            : (position(a) - position(b)).norm();
    value += t.multiplicity * length;
  }
  return value;
}

std::vector<double> FitnessModel::Achieved(const Eigen::VectorXd& genes) const {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<double> values;
  for (size_t b = 0; b < base_.bindings.size(); ++b)
    values.push_back(BindingAchieved(b, genes, outlines));
  return values;
}

std::vector<double> FitnessModel::SeamMismatch(const Eigen::VectorXd& genes) const {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<double> values;
  std::vector<double> la, lb;
  for (const SeamData& d : seams_) {
    SeamEdges(outlines[d.piece_a], d.a, &la);
    SeamEdges(outlines[d.piece_b], d.b, &lb);
    double diff = -d.ease;
    for (size_t k = 0; k < la.size(); ++k) diff += la[k] - lb[k];
    values.push_back(diff);
  }
  return values;
}

void FitnessModel::Structure(const Eigen::VectorXd& genes, const std::vector<Outline>& outlines,
                             std::vector<double>* out) const {
  for (const Direction& d : directions_) {
    const Block& block = blocks_.blocks[d.piece];
    const Piece& piece = base_.pieces[d.piece];
    Eigen::Vector2d a, b;
    if (d.kind == 0) {
      a = outlines[d.piece].row(d.a);
      b = outlines[d.piece].row(d.b);
    } else if (d.kind == 1) {
      auto at = [&](int l) -> Eigen::Vector2d {
        const int v = piece.landmarks[l].vertex;
        if (v >= 0) return outlines[d.piece].row(v).transpose();
        return EvalParam(block, genes.data(), block.inside[l]);
      };
      a = at(d.a);
      b = at(d.b);
    } else {
      a = EvalParam(block, genes.data(), block.grain[0]);
      b = EvalParam(block, genes.data(), block.grain[1]);
    }
    const Eigen::Vector2d e = b - a;
    out->push_back(d.unit.x() * e.y() - d.unit.y() * e.x());
  }
  constexpr double kAngleScaleMm = 100;
  for (size_t c = 0; c < corners_.size(); ++c) {
    const Outline& o = outlines[corners_[c].first];
    const int n = static_cast<int>(o.rows()), v = corners_[c].second;
    const Eigen::Vector2d e0 = o.row(v) - o.row((v - 1 + n) % n),
                          e1 = o.row((v + 1) % n) - o.row(v);
    const double turning = std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
    out->push_back(WrapAngle(turning - corner_turning_[c]) * kAngleScaleMm);
  }
  for (const auto& [p, d] : darts_) {
    const Outline& o = outlines[p];
    out->push_back((o.row(d.leg_a) - o.row(d.apex)).norm() -
                   (o.row(d.leg_b) - o.row(d.apex)).norm());
  }
}

void FitnessModel::StructureResiduals(const Eigen::VectorXd& genes,
                                      Eigen::VectorXd* residuals) const {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<double> r;
  Structure(genes, outlines, &r);
  *residuals = Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

void FitnessModel::Constraints(const Eigen::VectorXd& genes, Eigen::VectorXd* constraints) const {
  thread_local std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<double> c;
  for (size_t b = 0; b < targets_.size(); ++b)
    c.push_back(BindingAchieved(b, genes, outlines) - targets_[b]);
  std::vector<double> la, lb;
  for (const SeamData& d : seams_) {
    SeamEdges(outlines[d.piece_a], d.a, &la);
    SeamEdges(outlines[d.piece_b], d.b, &lb);
    double total = -d.ease;
    for (size_t k = 0; k < la.size(); ++k) total += la[k] - lb[k];
    c.push_back(total);
  }
  *constraints = Eigen::Map<Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size()));
}

Objectives FitnessModel::Evaluate(const Eigen::VectorXd& genes, bool check_simple) const {
  thread_local std::vector<Outline> outlines;
  thread_local std::vector<double> la, lb;
  Outlines(genes, &outlines);
  Objectives o;
  for (size_t b = 0; b < targets_.size(); ++b) {
    const double e = std::abs(BindingAchieved(b, genes, outlines) - targets_[b]);
    o.measurement_mm += e;
    o.max_measurement_mm = std::max(o.max_measurement_mm, e);
  }
  if (!targets_.empty()) o.measurement_mm /= static_cast<double>(targets_.size());
  for (const SeamData& d : seams_) {
    SeamEdges(outlines[d.piece_a], d.a, &la);
    SeamEdges(outlines[d.piece_b], d.b, &lb);
    double edge_error = 0, total = -d.ease;
    for (size_t k = 0; k < la.size(); ++k) {
      edge_error += std::abs(la[k] - lb[k] - d.edge_target[k]);
      total += la[k] - lb[k];
    }
    double angle_error = 0;
    for (size_t k = 1; k + 1 < d.a.size(); ++k) {
      const double diff =
          Turning(outlines[d.piece_a], d.a, k) - Turning(outlines[d.piece_b], d.b, k);
      angle_error += std::abs(WrapAngle(diff - d.angle_base[k - 1])) * kDeg;
    }
    o.seam += (angle_error + edge_error) / static_cast<double>(d.a.size());
    o.max_seam_length_mm = std::max(o.max_seam_length_mm, std::abs(total));
  }
  if (!seams_.empty()) o.seam /= static_cast<double>(seams_.size());
  int vertices = 0, critical = 0;
  for (size_t p = 0; p < outlines.size(); ++p) {
    const Eigen::VectorXd turning = TurningAngles(outlines[p]);
    for (Eigen::Index v = 0; v < turning.size(); ++v)
      o.shape_deg += std::abs(WrapAngle(turning[v] - base_turning_[p][v])) * kDeg;
    vertices += static_cast<int>(turning.size());
    for (int c : base_.pieces[p].critical)
      o.critical_shape_deg += std::abs(WrapAngle(turning[c] - base_turning_[p][c])) * kDeg;
    critical += static_cast<int>(base_.pieces[p].critical.size());
    if (check_simple && FindSelfIntersection(outlines[p]).first >= 0) o.simple = false;
  }
  o.shape_deg /= std::max(vertices, 1);
  if (num_structure_ > 0) {
    thread_local std::vector<double> rules;
    rules.clear();
    Structure(genes, outlines, &rules);
    for (double r : rules) o.max_structure_mm = std::max(o.max_structure_mm, std::abs(r));
  }
  o.critical_shape_deg /= std::max(critical, 1);
  return o;
}

void FitnessModel::Residuals(const Eigen::VectorXd& genes, double angle_scale_mm,
                             double length_scale_mm, Eigen::VectorXd* constraints,
                             Eigen::VectorXd* soft, int only_piece,
                             const Eigen::VectorXd* reuse_soft) const {
  thread_local std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  const bool reuse = only_piece >= 0 && reuse_soft != nullptr;
  auto stale = [&](int p) { return reuse && p != only_piece; };
  thread_local std::vector<double> c, s, la, lb;
  c.clear();
  s.clear();
  for (size_t b = 0; b < targets_.size(); ++b)
    c.push_back(BindingAchieved(b, genes, outlines) - targets_[b]);
  for (const SeamData& d : seams_) {
    SeamEdges(outlines[d.piece_a], d.a, &la);
    SeamEdges(outlines[d.piece_b], d.b, &lb);
    double total = -d.ease;
    for (size_t k = 0; k < la.size(); ++k) {
      total += la[k] - lb[k];
      s.push_back(la[k] - lb[k] - d.edge_target[k]);
    }
    c.push_back(total);
    const bool copy = stale(d.piece_a) && stale(d.piece_b);
    for (size_t k = 1; k + 1 < d.a.size(); ++k) {
      if (copy) {
        s.push_back((*reuse_soft)[static_cast<Eigen::Index>(s.size())]);
        continue;
      }
      const double diff =
          Turning(outlines[d.piece_a], d.a, k) - Turning(outlines[d.piece_b], d.b, k);
      s.push_back(WrapAngle(diff - d.angle_base[k - 1]) * angle_scale_mm);
    }
  }
  for (size_t p = 0; p < outlines.size(); ++p) {
    if (stale(static_cast<int>(p))) {  // unchanged piece: copy its block
      const Eigen::Index n = outlines[p].rows() * (length_scale_mm > 0 ? 2 : 1);
      const Eigen::Index at = static_cast<Eigen::Index>(s.size());
      for (Eigen::Index v = 0; v < n; ++v) s.push_back((*reuse_soft)[at + v]);
      continue;
    }
    // Edge directions, not just turning angles: a straight fold or hem line
    // must not tilt as a whole either (a pure turning-angle penalty lets a
    // CB fold line rotate, which no cutter would accept).
    const Outline& o = outlines[p];
    const Eigen::Index n = o.rows();
    for (Eigen::Index v = 0; v < n; ++v) {
      const Eigen::Vector2d e = o.row((v + 1) % n) - o.row(v);
      s.push_back(WrapAngle(std::atan2(e.y(), e.x()) - base_direction_[p][v]) * angle_scale_mm);
    }
    if (length_scale_mm > 0)
      for (Eigen::Index v = 0; v < n; ++v) {
        const double l = (o.row((v + 1) % n) - o.row(v)).norm();
        s.push_back(length_scale_mm * (l / base_length_[p][v] - 1.0));
      }
  }
  Structure(genes, outlines, &c);
  *constraints = Eigen::Map<Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size()));
  *soft = Eigen::Map<Eigen::VectorXd>(s.data(), static_cast<Eigen::Index>(s.size()));
}

}  // namespace bespoke
