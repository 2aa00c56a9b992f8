// The sewing-pattern model every resize/ algorithm and format speaks.
//
// A pattern is a set of pieces. Each piece is a closed outline (the sew
// line) in millimetres, in the piece's own 2-D frame (x right, y up), stored
// as a polyline of #V vertices counter-clockwise, the closing edge implied
// (the last vertex is NOT a repeat of the first). Curves are sampled into the
// polyline when a pattern is built or imported.
//
// On a piece: critical points (outline vertex indices: the corners and turning
// points that carry the design, through which the GA's control grid passes),
// landmarks (named points tied to body datum points; on the outline by index,
// or inside the piece by position), notches (outline indices), a grain line,
// internal lines (darts, placement lines) and the cut count.
//
// Across pieces: seams (two runs of outline vertices, stitched point i to
// point i, so both runs have the same number of points) and measurement
// bindings (a body measurement + design ease = the sum of landmark-pair
// distances, straight or along the outline, each times a multiplicity).
// The JSON form is documented in docs/pattern-format.md.
#ifndef BESPOKE_RESIZE_PATTERN_PATTERN_H_
#define BESPOKE_RESIZE_PATTERN_PATTERN_H_

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace bespoke {

using Outline = Eigen::Matrix<double, Eigen::Dynamic, 2>;  // #V x 2, mm

struct PieceLandmark {
  std::string name;   // unique on its piece, e.g. "cb_neck"
  std::string datum;  // body datum point it is tied to (catalogue name), may be empty
  int vertex = -1;    // outline index, or -1 for a point inside the piece
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // mm; used when vertex < 0
};

// A run of outline vertices that lie on one straight line (a straight edge,
// a fold or centre line), walking forward from `from` to `to`; resizing keeps
// it straight (its inner vertices stay on the chord between its ends).
struct StraightRun {
  int from = 0, to = 0;
  bool fold = false;  // a fold or centre line: it also keeps its direction to the grain
};

// A level line (chest, waist, hip, hem): two landmarks whose connecting line
// stays perpendicular to the grain, i.e. keeps its direction in the piece.
struct LevelLine {
  std::string name;
  std::string from, to;  // landmark names on the piece
};

// A dart: its two legs, apex to `leg_a` and apex to `leg_b` (outline
// indices), keep equal lengths.
struct Dart {
  int apex = 0, leg_a = 0, leg_b = 0;
};

struct Piece {
  std::string name;           // unique in the pattern, e.g. "front"
  Outline outline;            // #V x 2 sew line, mm, counter-clockwise
  std::vector<int> critical;  // outline indices of critical points
  std::vector<PieceLandmark> landmarks;
  std::vector<int> notches;  // outline indices
  bool has_grain = false;
  Eigen::Vector2d grain_start = Eigen::Vector2d::Zero();  // mm
  Eigen::Vector2d grain_end = Eigen::Vector2d::Zero();    // mm, arrow end
  std::vector<Outline> internal_lines;                    // open polylines, mm
  int cut_count = 1;                                      // pieces to cut
  bool mirrored = false;                                  // cut as mirrored pairs (left/right)
  bool on_fold = false;                                   // cut on the fold (a half piece)
  std::vector<StraightRun> straight;                      // straight edges, fold lines
  std::vector<StraightRun> not_straight;  // ranges never inferred as straight (InferStructure)
  std::vector<int> right_angles;          // outline indices of corners that stay square
  std::vector<LevelLine> level_lines;
  std::vector<Dart> darts;

  int num_vertices() const { return static_cast<int>(outline.rows()); }
  // Index of the landmark called `name`, or -1.
  int FindLandmark(const std::string& name) const;
  // Position of landmark `index` (outline vertex or inside point), mm.
  Eigen::Vector2d LandmarkPosition(int index) const;
};

// One side of a seam: the outline vertices of `piece` from `from` to `to`
// inclusive, walking forward (index + 1, wrapping) or backward.
struct SeamSide {
  std::string piece;
  int from = 0;
  int to = 0;
  bool forward = true;
};

struct Seam {
  std::string name;
  SeamSide a, b;       // stitched point i of a to point i of b
  double ease_mm = 0;  // designed length(a) - length(b), e.g. sleeve-head ease
};

struct BindingTerm {
  enum class Path { kStraight, kOutline };
  std::string piece;
  std::string from, to;         // landmark names on `piece`
  Path path = Path::kStraight;  // kOutline walks forward from `from` to `to`
  double multiplicity = 1;      // e.g. 2 for a half piece cut twice
};

struct MeasurementBinding {
  std::string id;           // unique, e.g. "chest"
  std::string measurement;  // catalogue measurement name, e.g. "chest_girth"; empty when fixed
  std::vector<BindingTerm> terms;
  // Target = body measurement x (1 + ease_percent / 100) + ease_mm.
  double ease_mm = 0;
  double ease_percent = 0;
  // "mm" or "percent": the ease is the base pattern's own at Pattern::base_body
  // (ResolveKeptEase sets ease_mm or ease_percent); "" when given.
  std::string keep_ease;
  // A style dimension that does not grade (a cuff depth, a pocket width):
  // target = the base pattern's own value; `measurement` is empty.
  bool fixed = false;
  double fixed_mm = 0;  // the kept value when `fixed` (mm)
  // The id of another binding (one with a measurement, or fixed) this one
  // grades with: target = its base value x that binding's target / that
  // binding's base value (a dimension no measurement gives, such as an
  // armhole depth, graded in proportion to the chest); `measurement` is
  // empty. "" when not used.
  std::string follows;
};

struct Pattern {
  std::string name;
  std::string source;  // where it came from ("design shirt (Aldrich)", a file)
  std::vector<Piece> pieces;
  std::vector<Seam> seams;
  std::vector<MeasurementBinding> bindings;
  // What an importer did to the file's geometry (outlines turned
  // counter-clockwise, seam runs resampled), one readable line each.
  std::vector<std::string> notes;
  // The body measurements the base pattern was drafted for (name -> mm); may
  // be empty. Needed by bindings that keep the base's own ease.
  std::map<std::string, double> base_body;

  // Index of the piece called `name`, or -1.
  int FindPiece(const std::string& name) const;
};

// Vertex indices of a seam side, in stitch order.
std::vector<int> SeamIndices(const SeamSide& side, int num_vertices);

// Outline vertices walked forward from `from` to `to` inclusive (the
// indices of a forward seam side between them).
std::vector<int> ForwardRun(int from, int to, int num_vertices);

// Length of a binding term on `piece` (mm).
double TermLength(const Piece& piece, const BindingTerm& term);

// Current value of a binding: sum of multiplicity * term length (mm).
double BindingValue(const Pattern& pattern, const MeasurementBinding& binding);

// Sum of edge lengths along a seam side (mm).
double SeamLength(const Piece& piece, const SeamSide& side);

// Checks the pattern's structure; throws InputError("<what>: <problem>") on
// the first problem: fewer than 3 vertices, non-finite coordinates, a
// self-intersecting outline, unknown pieces/landmarks, out-of-range indices,
// seams whose sides have different point counts, outline terms on inside
// landmarks. `what` names the file or design in messages.
// Without `seam_counts`, seam sides of different point counts are accepted
// (an importer resamples them next, EqualizeSeamCounts).
void ValidatePattern(const Pattern& pattern, const std::string& what, bool seam_counts = true);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_PATTERN_H_
