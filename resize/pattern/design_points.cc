#include "resize/pattern/design_points.h"

#include <algorithm>
#include <cmath>

#include "resize/pattern/edit.h"
#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

// Per vertex of piece `p`: whether it is a structure point (see the header).
std::vector<bool> StructurePoints(const Pattern& pattern, int p) {
  const Piece& piece = pattern.pieces[p];
  std::vector<bool> s(piece.num_vertices(), false);
  auto mark = [&](int v) {
    if (v >= 0 && v < piece.num_vertices()) s[v] = true;
  };
  for (const Seam& seam : pattern.seams)
    for (const SeamSide* side : {&seam.a, &seam.b})
      if (side->piece == piece.name) mark(side->from), mark(side->to);
  for (const PieceLandmark& l : piece.landmarks) mark(l.vertex);
  for (int v : piece.right_angles) mark(v);
  for (const StraightRun& r : piece.straight) mark(r.from), mark(r.to);
  for (const Dart& d : piece.darts) mark(d.apex), mark(d.leg_a), mark(d.leg_b);
  return s;
}

// Largest distance of the vertices of `run` from the line through its ends.
double Bulge(const Outline& o, const std::vector<int>& run) {
  const Eigen::Vector2d a = o.row(run.front()), d = Eigen::Vector2d(o.row(run.back())) - a;
  const double length = std::max(d.norm(), 1e-9);
  double worst = 0;
  for (int v : run) {
    const Eigen::Vector2d q = Eigen::Vector2d(o.row(v)) - a;
    worst = std::max(worst, std::abs(d.x() * q.y() - d.y() * q.x()) / length);
  }
  return worst;
}

// The cap run of `piece` when it is a sleeve, else empty.
std::vector<int> CapRun(const Piece& piece) {
  const int back = piece.FindLandmark("back_underarm"),
            front = piece.FindLandmark("front_underarm");
  if (back < 0 || front < 0) return {};
  const int a = piece.landmarks[back].vertex, b = piece.landmarks[front].vertex,
            n = piece.num_vertices();
  if (a < 0 || b < 0 || a == b) return {};
  const std::vector<int> ab = ForwardRun(a, b, n), ba = ForwardRun(b, a, n);
  int top = piece.FindLandmark("cap_top");
  if (top < 0) top = piece.FindLandmark("crown_top");
  if (top >= 0) {
    Eigen::Index nearest = 0;
    (piece.outline.rowwise() - piece.LandmarkPosition(top).transpose())
        .rowwise()
        .squaredNorm()
        .minCoeff(&nearest);
    const int v = static_cast<int>(nearest);
    if (std::find(ab.begin(), ab.end(), v) != ab.end() && v != a && v != b) return ab;
    if (std::find(ba.begin(), ba.end(), v) != ba.end() && v != a && v != b) return ba;
  }
  return Bulge(piece.outline, ab) <= Bulge(piece.outline, ba) ? ab : ba;
}

}  // namespace

std::vector<NotchRun> NotchRuns(const Pattern& pattern, int p) {
  const Piece& piece = pattern.pieces[p];
  const int n = piece.num_vertices();
  const std::vector<bool> s = StructurePoints(pattern, p);
  std::vector<NotchRun> runs;
  for (int notch : piece.notches) {
    if (notch < 0 || notch >= n || s[notch]) continue;
    NotchRun r;
    r.notch = notch;
    r.from = r.to = -1;
    for (int k = 1; k < n && r.from < 0; ++k)
      if (s[(notch - k + n) % n]) r.from = (notch - k + n) % n;
    for (int k = 1; k < n && r.to < 0; ++k)
      if (s[(notch + k) % n]) r.to = (notch + k) % n;
    if (r.from < 0 || r.to < 0 || r.from == r.to) continue;
    const double to_notch = OutlineDistance(piece.outline, r.from, notch);
    const double total = to_notch + OutlineDistance(piece.outline, notch, r.to);
    if (total < 1e-9) continue;
    r.fraction = to_notch / total;
    runs.push_back(r);
  }
  return runs;
}

