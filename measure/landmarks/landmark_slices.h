// Horizontal slice profiles of a body-framed cloud, the shared state of the
// landmark detector (measure/landmarks/landmarks.h; internal to it).
//
// A slice at height z holds the points within `half_thickness_mm` of the
// plane z; its points are split into 2-D pieces: points closer than
// `link_mm` (in x, y) are linked, and a piece is a connected set. Pieces are
// what the trunk, the arms and the legs look like in the slice; the gaps
// between pieces (not the mere presence of points, which holes break) are
// what the detector reads the armpits and the crotch from.
// Frame: the body frame (mm, +z up, facing +y, the person's right is +x).
#ifndef BESPOKE_MEASURE_LANDMARKS_LANDMARK_SLICES_H_
#define BESPOKE_MEASURE_LANDMARKS_LANDMARK_SLICES_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke::landmarks {

struct Piece {
  std::vector<int> rows;                         // rows of the cloud
  Eigen::Vector2d lo = Eigen::Vector2d::Zero();  // min x, min y (mm)
  Eigen::Vector2d hi = Eigen::Vector2d::Zero();  // max x, max y (mm)
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
};

struct Slice {
  double z = 0;           // plane height (mm)
  std::vector<int> rows;  // every point of the slice
  std::vector<Piece> pieces;
};

struct SliceOptions {
  double step_mm = 5;            // default 5 mm: spacing of the slice planes
  double half_thickness_mm = 4;  // default 4 mm: points within this of a plane
  double link_mm = 12;           // default 12 mm: points closer than this (xy) are one piece
};

// Slices from the lowest to the highest point; slice i is at z_min + i * step.
std::vector<Slice> SliceCloud(const SliceOptions& options, const Eigen::MatrixX3d& points);

// The pieces of `rows` (2-D connectivity in x, y at `link_mm`).
std::vector<Piece> SplitPieces(const Eigen::MatrixX3d& points, const std::vector<int>& rows,
                               double link_mm);

// Index of the slice nearest height z (clamped).
int SliceAt(const std::vector<Slice>& slices, double z);

// Smallest xy distance between two pieces' points (mm).
double PieceGap(const Eigen::MatrixX3d& points, const Piece& a, const Piece& b);

// Perimeter of the 2-D convex hull of the rows' xy (mm).
double HullPerimeter(const Eigen::MatrixX3d& points, const std::vector<int>& rows);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_LANDMARK_SLICES_H_
