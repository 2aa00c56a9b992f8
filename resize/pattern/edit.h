// Edits of an imported pattern that keep every index consistent: turning an
// outline counter-clockwise, resampling the two sides of a seam to the same
// number of points, and inferring the design's structure (straight runs,
// folds, square corners) from the geometry.
//
// Every edit remaps all outline indices that refer to the piece (critical
// points, notches, landmarks, straight runs, right angles, darts, seam ends)
// and adds a readable line to Pattern::notes saying what it did.
#ifndef BESPOKE_RESIZE_PATTERN_EDIT_H_
#define BESPOKE_RESIZE_PATTERN_EDIT_H_

#include <string>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

// Replaces the outline of piece `p` with `outline` (#V' x 2, mm), where
// old_to_new[v] is the new index of old vertex v (#V entries), and remaps
// every index that refers to it. When `reversed`, seam sides on the piece
// swap direction and outline binding terms swap their ends.
void ReplaceOutline(Pattern* pattern, int p, const Outline& outline,
                    const std::vector<int>& old_to_new, bool reversed = false);

// Makes every inside landmark (given by position) that lies within
// `tolerance_mm` of its piece's outline an outline landmark: it takes the
// vertex there, or a vertex is added on the edge (which does not change the
// outline's shape), so the landmark moves with the outline (a centre-back
// chest point stays on the fold line). Notes say which.
void LandmarksOntoOutline(Pattern* pattern, double tolerance_mm = 0.5);

// Turns every clockwise outline counter-clockwise (notes say which).
void MakeCounterClockwise(Pattern* pattern);

// Gives both sides of every seam the same number of points: each side keeps
// all its vertices and gains one at the arc-length fraction of each vertex of
// the other side (fractions closer than `merge_mm` of arc count as one), so
// stitch i pairs points at equal fractions of the two runs and no outline
// changes shape. Notes say which seams were resampled.
void EqualizeSeamCounts(Pattern* pattern, double merge_mm = 1.0);

struct StructureOptions {
  // An inner vertex within this distance of the chord of its run counts as
  // on a straight line (mm). Default 0.05 mm.
  double straight_tolerance_mm = 0.05;
  // A run's chord must be at least this long to count as a straight edge
  // (mm). Default 20 mm.
  double min_straight_mm = 20;
  // A corner whose inner angle is within this of 90 degrees, between two
  // straight runs, counts as square (deg). Default 1 deg.
  double right_angle_tolerance_deg = 1;
};

// Adds to every piece the straight runs with inner vertices (maximal runs of
// collinear vertices), the square corners between straight runs, and, on a
// piece cut on the fold, the fold: the longest straight edge along the grain
// (along y when the piece has no grain). Runs, corners and folds already on
// the piece are kept; `not_straight` ranges (from the sidecar) are skipped.
void InferStructure(const StructureOptions& options, Pattern* pattern);

// Adds to every piece's critical points its outline landmarks, the ends of
// its straight runs, its square corners and its darts' vertices, so the
// control grid (and the graded start's grid lines) passes through them.
void AddStructureCriticalPoints(Pattern* pattern);

// The unit grain direction of a piece in its frame: its grain line, else its
// first fold, else +y.
Eigen::Vector2d GrainDirection(const Piece& piece);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_EDIT_H_