double NotchShift(const Outline& outline, const NotchRun& run) {
  const double to_notch = OutlineDistance(outline, run.from, run.notch);
  const double after = OutlineDistance(outline, run.notch, run.to);
  return to_notch - run.fraction * (to_notch + after);
}

std::vector<DesignDimension> FindDesignDimensions(const Pattern& pattern) {
  std::vector<DesignDimension> caps, depths;
  std::vector<std::vector<int>> armholes(pattern.pieces.size());
  for (const Piece& piece : pattern.pieces) {
    const std::vector<int> cap = CapRun(piece);
    if (cap.empty()) continue;
    caps.push_back({DesignDimension::Kind::kCapHeight, piece.name, cap});
    auto on_cap = [&](int v) { return std::find(cap.begin(), cap.end(), v) != cap.end(); };
    for (const Seam& seam : pattern.seams)
      for (int k = 0; k < 2; ++k) {
        const SeamSide &sleeve = k == 0 ? seam.a : seam.b, &other = k == 0 ? seam.b : seam.a;
        if (sleeve.piece != piece.name || other.piece == piece.name) continue;
        if (!on_cap(sleeve.from) || !on_cap(sleeve.to)) continue;
        const int o = pattern.FindPiece(other.piece);
        if (o < 0) continue;
        for (int v : SeamIndices(other, pattern.pieces[o].num_vertices()))
          if (std::find(armholes[o].begin(), armholes[o].end(), v) == armholes[o].end())
            armholes[o].push_back(v);
      }
  }
  for (size_t p = 0; p < pattern.pieces.size(); ++p)
    if (!armholes[p].empty() && CapRun(pattern.pieces[p]).empty())
      depths.push_back({DesignDimension::Kind::kArmholeDepth, pattern.pieces[p].name, armholes[p]});
  caps.insert(caps.end(), depths.begin(), depths.end());
  return caps;
}

double MeasureDesignDimension(const Pattern& pattern, const DesignDimension& d) {
  const int p = pattern.FindPiece(d.piece);
  if (p < 0 || d.vertices.empty()) return 0;
  const Piece& piece = pattern.pieces[p];
  if (d.kind == DesignDimension::Kind::kCapHeight) return Bulge(piece.outline, d.vertices);
  const Eigen::Vector2d grain = GrainDirection(piece);
  double lo = 1e300, hi = -1e300;
  for (int v : d.vertices) {
    const double h = grain.dot(Eigen::Vector2d(piece.outline.row(v)));
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  return hi - lo;
}

Eigen::Vector2d CapDirection(const Pattern& pattern, const DesignDimension& cap) {
  const Outline& o = pattern.pieces[pattern.FindPiece(cap.piece)].outline;
  const Eigen::Vector2d a = o.row(cap.vertices.front()), b = o.row(cap.vertices.back());
  const Eigen::Vector2d normal = Eigen::Vector2d(a.y() - b.y(), b.x() - a.x()).normalized();
  double best = 0;
  for (int v : cap.vertices) {
    const double h = normal.dot(Eigen::Vector2d(o.row(v)) - a);
    if (std::abs(h) > std::abs(best)) best = h;
  }
  return best < 0 ? Eigen::Vector2d(-normal) : normal;
}

double InferredCapHeight(const Piece& sleeve, const Eigen::Vector2d& up) {
  const Eigen::Vector2d across(up.y(), -up.x());
  Eigen::Index a = 0, b = 0;
  const Eigen::VectorXd along = sleeve.outline * across;
  along.minCoeff(&a);
  along.maxCoeff(&b);
  const Eigen::Vector2d pa = sleeve.outline.row(a), pb = sleeve.outline.row(b);
  Eigen::Vector2d normal = Eigen::Vector2d(pa.y() - pb.y(), pb.x() - pa.x()).normalized();
  if (normal.dot(up) < 0) normal = -normal;
  double height = 0;
  for (Eigen::Index v = 0; v < sleeve.outline.rows(); ++v)
    height = std::max(height, normal.dot(Eigen::Vector2d(sleeve.outline.row(v)) - pa));
  return height;
}

std::string DesignDimensionName(DesignDimension::Kind kind) {
  return kind == DesignDimension::Kind::kCapHeight ? "cap_height" : "armhole_depth";
}

}  // namespace bespoke
