// The three objectives of thesis 4.2.4, evaluated for a gene vector, and the
// hard constraints (with their Jacobian) that the graded start and the
// polish solve (grader.h, polish.h).
//
//  measurement (Eq 4.5): mean over bindings of |target - achieved| (mm), with
//    target = body measurement + the binding's design ease.
//  seam (Eq 4.6-4.8): per seam, (sum of |angle differences| at the paired
//    inner seam points (deg) + sum of |edge length differences| of paired
//    seam edges (mm)) / points, averaged over seams. Deviation: differences
//    are taken relative to the base pattern (and the designed seam ease is
//    spread over the edges), because two well-matched sides of a curved seam
//    (sleeve head vs armhole) legitimately differ in angle and length.
//  shape: mean |change of turning angle| from the shape reference over all
//    outline vertices of the pieces a binding or seam reaches (deg); the
//    reference is the base until SetShapeReference names another (resize.h:
//    the graded start). Scale-invariant: proportional grading of the
//    reference has shape change 0.
// Also reported: the largest binding error, the critical-point angle change
// (the thesis's higher-level selection criterion), the worst seam total
// length mismatch and the largest structure-rule violation.
#ifndef BESPOKE_RESIZE_GA_OBJECTIVES_H_
#define BESPOKE_RESIZE_GA_OBJECTIVES_H_

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "resize/ga/block.h"
#include "resize/pattern/measurements.h"
#include "resize/pattern/pattern.h"

namespace bespoke {

struct Objectives {
  double measurement_mm = 0;      // Eq 4.5 (mean |error| over bindings)
  double seam = 0;                // Eq 4.8 (mixed deg + mm per point)
  double shape_deg = 0;           // mean |turning-angle change| over outline vertices
  double max_measurement_mm = 0;  // largest |binding error|
  double critical_shape_deg = 0;  // mean |turning-angle change| at critical points
  double max_seam_length_mm = 0;  // largest |length(a) - length(b) - ease| over seams
  double max_structure_mm = 0;    // largest structure-rule violation (Constraints, mm)
  bool simple = true;             // every outline free of self-intersections (final checks only)
};

// atan2(y, x) within 1e-14 rad of the C library's (a range reduction to
// |t| <= tan(15 deg) and the series), for the turning angle at every outline
// vertex of every individual the GA evaluates, where std::atan2 took half
// the evaluation's time. Non-finite or zero arguments go to std::atan2.
double FastAtan2(double y, double x);

// Everything fixed during one fit: the base pattern, its blocks, targets and
// base angles. Const members are thread-safe (no shared mutable state).
class FitnessModel {
 public:
  FitnessModel(const Pattern& base, const BlockSet& blocks, const MeasurementSet& body);

  Objectives Evaluate(const Eigen::VectorXd& genes, bool check_simple = false) const;

  // Measures the shape objective from the pattern of `genes` instead of the
  // base: the turning angles the GA keeps are then that pattern's.
  void SetShapeReference(const Eigen::VectorXd& genes);

  // Per binding: target (mm) and achieved (mm) for `genes`.
  const std::vector<double>& Targets() const { return targets_; }
  std::vector<double> Achieved(const Eigen::VectorXd& genes) const;
  // Per seam: length(a) - length(b) - ease (mm).
  std::vector<double> SeamMismatch(const Eigen::VectorXd& genes) const;

  // The hard constraints, 0 when met (mm): every binding's error, every
  // seam's total length mismatch, then the structure rules: a fold's, level
  // line's or grain line's far end off its base direction (the sideways
  // offset), a square corner's turning change x 100 mm/rad, a dart's
  // leg-length difference, a straight run's critical inner vertex's
  // distance from the run's chord (between critical vertices EvalOutline
  // keeps runs straight), and a notch's shift along the outline from its
  // base fraction between the structure points that bound it
  // (design_points.h NotchRun; notches a straight run already holds at
  // their fraction are left out). With `jacobian`, also d constraints /
  // d genes (#c x #genes).
  void Constraints(const Eigen::VectorXd& genes, Eigen::VectorXd* constraints,
                   Eigen::SparseMatrix<double>* jacobian = nullptr) const;
  int num_bindings() const { return static_cast<int>(targets_.size()); }
  int num_seams() const { return static_cast<int>(seams_.size()); }

