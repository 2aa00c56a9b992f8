// Helper for drafting pieces in code: append outline vertices (straight runs
// and sampled curves) in counter-clockwise order, naming the ones that become
// landmarks or critical points, then Build() the Piece.
//
//   PieceBuilder b("back");
//   b.Add({0, 0}, "cb_neck", "back_neck_point", /*critical=*/true);
//   b.AddCurve(SmoothCurve({...}, 8));   // first point skipped if it repeats the last
//   Piece back = b.Build();
// Build() throws InternalError when the outline is not counter-clockwise or a
// name repeats (drafting bugs, not user input).
#ifndef BESPOKE_RESIZE_DESIGNS_PIECE_BUILDER_H_
#define BESPOKE_RESIZE_DESIGNS_PIECE_BUILDER_H_

#include <map>
#include <string>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

class PieceBuilder {
 public:
  explicit PieceBuilder(std::string name) { piece_.name = std::move(name); }

  // Appends a vertex; a non-empty `landmark` names it (with the body `datum`).
  int Add(const Eigen::Vector2d& p, const std::string& landmark = "", const std::string& datum = "",
          bool critical = false);
  // Appends the points of a sampled curve; its first point is dropped when it
  // coincides with the last vertex, and its last point is dropped when
  // `skip_last` (it is added next by name).
  void AddCurve(const std::vector<Eigen::Vector2d>& points, bool skip_last = true);
  // Evenly spaced points strictly between the last vertex and `to`.
  void AddLineTo(const Eigen::Vector2d& to, int inner_points);
  // A landmark inside the piece (not on the outline).
  void AddInside(const std::string& landmark, const Eigen::Vector2d& p,
                 const std::string& datum = "");
  void MarkCritical(int index) { critical_.push_back(index); }
  void Notch(int index) { piece_.notches.push_back(index); }
  void Grain(const Eigen::Vector2d& start, const Eigen::Vector2d& end);
  void Cut(int count, bool mirrored, bool on_fold = false);

  int size() const { return static_cast<int>(points_.size()); }
  int Index(const std::string& landmark) const;  // InternalError if absent
  const Eigen::Vector2d& Last() const { return points_.back(); }
  Piece Build();

 private:
  Piece piece_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<int> critical_;
  std::map<std::string, int> names_;
};

// Seam side helper: outline run of `piece` between two named vertices.
SeamSide Side(const PieceBuilder& b, const std::string& piece, const std::string& from,
              const std::string& to, bool forward);

// The point `d_mm` from `corner` along the bisector of the angle a-corner-b
// (all in the piece's plane, mm), for Aldrich-style curves that pass "2.5 cm
// from the corner".
Eigen::Vector2d Bisector(const Eigen::Vector2d& corner, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b, double d_mm);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_DESIGNS_PIECE_BUILDER_H_
