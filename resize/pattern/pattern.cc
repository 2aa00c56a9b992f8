#include "resize/pattern/pattern.h"

#include <cmath>
#include <set>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {

int Piece::FindLandmark(const std::string& landmark) const {
  for (size_t i = 0; i < landmarks.size(); ++i)
    if (landmarks[i].name == landmark) return static_cast<int>(i);
  return -1;
}

Eigen::Vector2d Piece::LandmarkPosition(int index) const {
  const PieceLandmark& l = landmarks.at(index);
  if (l.vertex >= 0) return outline.row(l.vertex).transpose();
  return l.position;
}

int Pattern::FindPiece(const std::string& piece) const {
  for (size_t i = 0; i < pieces.size(); ++i)
    if (pieces[i].name == piece) return static_cast<int>(i);
  return -1;
}

std::vector<int> SeamIndices(const SeamSide& side, int n) {
  std::vector<int> indices;
  for (int i = side.from;; i = side.forward ? (i + 1) % n : (i - 1 + n) % n) {
    indices.push_back(i);
    if (i == side.to || static_cast<int>(indices.size()) > n) break;
  }
  return indices;
}

std::vector<int> ForwardRun(int from, int to, int n) {
  SeamSide side;
  side.from = from, side.to = to, side.forward = true;
  return SeamIndices(side, n);
}

double TermLength(const Piece& piece, const BindingTerm& term) {
  const int a = piece.FindLandmark(term.from), b = piece.FindLandmark(term.to);
  if (term.path == BindingTerm::Path::kOutline)
    return OutlineDistance(piece.outline, piece.landmarks[a].vertex, piece.landmarks[b].vertex);
  return (piece.LandmarkPosition(a) - piece.LandmarkPosition(b)).norm();
}

double BindingValue(const Pattern& pattern, const MeasurementBinding& binding) {
  double value = 0;
  for (const BindingTerm& term : binding.terms)
    value += term.multiplicity * TermLength(pattern.pieces[pattern.FindPiece(term.piece)], term);
  return value;
}

double SeamLength(const Piece& piece, const SeamSide& side) {
  return OutlineDistance(piece.outline, side.from, side.to, side.forward);
}

