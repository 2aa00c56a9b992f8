#include "resize/pattern/edit.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

int Wrap(int i, int n) { return ((i % n) + n) % n; }

// Largest distance of the run's inner vertices from its chord (mm).
double ChordDeviation(const Outline& o, const std::vector<int>& run) {
  const Eigen::Vector2d a = o.row(run.front()), b = o.row(run.back());
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-9) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (size_t k = 1; k + 1 < run.size(); ++k) {
    const Eigen::Vector2d p = Eigen::Vector2d(o.row(run[k])) - a;
    const double t = p.dot(d) / (length * length);
    if (t <= 0 || t >= 1) return std::numeric_limits<double>::infinity();  // folds back
    worst = std::max(worst, std::abs(d.x() * p.y() - d.y() * p.x()) / length);
  }
  return worst;
}

bool Overlaps(const StraightRun& a, const StraightRun& b, int n) {
  const std::vector<int> ra = ForwardRun(a.from, a.to, n), rb = ForwardRun(b.from, b.to, n);
  int shared = 0;
  for (int v : ra) shared += std::count(rb.begin(), rb.end(), v) ? 1 : 0;
  return shared >= 2;
}

// Arc-length fractions of the vertices of a seam side, in stitch order.
std::vector<double> Fractions(const Outline& o, const std::vector<int>& idx) {
  std::vector<double> f(idx.size(), 0.0);
  for (size_t k = 1; k < idx.size(); ++k)
    f[k] = f[k - 1] + (o.row(idx[k]) - o.row(idx[k - 1])).norm();
  const double total = std::max(f.back(), 1e-12);
  for (double& x : f) x /= total;
  return f;
}

// Inserts points on side `side` of piece `p` at the given arc-length
// fractions (in stitch order), then remaps.
void InsertAtFractions(Pattern* pattern, const SeamSide& side, const std::vector<double>& at) {
  if (at.empty()) return;
  const int p = pattern->FindPiece(side.piece);
  const Outline& o = pattern->pieces[p].outline;
  const int n = static_cast<int>(o.rows());
  const std::vector<int> idx = SeamIndices(side, n);
  const std::vector<double> f = Fractions(o, idx);
  // Per outline edge k -> k+1: parameters t in (0, 1) of the new points.
  std::map<int, std::vector<double>> inserts;
  for (double x : at) {
    size_t k = 1;
    while (k + 1 < f.size() && f[k] < x) ++k;
    const double t = (x - f[k - 1]) / std::max(f[k] - f[k - 1], 1e-12);
    const int u = idx[k - 1], w = idx[k];
    if (side.forward)
      inserts[u].push_back(t);
    else
      inserts[w].push_back(1 - t);  // edge w -> u in outline order
  }
  std::vector<Eigen::Vector2d> points;
  std::vector<int> old_to_new(n);
  for (int v = 0; v < n; ++v) {
    old_to_new[v] = static_cast<int>(points.size());
    points.push_back(o.row(v));
    auto it = inserts.find(v);
    if (it == inserts.end()) continue;
    std::sort(it->second.begin(), it->second.end());
    const Eigen::Vector2d a = o.row(v), b = o.row((v + 1) % n);
    for (double t : it->second) points.push_back(a + t * (b - a));
  }
  Outline out(static_cast<Eigen::Index>(points.size()), 2);
  for (size_t i = 0; i < points.size(); ++i) out.row(i) = points[i].transpose();
  ReplaceOutline(pattern, p, out, old_to_new);
}

}  // namespace

