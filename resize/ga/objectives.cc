#include "resize/ga/objectives.h"

#include <algorithm>
#include <cmath>

#include "resize/pattern/design_points.h"
#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr double kFlatRad = 1e-3;  // a curve vertex turning less is flat

double Turning(const Outline& o, const std::vector<int>& idx, size_t k) {
  const Eigen::Vector2d a = o.row(idx[k]) - o.row(idx[k - 1]);
  const Eigen::Vector2d b = o.row(idx[k + 1]) - o.row(idx[k]);
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

}  // namespace

double FastAtan2(double y, double x) {
  constexpr double kTan15 = 0.26794919243112270;  // tan(pi / 12)
  constexpr double kSqrt3 = 1.7320508075688772;
  const double ax = std::abs(x), ay = std::abs(y);
  const double big = std::max(ax, ay), small = std::min(ax, ay);
  if (!(big > 0) || !std::isfinite(big)) return std::atan2(y, x);
  double r = small / big, base = 0;  // atan(small / big) in [0, pi / 4]
  if (r > kTan15) {  // atan(r) = pi / 6 + atan((r sqrt3 - 1) / (r + sqrt3)), |that| <= tan(pi / 12)
    r = (r * kSqrt3 - 1) / (r + kSqrt3);
    base = M_PI / 6;
  }
  // The arctangent's series to r^21: the next term is below 3e-15 for |r| <= tan(pi / 12).
  const double r2 = r * r;
  double p = 1.0 / 21;
  for (int k = 9; k >= 0; --k) p = p * -r2 + 1.0 / (2 * k + 1);
  double a = base + r * p;
  if (ay > ax) a = M_PI / 2 - a;
  if (x < 0) a = M_PI - a;
  return std::signbit(y) ? -a : a;
}

namespace {

// Turning angle at every vertex of a closed outline (rad, left positive),
// as TurningAngles computes it (with FastAtan2), into `out` (resized only when its size
// differs, so a buffer reused across calls is not reallocated).
void TurningInto(const Outline& o, Eigen::VectorXd* out) {
  const int n = static_cast<int>(o.rows());
  out->resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = o.row(i) - o.row((i - 1 + n) % n);
    const Eigen::Vector2d b = o.row((i + 1) % n) - o.row(i);
    (*out)[i] = FastAtan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  }
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

// Outline vertices walked forward from `from` to `to` inclusive.
std::vector<int> ForwardPath(int from, int to, int n) {
  std::vector<int> path = {from};
  for (int v = from; v != to;) {
    v = (v + 1) % n;
    path.push_back(v);
  }
  return path;
}

}  // namespace