namespace {

void CheckPiece(const Piece& piece, const std::string& what) {
  const std::string where = what + ": piece '" + piece.name + "'";
  const int n = piece.num_vertices();
  if (n < 3) throw InputError(where + " has " + std::to_string(n) + " outline vertices (need 3+)");
  if (!piece.outline.allFinite()) throw InputError(where + " has non-finite coordinates");
  const auto [e1, e2] = FindSelfIntersection(piece.outline);
  if (e1 >= 0)
    throw InputError(where + ": outline self-intersects (edges " + std::to_string(e1) + " and " +
                     std::to_string(e2) + ")");
  auto check_index = [&](int i, const std::string& kind) {
    if (i < 0 || i >= n)
      throw InputError(where + ": " + kind + " index " + std::to_string(i) + " out of range 0.." +
                       std::to_string(n - 1));
  };
  for (int c : piece.critical) check_index(c, "critical point");
  for (int c : piece.notches) check_index(c, "notch");
  std::set<std::string> names;
  for (const PieceLandmark& l : piece.landmarks) {
    if (!names.insert(l.name).second) throw InputError(where + ": duplicate landmark " + l.name);
    if (l.vertex >= 0) check_index(l.vertex, "landmark '" + l.name + "'");
    if (l.vertex < 0 && !l.position.allFinite())
      throw InputError(where + ": landmark '" + l.name + "' has no valid position");
  }
  for (const StraightRun& r : piece.straight) {
    check_index(r.from, "straight run start");
    check_index(r.to, "straight run end");
    if (r.from == r.to) throw InputError(where + ": a straight run needs two different ends");
  }
  for (int v : piece.right_angles) check_index(v, "right-angle corner");
  for (const Dart& d : piece.darts) {
    check_index(d.apex, "dart apex");
    check_index(d.leg_a, "dart leg");
    check_index(d.leg_b, "dart leg");
  }
  for (const LevelLine& l : piece.level_lines)
    for (const std::string& end : {l.from, l.to})
      if (piece.FindLandmark(end) < 0)
        throw InputError(where + ": level line '" + l.name + "' names unknown landmark '" + end +
                         "'");
  if (piece.cut_count < 1) throw InputError(where + ": cut count must be at least 1");
}

void CheckSeam(const Pattern& pattern, const Seam& seam, const std::string& what,
               bool seam_counts) {
  const std::string where = what + ": seam '" + seam.name + "'";
  size_t counts[2];
  int k = 0;
  for (const SeamSide* side : {&seam.a, &seam.b}) {
    const int p = pattern.FindPiece(side->piece);
    if (p < 0) throw InputError(where + " names unknown piece '" + side->piece + "'");
    const int n = pattern.pieces[p].num_vertices();
    if (side->from < 0 || side->from >= n || side->to < 0 || side->to >= n)
      throw InputError(where + ": vertex range " + std::to_string(side->from) + ".." +
                       std::to_string(side->to) + " outside piece '" + side->piece + "'");
    counts[k++] = SeamIndices(*side, n).size();
  }
  if (seam_counts && counts[0] != counts[1])
    throw InputError(where + ": sides have different point counts (" + std::to_string(counts[0]) +
                     " on '" + seam.a.piece + "', " + std::to_string(counts[1]) + " on '" +
                     seam.b.piece + "'); stitches pair point i with point i");
  if (counts[0] < 2) throw InputError(where + ": a seam side needs at least 2 points");
}

void CheckBinding(const Pattern& pattern, const MeasurementBinding& b, const std::string& what) {
  const std::string where = what + ": binding '" + b.id + "'";
  if (b.measurement.empty() && !b.fixed && b.follows.empty())
    throw InputError(where + " has no measurement name");
  if (!b.follows.empty()) {
    const MeasurementBinding* leader = nullptr;
    for (const MeasurementBinding& other : pattern.bindings)
      if (other.id == b.follows) leader = &other;
    if (leader == nullptr || leader == &b || !leader->follows.empty())
      throw InputError(where + " follows '" + b.follows +
                       "', which is not another binding with a measurement or a fixed one");
  }
  if (!b.keep_ease.empty() && b.keep_ease != "mm" && b.keep_ease != "percent")
    throw InputError(where + ": kept ease is \"mm\" or \"percent\"");
  if (!std::isfinite(b.ease_mm) || !std::isfinite(b.ease_percent) || b.ease_percent <= -100)
    throw InputError(where + ": ease must be finite and above -100 %");
  if (b.terms.empty()) throw InputError(where + " has no terms");
  for (const BindingTerm& t : b.terms) {
    const int p = pattern.FindPiece(t.piece);
    if (p < 0) throw InputError(where + " names unknown piece '" + t.piece + "'");
    const Piece& piece = pattern.pieces[p];
    for (const std::string& l : {t.from, t.to}) {
      const int li = piece.FindLandmark(l);
      if (li < 0)
        throw InputError(where + " names unknown landmark '" + l + "' on piece '" + t.piece + "'");
      if (t.path == BindingTerm::Path::kOutline && piece.landmarks[li].vertex < 0)
        throw InputError(where + ": outline path needs landmark '" + l + "' on the outline");
    }
    if (!(t.multiplicity > 0)) throw InputError(where + ": multiplicity must be positive");
  }
}

}  // namespace

void ValidatePattern(const Pattern& pattern, const std::string& what, bool seam_counts) {
  if (pattern.pieces.empty()) throw InputError(what + ": pattern has no pieces");
  std::set<std::string> names;
  for (const Piece& piece : pattern.pieces) {
    if (piece.name.empty()) throw InputError(what + ": a piece has no name");
    if (!names.insert(piece.name).second)
      throw InputError(what + ": duplicate piece name '" + piece.name + "'");
    CheckPiece(piece, what);
  }
  for (const Seam& seam : pattern.seams) CheckSeam(pattern, seam, what, seam_counts);
  std::set<std::string> ids;
  for (const MeasurementBinding& b : pattern.bindings) {
    if (!ids.insert(b.id).second) throw InputError(what + ": duplicate binding id '" + b.id + "'");
    CheckBinding(pattern, b, what);
  }
}

}  // namespace bespoke