void ReplaceOutline(Pattern* pattern, int p, const Outline& outline,
                    const std::vector<int>& old_to_new, bool reversed) {
  Piece& piece = pattern->pieces[p];
  auto map = [&](int v) {
    return v >= 0 && v < static_cast<int>(old_to_new.size()) ? old_to_new[v] : v;
  };
  for (int& c : piece.critical) c = map(c);
  for (int& c : piece.notches) c = map(c);
  for (int& c : piece.right_angles) c = map(c);
  for (PieceLandmark& l : piece.landmarks)
    if (l.vertex >= 0) l.vertex = map(l.vertex);
  for (auto* runs : {&piece.straight, &piece.not_straight})
    for (StraightRun& r : *runs) {
      const int from = map(r.from), to = map(r.to);
      r.from = reversed ? to : from;
      r.to = reversed ? from : to;
    }
  for (Dart& d : piece.darts) {
    d.apex = map(d.apex);
    d.leg_a = map(d.leg_a);
    d.leg_b = map(d.leg_b);
  }
  for (Seam& s : pattern->seams)
    for (SeamSide* side : {&s.a, &s.b}) {
      if (side->piece != piece.name) continue;
      side->from = map(side->from);
      side->to = map(side->to);
      if (reversed) side->forward = !side->forward;
    }
  if (reversed)
    for (MeasurementBinding& b : pattern->bindings)
      for (BindingTerm& t : b.terms)
        if (t.piece == piece.name && t.path == BindingTerm::Path::kOutline) std::swap(t.from, t.to);
  piece.outline = outline;
}