FitnessModel::FitnessModel(const Pattern& base, const BlockSet& blocks, const MeasurementSet& body)
    : base_(base), blocks_(blocks), driven_(base.pieces.size(), false) {
  for (const MeasurementBinding& b : base.bindings)
    for (const BindingTerm& t : b.terms) driven_[base.FindPiece(t.piece)] = true;
  for (const Seam& s : base.seams)
    driven_[base.FindPiece(s.a.piece)] = driven_[base.FindPiece(s.b.piece)] = true;
  // Stencils of every point; inner vertices of straight runs follow their ends.
  std::vector<std::pair<int, double>> st;
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const Block& block = blocks.blocks[p];
    std::vector<Stencil> stencils;
    for (const GridParam& g : block.outline) {
      ParamStencil(block, g, &st);
      stencils.push_back(st);
    }
    for (const BlockRun& r : block.straight)
      for (size_t k = 0; k < r.inner.size(); ++k) {
        Stencil combined;
        for (const auto& [c, w] : stencils[r.from]) combined.push_back({c, (1 - r.t[k]) * w});
        for (const auto& [c, w] : stencils[r.to]) combined.push_back({c, r.t[k] * w});
        stencils[r.inner[k]] = combined;
      }
    for (const GridParam& g : block.inside) {
      ParamStencil(block, g, &st);
      stencils.push_back(st);
    }
    for (const GridParam& g : block.grain) {
      ParamStencil(block, g, &st);
      stencils.push_back(st);
    }
    stencils_.push_back(std::move(stencils));
  }
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const Piece& piece = base.pieces[p];
    const int k = static_cast<int>(p), n = piece.num_vertices();
    for (const StraightRun& r : piece.straight)
      if (r.fold) {
        const Eigen::Vector2d d = piece.outline.row(r.to) - piece.outline.row(r.from);
        directions_.push_back({k, r.from, r.to, d.normalized()});
      }
    for (const LevelLine& l : piece.level_lines) {
      const int a = piece.FindLandmark(l.from), b = piece.FindLandmark(l.to);
      const Eigen::Vector2d d = piece.LandmarkPosition(b) - piece.LandmarkPosition(a);
      directions_.push_back({k, LandmarkPoint(k, a), LandmarkPoint(k, b), d.normalized()});
    }
    if (piece.has_grain) {
      const int start = n + static_cast<int>(piece.landmarks.size());
      directions_.push_back(
          {k, start, start + 1, (piece.grain_end - piece.grain_start).normalized()});
    }
    const Eigen::VectorXd turning = TurningAngles(piece.outline);
    base_turning_.push_back(turning);
    shape_turning_.push_back(turning);
    for (int v : piece.right_angles) {
      corners_.push_back({k, v});
      corner_turning_.push_back(turning[v]);
    }
    for (const Dart& d : piece.darts) darts_.push_back({k, d});
    std::vector<bool> critical(n, false);
    for (int c : piece.critical) critical[c] = true;
    for (const StraightRun& r : KeptStraightRuns(piece))
      for (int v = (r.from + 1) % n; v != r.to; v = (v + 1) % n)
        if (critical[v]) collinear_.push_back({k, r.from, r.to, v});
    AddNotches(k);
    std::vector<bool> on_run(n, false);  // the design's straight runs, ends included
    for (const StraightRun& r : piece.straight)
      for (int v = r.from;; v = (v + 1) % n) {
        on_run[v] = true;
        if (v == r.to) break;
      }
    std::vector<int> sign(n, 0);
    std::vector<bool> flat(n, false);
    const std::vector<bool> curves = CurveVertices(piece.outline, on_run);
    auto curve = [&](int v) { return static_cast<bool>(curves[v]); };
    auto sgn = [&](int v) { return turning[v] > 0 ? 1 : -1; };
    for (int v = 0; v < n; ++v) {
      if (!curve(v)) continue;
      if (std::abs(turning[v]) >= kFlatRad) {
        sign[v] = sgn(v);
        continue;
      }
      const int a = (v - 1 + n) % n, b = (v + 1) % n;
      if (curve(a) && curve(b) && std::abs(turning[a]) >= kFlatRad &&
          std::abs(turning[b]) >= kFlatRad && sgn(a) == sgn(b)) {
        sign[v] = sgn(a);
        flat[v] = true;
      }
    }
    curve_sign_.push_back(sign);
    curve_flat_.push_back(flat);
  }
  targets_ = BindingTargets(base, body);
  for (const MeasurementBinding& b : base.bindings) {
    std::vector<TermData> terms;
    for (const BindingTerm& t : b.terms) {
      TermData d;
      d.piece = base.FindPiece(t.piece);
      const Piece& piece = base.pieces[d.piece];
      const int la = piece.FindLandmark(t.from), lb = piece.FindLandmark(t.to);
      d.a = LandmarkPoint(d.piece, la);
      d.b = LandmarkPoint(d.piece, lb);
      if (t.path == BindingTerm::Path::kOutline)
        d.path = ForwardPath(piece.landmarks[la].vertex, piece.landmarks[lb].vertex,
                             piece.num_vertices());
      d.multiplicity = t.multiplicity;
      d.base_length = TermLength(piece, t);
      terms.push_back(std::move(d));
    }
    terms_.push_back(std::move(terms));
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
    d.forward_a = seam.a.forward;
    d.forward_b = seam.b.forward;
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

void FitnessModel::AddNotches(int piece) {
  const int n = base_.pieces[piece].num_vertices();
  for (const NotchRun& r : NotchRuns(base_, piece)) {
    // Inside one run EvalOutline keeps straight, the notch's fraction is fixed.
    bool held = false;
    for (const BlockRun& s : blocks_.blocks[piece].straight) {
      const std::vector<int> run = ForwardRun(s.from, s.to, n);
      const int a = static_cast<int>(std::find(run.begin(), run.end(), r.from) - run.begin());
      const int b = static_cast<int>(std::find(run.begin(), run.end(), r.to) - run.begin());
      held =
          held || (a < static_cast<int>(run.size()) && b < static_cast<int>(run.size()) && a < b);
    }
    if (!held)
      notches_.push_back(
          {piece, ForwardRun(r.from, r.notch, n), ForwardRun(r.notch, r.to, n), r.fraction});
  }
}

int FitnessModel::LandmarkPoint(int piece, int landmark) const {
  const Piece& p = base_.pieces[piece];
  const int v = p.landmarks[landmark].vertex;
  return v >= 0 ? v : p.num_vertices() + landmark;
}

Eigen::Vector2d FitnessModel::Point(int piece, int point, const Eigen::VectorXd& genes,
                                    const std::vector<Outline>& outlines) const {
  const Block& block = blocks_.blocks[piece];
  const int n = static_cast<int>(block.outline.size());
  if (point < n) return outlines[piece].row(point).transpose();
  const int l = point - n;
  if (l < static_cast<int>(block.inside.size()))
    return EvalParam(block, genes.data(), block.inside[l]);
  return EvalParam(block, genes.data(), block.grain[l - block.inside.size()]);
}

void FitnessModel::Outlines(const Eigen::VectorXd& genes, std::vector<Outline>* outlines) const {
  outlines->resize(blocks_.blocks.size());
  for (size_t k = 0; k < blocks_.blocks.size(); ++k)
    EvalOutline(blocks_.blocks[k], genes.data(), &(*outlines)[k]);
}

double FitnessModel::TermValue(const TermData& t, const Eigen::VectorXd& genes,
                               const std::vector<Outline>& outlines) const {
  if (t.path.empty())
    return (Point(t.piece, t.a, genes, outlines) - Point(t.piece, t.b, genes, outlines)).norm();
  double length = 0;
  for (size_t k = 0; k + 1 < t.path.size(); ++k)
    length += (outlines[t.piece].row(t.path[k + 1]) - outlines[t.piece].row(t.path[k])).norm();
  return length;
}

std::vector<double> FitnessModel::Achieved(const Eigen::VectorXd& genes) const {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<double> values;
  for (const std::vector<TermData>& terms : terms_) {
    double value = 0;
    for (const TermData& t : terms) value += t.multiplicity * TermValue(t, genes, outlines);
    values.push_back(value);
  }
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

std::vector<FitnessModel::TurningBound> FitnessModel::CurveViolations(
    const Eigen::VectorXd& genes) const {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  std::vector<TurningBound> out;
  for (size_t p = 0; p < outlines.size(); ++p) {
    if (!driven_[p]) continue;
    const Eigen::VectorXd turning = TurningAngles(outlines[p]);
    for (Eigen::Index v = 0; v < turning.size(); ++v) {
      const int s = curve_sign_[p][v];
      if (s == 0) continue;
      const int k = static_cast<int>(p), i = static_cast<int>(v);
      if (curve_flat_[p][v]) {
        if (s * turning[v] < -kFlatRad) out.push_back({k, i, -s * 0.5 * kFlatRad});
      } else if (s * turning[v] < 0) {
        out.push_back({k, i, 0.25 * base_turning_[p][v]});
      }
    }
  }
  return out;
}

void FitnessModel::SetShapeReference(const Eigen::VectorXd& genes) {
  std::vector<Outline> outlines;
  Outlines(genes, &outlines);
  for (size_t p = 0; p < outlines.size(); ++p) shape_turning_[p] = TurningAngles(outlines[p]);
}

Objectives FitnessModel::Evaluate(const Eigen::VectorXd& genes, bool check_simple) const {
  // Per-thread buffers: evaluation runs for every individual of every
  // generation, in parallel, and must not allocate once they have grown.
  thread_local std::vector<Outline> outlines;
  thread_local std::vector<Eigen::VectorXd> turning;
  thread_local std::vector<double> la, lb;
  Outlines(genes, &outlines);
  turning.resize(outlines.size());
  for (size_t p = 0; p < outlines.size(); ++p)
    if (driven_[p]) TurningInto(outlines[p], &turning[p]);
  Objectives o;
  for (size_t b = 0; b < terms_.size(); ++b) {
    double value = 0;
    for (const TermData& t : terms_[b]) value += t.multiplicity * TermValue(t, genes, outlines);
    const double e = std::abs(value - targets_[b]);
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
    // A seam side walks its outline's vertices one by one, so its turning
    // at an inner point is the outline's there, negated when it walks
    // backwards (the same atan2 of the negated cross product).
    const Eigen::VectorXd& ta = turning[d.piece_a];
    const Eigen::VectorXd& tb = turning[d.piece_b];
    const double sa = d.forward_a ? 1.0 : -1.0, sb = d.forward_b ? 1.0 : -1.0;
    double angle_error = 0;
    for (size_t k = 1; k + 1 < d.a.size(); ++k) {
      const double diff = sa * ta[d.a[k]] - sb * tb[d.b[k]];
      angle_error += std::abs(WrapAngle(diff - d.angle_base[k - 1])) * kDeg;
    }
    o.seam += (angle_error + edge_error) / static_cast<double>(d.a.size());
    o.max_seam_length_mm = std::max(o.max_seam_length_mm, std::abs(total));
  }
  if (!seams_.empty()) o.seam /= static_cast<double>(seams_.size());
  int vertices = 0, critical = 0;
  for (size_t p = 0; p < outlines.size(); ++p) {
    if (!driven_[p]) continue;
    const Eigen::VectorXd& t = turning[p];
    for (Eigen::Index v = 0; v < t.size(); ++v)
      o.shape_deg += std::abs(WrapAngle(t[v] - shape_turning_[p][v])) * kDeg;
    vertices += static_cast<int>(t.size());
    for (int c : base_.pieces[p].critical)
      o.critical_shape_deg += std::abs(WrapAngle(t[c] - shape_turning_[p][c])) * kDeg;
    critical += static_cast<int>(base_.pieces[p].critical.size());
    if (check_simple && FindSelfIntersection(outlines[p]).first >= 0) o.simple = false;
  }
  o.shape_deg /= std::max(vertices, 1);
  o.critical_shape_deg /= std::max(critical, 1);
  if (!directions_.empty() || !corners_.empty() || !darts_.empty() || !collinear_.empty() ||
      !notches_.empty()) {
    thread_local std::vector<double> rules;
    rules.clear();
    Structure(genes, outlines, &rules);
    for (double r : rules) o.max_structure_mm = std::max(o.max_structure_mm, std::abs(r));
  }
  return o;
}

}  // namespace bespoke
