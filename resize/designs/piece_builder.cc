#include "resize/designs/piece_builder.h"

#include <algorithm>

#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {

int PieceBuilder::Add(const Eigen::Vector2d& p, const std::string& landmark,
                      const std::string& datum, bool critical) {
  points_.push_back(p);
  const int index = size() - 1;
  if (!landmark.empty()) {
    BESPOKE_CHECK(names_.emplace(landmark, index).second, "duplicate landmark " + landmark);
    PieceLandmark l;
    l.name = landmark;
    l.datum = datum;
    l.vertex = index;
    piece_.landmarks.push_back(l);
  }
  if (critical) critical_.push_back(index);
  return index;
}

void PieceBuilder::AddCurve(const std::vector<Eigen::Vector2d>& points, bool skip_last) {
  size_t begin = 0, end = points.size();
  if (!points_.empty() && !points.empty() && (points.front() - points_.back()).norm() < 1e-9)
    begin = 1;
  if (skip_last && end > begin) --end;
  for (size_t i = begin; i < end; ++i) points_.push_back(points[i]);
}

void PieceBuilder::AddLineTo(const Eigen::Vector2d& to, int inner_points) {
  const Eigen::Vector2d from = points_.back();
  for (int k = 1; k <= inner_points; ++k)
    points_.push_back(from + (to - from) * (static_cast<double>(k) / (inner_points + 1)));
}

void PieceBuilder::AddInside(const std::string& landmark, const Eigen::Vector2d& p,
                             const std::string& datum) {
  PieceLandmark l;
  l.name = landmark;
  l.datum = datum;
  l.position = p;
  piece_.landmarks.push_back(l);
}

void PieceBuilder::Grain(const Eigen::Vector2d& start, const Eigen::Vector2d& end) {
  piece_.has_grain = true;
  piece_.grain_start = start;
  piece_.grain_end = end;
}

void PieceBuilder::Cut(int count, bool mirrored, bool on_fold) {
  piece_.cut_count = count;
  piece_.mirrored = mirrored;
  piece_.on_fold = on_fold;
}

int PieceBuilder::Index(const std::string& landmark) const {
  const auto it = names_.find(landmark);
  BESPOKE_CHECK(it != names_.end(), "no drafted point " + landmark + " on " + piece_.name);
  return it->second;
}

Piece PieceBuilder::Build() {
  Piece piece = piece_;
  piece.outline.resize(size(), 2);
  for (int i = 0; i < size(); ++i) piece.outline.row(i) = points_[i].transpose();
  std::sort(critical_.begin(), critical_.end());
  critical_.erase(std::unique(critical_.begin(), critical_.end()), critical_.end());
  piece.critical = critical_;
  std::sort(piece.notches.begin(), piece.notches.end());
  BESPOKE_CHECK(SignedArea(piece.outline) > 0, "drafted piece " + piece.name + " is clockwise");
  return piece;
}

SeamSide Side(const PieceBuilder& b, const std::string& piece, const std::string& from,
              const std::string& to, bool forward) {
  SeamSide side;
  side.piece = piece;
  side.from = b.Index(from);
  side.to = b.Index(to);
  side.forward = forward;
  return side;
}

Eigen::Vector2d Bisector(const Eigen::Vector2d& corner, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b, double d_mm) {
  return corner + ((a - corner).normalized() + (b - corner).normalized()).normalized() * d_mm;
}

}  // namespace bespoke