void LandmarksOntoOutline(Pattern* pattern, double tolerance_mm) {
  for (size_t p = 0; p < pattern->pieces.size(); ++p) {
    for (size_t l = 0; l < pattern->pieces[p].landmarks.size(); ++l) {
      Piece& piece = pattern->pieces[p];
      PieceLandmark& mark = piece.landmarks[l];
      if (mark.vertex >= 0) continue;
      const Outline& o = piece.outline;
      const int n = piece.num_vertices();
      int edge = -1;
      double best = tolerance_mm, best_t = 0;
      for (int v = 0; v < n; ++v) {
        const Eigen::Vector2d a = o.row(v), d = Eigen::Vector2d(o.row((v + 1) % n)) - a;
        const double t =
            std::clamp((mark.position - a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
        const double dist = (a + t * d - mark.position).norm();
        if (dist <= best) best = dist, edge = v, best_t = t;
      }
      if (edge < 0) continue;
      const double length = (o.row((edge + 1) % n) - o.row(edge)).norm();
      if (best_t * length < 0.01 || (1 - best_t) * length < 0.01) {
        mark.vertex = best_t * length < 0.01 ? edge : (edge + 1) % n;
        continue;
      }
      Outline out(n + 1, 2);
      std::vector<int> old_to_new(n);
      for (int v = 0, k = 0; v < n; ++v) {
        old_to_new[v] = k;
        out.row(k++) = o.row(v);
        if (v == edge) out.row(k++) = (o.row(v) + best_t * (o.row((v + 1) % n) - o.row(v)));
      }
      const std::string name = mark.name;
      ReplaceOutline(pattern, static_cast<int>(p), out, old_to_new);
      Piece& changed = pattern->pieces[p];
      changed.landmarks[l].vertex = old_to_new[edge] + 1;
      pattern->notes.push_back("piece '" + changed.name + "': landmark '" + name +
                               "' lies on the outline; a vertex was added there");
    }
  }
}

void MakeCounterClockwise(Pattern* pattern) {
  for (size_t p = 0; p < pattern->pieces.size(); ++p) {
    const Outline& o = pattern->pieces[p].outline;
    if (SignedArea(o) >= 0) continue;
    const int n = static_cast<int>(o.rows());
    std::vector<int> old_to_new(n);
    for (int v = 0; v < n; ++v) old_to_new[v] = n - 1 - v;
    ReplaceOutline(pattern, static_cast<int>(p), o.colwise().reverse().eval(), old_to_new, true);
    pattern->notes.push_back("piece '" + pattern->pieces[p].name +
                             "': outline turned counter-clockwise (it was clockwise); vertex "
                             "indices now count the other way");
  }
}

namespace {

// One pass of EqualizeSeamCounts over every seam; true when a point was added.
bool EqualizePass(Pattern* pattern, double merge_mm) {
  bool changed = false;
  for (Seam& seam : pattern->seams) {
    const int pa = pattern->FindPiece(seam.a.piece), pb = pattern->FindPiece(seam.b.piece);
    if (pa < 0 || pb < 0) continue;
    const Outline& oa = pattern->pieces[pa].outline;
    const Outline& ob = pattern->pieces[pb].outline;
    const std::vector<int> ia = SeamIndices(seam.a, static_cast<int>(oa.rows()));
    const std::vector<int> ib = SeamIndices(seam.b, static_cast<int>(ob.rows()));
    if (ia.size() == ib.size() || ia.size() < 2 || ib.size() < 2) continue;
    const double length =
        std::max(SeamLength(pattern->pieces[pa], seam.a), SeamLength(pattern->pieces[pb], seam.b));
    const double merge = merge_mm / std::max(length, 1e-9);
    // Sorted union of both sides' fractions; a cluster holds at most one
    // vertex of each side, so both sides end with one point per cluster.
    struct Mark {
      double f;
      int side;
    };
    std::vector<Mark> marks;
    for (double f : Fractions(oa, ia)) marks.push_back({f, 0});
    for (double f : Fractions(ob, ib)) marks.push_back({f, 1});
    std::sort(marks.begin(), marks.end(), [](const Mark& x, const Mark& y) { return x.f < y.f; });
    std::vector<double> add_a, add_b;
    for (size_t k = 0; k < marks.size();) {
      bool has[2] = {false, false};
      double f_other[2] = {0, 0};
      size_t j = k;
      while (j < marks.size() && marks[j].f - marks[k].f <= merge && !has[marks[j].side]) {
        has[marks[j].side] = true;
        f_other[1 - marks[j].side] = marks[j].f;
        ++j;
      }
      if (!has[0]) add_a.push_back(f_other[0]);
      if (!has[1]) add_b.push_back(f_other[1]);
      k = j;
    }
    InsertAtFractions(pattern, seam.a, add_a);
    InsertAtFractions(pattern, seam.b, add_b);
    changed = changed || !add_a.empty() || !add_b.empty();
  }
  return changed;
}

std::pair<size_t, size_t> SideCounts(const Pattern& pattern, const Seam& seam) {
  const int pa = pattern.FindPiece(seam.a.piece), pb = pattern.FindPiece(seam.b.piece);
  if (pa < 0 || pb < 0) return {0, 0};
  return {SeamIndices(seam.a, pattern.pieces[pa].num_vertices()).size(),
          SeamIndices(seam.b, pattern.pieces[pb].num_vertices()).size()};
}

}  // namespace

void EqualizeSeamCounts(Pattern* pattern, double merge_mm) {
  std::vector<std::pair<size_t, size_t>> before;
  for (const Seam& seam : pattern->seams) before.push_back(SideCounts(*pattern, seam));
  // Seams that share a run (two sleeves set into one armhole) need passes
  // until every pair agrees.
  for (int pass = 0; pass < 8 && EqualizePass(pattern, merge_mm); ++pass) {
  }
  for (size_t s = 0; s < pattern->seams.size(); ++s) {
    const auto after = SideCounts(*pattern, pattern->seams[s]);
    if (after == before[s]) continue;
    pattern->notes.push_back("seam '" + pattern->seams[s].name + "': sides resampled from " +
                             std::to_string(before[s].first) + " and " +
                             std::to_string(before[s].second) + " to " +
                             std::to_string(after.first) + " and " + std::to_string(after.second) +
                             " points (points added at the other side's arc-length fractions; "
                             "outlines unchanged)");
  }
}

void AddStructureCriticalPoints(Pattern* pattern) {
  for (Piece& piece : pattern->pieces) {
    std::vector<int> add;
    for (const PieceLandmark& l : piece.landmarks)
      if (l.vertex >= 0) add.push_back(l.vertex);
    for (const StraightRun& r : piece.straight) add.insert(add.end(), {r.from, r.to});
    add.insert(add.end(), piece.right_angles.begin(), piece.right_angles.end());
    for (const Dart& d : piece.darts) add.insert(add.end(), {d.apex, d.leg_a, d.leg_b});
    for (int v : add)
      if (!std::count(piece.critical.begin(), piece.critical.end(), v)) piece.critical.push_back(v);
    std::sort(piece.critical.begin(), piece.critical.end());
  }
}

Eigen::Vector2d GrainDirection(const Piece& piece) {
  if (piece.has_grain && (piece.grain_end - piece.grain_start).norm() > 1e-9)
    return (piece.grain_end - piece.grain_start).normalized();
  for (const StraightRun& r : piece.straight)
    if (r.fold) {
      const Eigen::Vector2d d = piece.outline.row(r.to) - piece.outline.row(r.from);
      if (d.norm() > 1e-9) return d.normalized();
    }
  return Eigen::Vector2d::UnitY();
}

void InferStructure(const StructureOptions& options, Pattern* pattern) {
  for (Piece& piece : pattern->pieces) {
    const Outline& o = piece.outline;
    const int n = piece.num_vertices();
    // Maximal collinear runs, from every start vertex.
    std::vector<StraightRun> found;
    for (int i = 0; i < n; ++i) {
      int j = i + 2;
      while (j - i < n &&
             ChordDeviation(o, ForwardRun(i, Wrap(j, n), n)) <= options.straight_tolerance_mm)
        ++j;
      const int end = j - 1;  // last vertex that kept the run straight
      if (end - i < 1) continue;
      const StraightRun run{i, Wrap(end, n), false};
      if ((o.row(run.to) - o.row(run.from)).norm() < options.min_straight_mm) continue;
      found.push_back(run);
    }
    auto inside = [&](const StraightRun& a, const StraightRun& b) {  // a within b
      const std::vector<int> ra = ForwardRun(a.from, a.to, n), rb = ForwardRun(b.from, b.to, n);
      for (int v : ra)
        if (!std::count(rb.begin(), rb.end(), v)) return false;
      return true;
    };
    std::vector<StraightRun> runs;  // single long edges too, for folds and corners
    for (const StraightRun& r : found) {
      bool contained = false;
      for (const StraightRun& q : found)
        if (&q != &r && inside(r, q) && !(inside(q, r) && &q > &r)) contained = true;
      for (const StraightRun& q : piece.not_straight)
        if (Overlaps(r, q, n)) contained = true;
      if (!contained) runs.push_back(r);
    }
    for (const StraightRun& r : runs) {
      if (ForwardRun(r.from, r.to, n).size() < 3) continue;  // one edge cannot kink
      bool known = false;
      for (const StraightRun& q : piece.straight) known = known || Overlaps(r, q, n);
      if (!known) piece.straight.push_back(r);
    }
    if (piece.on_fold && std::none_of(piece.straight.begin(), piece.straight.end(),
                                      [](const StraightRun& r) { return r.fold; })) {
      const Eigen::Vector2d grain = GrainDirection(piece);
      const StraightRun* best = nullptr;
      double best_length = 0;
      for (const StraightRun& r : runs) {
        const Eigen::Vector2d d = o.row(r.to) - o.row(r.from);
        if (std::abs(d.normalized().dot(grain)) < std::cos(2 * M_PI / 180)) continue;
        if (d.norm() > best_length) best = &r, best_length = d.norm();
      }
      if (best) {
        bool merged = false;
        for (StraightRun& q : piece.straight)
          if (Overlaps(*best, q, n)) q.fold = merged = true;
        if (!merged) piece.straight.push_back({best->from, best->to, true});
      }
    }
    // Square corners where two straight runs meet.
    for (const StraightRun& a : runs)
      for (const StraightRun& b : runs) {
        if (a.to != b.from) continue;
        const Eigen::Vector2d da = o.row(a.to) - o.row(a.from), db = o.row(b.to) - o.row(b.from);
        const double angle =
            std::acos(std::clamp(da.normalized().dot(db.normalized()), -1.0, 1.0)) * 180 / M_PI;
        if (std::abs(angle - 90) > options.right_angle_tolerance_deg) continue;
        if (!std::count(piece.right_angles.begin(), piece.right_angles.end(), a.to))
          piece.right_angles.push_back(a.to);
      }
  }
}

}  // namespace bespoke
