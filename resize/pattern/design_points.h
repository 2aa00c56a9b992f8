// Where a piece's design sits on its outline beyond the structure rules of
// pattern.h: the arc-length place of every notch between the structure
// points that bound it, and the two dimensions a pattern maker checks after
// grading a shirt, the sleeve cap height and the armhole depth.
//
// Structure points of a piece: its seam ends, outline landmarks, square
// corners, ends of its straight runs and dart vertices. A notch between two
// of them keeps the fraction of the outline length between them at which it
// sits in the base: a grader keeps a notch at the same fraction of its seam,
// and two notches matched across a seam, each at its fraction of its own
// side, stay matched. A notch that is itself a structure point (a seam end,
// a landmark) is placed by that structure and has no run.
#ifndef BESPOKE_RESIZE_PATTERN_DESIGN_POINTS_H_
#define BESPOKE_RESIZE_PATTERN_DESIGN_POINTS_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

// A notch between two structure points of its piece.
struct NotchRun {
  int notch = 0;         // outline index of the notch
  int from = 0, to = 0;  // nearest structure points before and after it (forward order)
  double fraction = 0;   // outline length from..notch / from..to in the pattern it came from
};

// The notch runs of piece `piece` of `pattern`, fractions measured on that
// piece. Notches at a structure point, and notches of a piece with fewer
// than two structure points, have none.
std::vector<NotchRun> NotchRuns(const Pattern& pattern, int piece);

// How far the notch of `run` sits from its fraction on `outline` (a piece
// with the same vertices): length(from..notch) - fraction x
// length(from..to), mm along the outline.
double NotchShift(const Outline& outline, const NotchRun& run);

// A dimension a pattern maker checks after grading.
//  kCapHeight: on a sleeve (a piece with outline landmarks `back_underarm`
//    and `front_underarm`), the largest distance of a cap vertex from the
//    line between the two underarm points, perpendicular to that line. The
//    cap is the outline run between the underarm points that holds the cap
//    top landmark (`cap_top` or `crown_top`, its nearest vertex when inside)
//    when there is one, else the run that bulges less from the underarm line
//    (a cap is lower than a sleeve is long).
//  kArmholeDepth: on a piece sewn to a sleeve cap (a seam with one side
//    inside the cap run, the other on this piece), the extent along the
//    piece's grain (edit.h GrainDirection) of its vertices on those seams:
//    shoulder end to underarm on a bodice whose armhole is one run; the
//    part it carries when a yoke takes the rest.
struct DesignDimension {
  enum class Kind { kCapHeight, kArmholeDepth };
  Kind kind = Kind::kCapHeight;
  std::string piece;
  std::vector<int> vertices;  // kCapHeight: the cap run (underarm to underarm); else the armhole
};

// The dimensions of `pattern` (sleeves in piece order, then the pieces their
// caps are sewn to).
std::vector<DesignDimension> FindDesignDimensions(const Pattern& pattern);

// The value of `dimension` on `pattern` (same pieces and vertices as the one
// it was found on), mm.
double MeasureDesignDimension(const Pattern& pattern, const DesignDimension& dimension);

// The direction from the middle of the underarm line to the cap top of a
// kCapHeight dimension on `pattern` (unit).
Eigen::Vector2d CapDirection(const Pattern& pattern, const DesignDimension& cap);

// The cap height of a sleeve that carries no landmarks (another system's
// draft of it) whose cap lies towards `up` (CapDirection of the same sleeve
// where its points are named): its underarm points are its two extreme
// vertices across `up`, the height the largest distance of a vertex from
// the line between them on the `up` side, mm.
double InferredCapHeight(const Piece& sleeve, const Eigen::Vector2d& up);

// "cap_height" or "armhole_depth".
std::string DesignDimensionName(DesignDimension::Kind kind);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_DESIGN_POINTS_H_