  // Curves keep their inflections: every curve vertex (CurveVertices of the
  // base, runs kept straight skipped) that turns by 1e-3 rad
  // or more in the base keeps its sign, and a flat one (less than 1e-3 rad)
  // between two that turn alike turns their way or by less than 1e-3 rad.
  // CurveViolations lists the vertices of `genes` that break this, each with
  // the bound to hold it to (a quarter of its base turning; half the flat
  // limit the wrong way);
  // CurveConstraints gives (turning - bound) x 100 mm/rad for a list, with
  // its Jacobian.
  struct TurningBound {
    int piece = 0, vertex = 0;
    double bound_rad = 0;
  };
  std::vector<TurningBound> CurveViolations(const Eigen::VectorXd& genes) const;
  void CurveConstraints(const Eigen::VectorXd& genes, const std::vector<TurningBound>& bounds,
                        Eigen::VectorXd* constraints,
                        Eigen::SparseMatrix<double>* jacobian = nullptr) const;

  // Per term of every binding with several terms: weight x (term length /
  // its base length - the binding's target / its base value), a girth's
  // change shared by its pieces in proportion. With `jacobian`, d / d genes.
  void Shares(const Eigen::VectorXd& genes, double weight, Eigen::VectorXd* residuals,
              Eigen::SparseMatrix<double>* jacobian = nullptr) const;

  // Per piece: whether a binding term or a seam reaches it.
  const std::vector<bool>& Driven() const { return driven_; }
  const Pattern& base() const { return base_; }
  const BlockSet& blocks() const { return blocks_; }

 private:
  using Stencil = std::vector<std::pair<int, double>>;  // (control point, weight)
  struct SeamData {
    int piece_a, piece_b;
    std::vector<int> a, b;            // vertex indices in stitch order
    std::vector<double> edge_target;  // target la_i - lb_i per edge (mm)
    std::vector<double> angle_base;   // base turning(a) - turning(b) at inner points (rad)
    double ease = 0;
    bool forward_a = true, forward_b = true;  // each side walks its outline forwards
  };
  struct Direction {  // a fold, level line or grain line kept at its base direction
    int piece;
    int a, b;  // points (PointIndex) of its ends
    Eigen::Vector2d unit;
  };
  struct TermData {  // one binding term, resolved
    int piece;
    int a, b;               // points (PointIndex) of its ends
    std::vector<int> path;  // outline vertices walked, for an outline term
    double multiplicity = 1;
    double base_length = 0;
  };

  void Outlines(const Eigen::VectorXd& genes, std::vector<Outline>* outlines) const;
  // Adds the notch rules of piece `piece` (constructor).
  void AddNotches(int piece);
  // A piece's points: outline vertices 0..V-1, then one per landmark (used
  // for inside landmarks), then the grain line's start and end; their
  // stencils (with straight runs resolved) in stencils_.
  Eigen::Vector2d Point(int piece, int point, const Eigen::VectorXd& genes,
                        const std::vector<Outline>& outlines) const;
  int LandmarkPoint(int piece, int landmark) const;
  double TermValue(const TermData& t, const Eigen::VectorXd& genes,
                   const std::vector<Outline>& outlines) const;
  void Structure(const Eigen::VectorXd& genes, const std::vector<Outline>& outlines,
                 std::vector<double>* out) const;

  Pattern base_;
  BlockSet blocks_;
  std::vector<bool> driven_;
  std::vector<std::vector<Stencil>> stencils_;  // per piece, per point
  std::vector<double> targets_;
  std::vector<std::vector<TermData>> terms_;  // per binding
  std::vector<SeamData> seams_;
  std::vector<Direction> directions_;
  std::vector<std::pair<int, int>> corners_;  // piece, vertex
  std::vector<double> corner_turning_;        // base turning (rad)
  std::vector<std::pair<int, Dart>> darts_;
  struct Collinear {  // a critical vertex kept on its straight run's chord
    int piece, a, b, v;
  };
  std::vector<Collinear> collinear_;
  struct NotchData {  // a notch kept at its base fraction of its run
    int piece;
    std::vector<int> before, after;  // outline vertices from..notch and notch..to
    double fraction;
  };
  std::vector<NotchData> notches_;
  std::vector<std::vector<int>>
      curve_sign_;  // per piece, per vertex: base sign rule (+1, -1, 0 free)
  std::vector<std::vector<bool>> curve_flat_;   // per piece, per vertex: a flat vertex
  std::vector<Eigen::VectorXd> base_turning_;   // per piece, radians
  std::vector<Eigen::VectorXd> shape_turning_;  // per piece: the shape reference's
};

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_OBJECTIVES_H_
