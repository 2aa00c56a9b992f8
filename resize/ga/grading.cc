#include "resize/ga/grading.h"

#include <algorithm>

namespace bespoke {

std::vector<double> ProportionalScales(const Pattern& pattern, const MeasurementSet& body) {
  const size_t n = pattern.pieces.size();
  std::vector<double> scale(n, 0.0);
  std::vector<bool> known(n, false);
  const std::vector<double> targets = BindingTargets(pattern, body);
  for (size_t i = 0; i < pattern.bindings.size(); ++i) {
    const MeasurementBinding& b = pattern.bindings[i];
    const double current = BindingValue(pattern, b);
    if (current <= 0) continue;
    // Sr = m_i / d (Algorithm 6 line 6), with the ease kept: target / current.
    const double ratio = targets[i] / current;
    for (const BindingTerm& t : b.terms) {
      const int p = pattern.FindPiece(t.piece);
      scale[p] = known[p] ? std::max(scale[p], ratio) : ratio;  // largest Sr (line 8)
      known[p] = true;
    }
  }
  // Unbound pieces follow the pieces they are sewn to.
  for (size_t round = 0; round < n; ++round) {
    bool changed = false;
    for (size_t p = 0; p < n; ++p) {
      if (known[p]) continue;
      double sum = 0;
      int count = 0;
      for (const Seam& s : pattern.seams) {
        const int a = pattern.FindPiece(s.a.piece), b = pattern.FindPiece(s.b.piece);
        const int other = a == static_cast<int>(p) ? b : (b == static_cast<int>(p) ? a : -1);
        if (other >= 0 && other != static_cast<int>(p) && known[other]) {
          sum += scale[other];
          ++count;
        }
      }
      if (count > 0) {
        scale[p] = sum / count;
        known[p] = true;
        changed = true;
      }
    }
    if (!changed) break;
  }
  for (size_t p = 0; p < n; ++p)
    if (!known[p]) scale[p] = 1.0;
  return scale;
}

Pattern ScalePieces(const Pattern& pattern, const std::vector<double>& scales) {
  Pattern result = pattern;
  for (size_t k = 0; k < result.pieces.size(); ++k) {
    Piece& piece = result.pieces[k];
    const Eigen::RowVector2d centre =
        0.5 * (piece.outline.colwise().minCoeff() + piece.outline.colwise().maxCoeff());
    const double s = scales[k];
    auto scale_point = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
      return centre.transpose() + s * (p - centre.transpose());
    };
    for (Eigen::Index r = 0; r < piece.outline.rows(); ++r)
      piece.outline.row(r) = scale_point(piece.outline.row(r).transpose()).transpose();
    for (PieceLandmark& l : piece.landmarks)
      if (l.vertex < 0) l.position = scale_point(l.position);
    piece.grain_start = scale_point(piece.grain_start);
    piece.grain_end = scale_point(piece.grain_end);
    for (Outline& line : piece.internal_lines)
      for (Eigen::Index r = 0; r < line.rows(); ++r)
        line.row(r) = scale_point(line.row(r).transpose()).transpose();
  }
  return result;
}

Pattern ProportionalGrade(const Pattern& pattern, const MeasurementSet& body) {
  return ScalePieces(pattern, ProportionalScales(pattern, body));
}

}  // namespace bespoke
