// The three objectives of thesis 4.2.4, evaluated for a gene vector, and the
// residual vectors the final polish (polish.h) works on.
//
//  measurement (Eq 4.5): mean over bindings of |target - achieved| (mm), with
//    target = body measurement + the binding's design ease.
//  seam (Eq 4.6-4.8): per seam, (sum of |angle differences| at the paired
//    inner seam points (deg) + sum of |edge length differences| of paired
//    seam edges (mm)) / points, averaged over seams. Deviation: differences
//    are taken relative to the base pattern (and the designed seam ease is
//    spread over the edges), because two well-matched sides of a curved seam
//    (sleeve head vs armhole) legitimately differ in angle and length.
//  shape: mean |change of turning angle| over all outline vertices (deg);
//    scale-invariant, so proportional grading has shape change 0.
// Also reported: the largest binding error, the critical-point angle change
// (the thesis's higher-level selection criterion) and the worst seam total
// length mismatch.
#ifndef BESPOKE_RESIZE_GA_OBJECTIVES_H_
#define BESPOKE_RESIZE_GA_OBJECTIVES_H_

#include <Eigen/Core>
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
  double max_structure_mm = 0;    // largest structure-rule violation (StructureResiduals, mm)
  bool simple = true;             // every outline free of self-intersections (final checks only)
};

// Everything fixed during one fit: the base pattern, its blocks, targets and
// base angles. Evaluate() is thread-safe (it uses no shared mutable state).
class FitnessModel {
 public:
  // `structure` (same pieces and vertex counts as `base`; defaults to `base`)
  // gives the directions of folds, level lines and grain lines, the square
  // corners' angles and the darts that the structure rules keep.
  FitnessModel(const Pattern& base, const BlockSet& blocks, const MeasurementSet& body,
               const Pattern* structure = nullptr);

  Objectives Evaluate(const Eigen::VectorXd& genes, bool check_simple = false) const;

  // Per binding: target (mm) and achieved (mm) for `genes`.
  std::vector<double> Targets() const { return targets_; }
  std::vector<double> Achieved(const Eigen::VectorXd& genes) const;
  // Per seam: length(a) - length(b) - ease (mm).
  std::vector<double> SeamMismatch(const Eigen::VectorXd& genes) const;

  // Binding errors then seam length mismatches (mm), for `genes`.
  void Constraints(const Eigen::VectorXd& genes, Eigen::VectorXd* constraints) const;

  // The structure rules, one residual each (mm), 0 when kept: a fold's,
  // level line's or grain line's far end off its reference direction
  // (the sideways offset), a square corner's angle change x 100 mm/rad, a
  // dart's leg-length difference. Straight runs need none (EvalOutline
  // keeps them straight).
  void StructureResiduals(const Eigen::VectorXd& genes, Eigen::VectorXd* residuals) const;
  int num_structure() const { return num_structure_; }

  // For the polish: hard constraints (binding errors, seam length
  // mismatches, then the structure rules; mm) and soft residuals (turning-angle changes at every
  // outline edge's direction change scaled by `angle_scale_mm` per radian (keeps inner angles and
  // the piece's orientation to the grain), paired-edge differences in mm, paired seam-angle
  // differences scaled likewise). With `only_piece` >= 0 and `reuse_soft` (the soft residuals of
  // genes that differ from these only in that piece's control points), soft entries that do not
  // depend on that piece are copied instead of recomputed (for the polish's finite differences).
  // With `length_scale_mm` > 0 the soft residuals also hold, per outline
  // edge, its relative length change from the base pattern scaled by
  // `length_scale_mm` (length_scale_mm x (length / base length - 1)).
  void Residuals(const Eigen::VectorXd& genes, double angle_scale_mm, double length_scale_mm,
                 Eigen::VectorXd* constraints, Eigen::VectorXd* soft, int only_piece = -1,
                 const Eigen::VectorXd* reuse_soft = nullptr) const;

  const Pattern& base() const { return base_; }
  const BlockSet& blocks() const { return blocks_; }

 private:
  struct SeamData {
    int piece_a, piece_b;
    std::vector<int> a, b;            // vertex indices in stitch order
    std::vector<double> edge_target;  // target la_i - lb_i per edge (mm)
    std::vector<double> angle_base;   // base turning(a) - turning(b) at inner points (rad)
    double ease = 0;
  };
  void Outlines(const Eigen::VectorXd& genes, std::vector<Outline>* outlines) const;
  double BindingAchieved(size_t b, const Eigen::VectorXd& genes,
                         const std::vector<Outline>& outlines) const;

  struct Direction {  // a fold, level line or grain line kept at its reference direction
    int piece;
    int kind;  // 0 outline vertices a-b, 1 landmarks a-b, 2 grain line
    int a, b;
    Eigen::Vector2d unit;
  };
  void Structure(const Eigen::VectorXd& genes, const std::vector<Outline>& outlines,
                 std::vector<double>* out) const;

  Pattern base_;
  BlockSet blocks_;
  std::vector<Direction> directions_;
  std::vector<std::pair<int, int>> corners_;  // piece, vertex
  std::vector<double> corner_turning_;        // reference turning (rad)
  std::vector<std::pair<int, Dart>> darts_;
  int num_structure_ = 0;
  std::vector<double> targets_;
  std::vector<SeamData> seams_;
  std::vector<Eigen::VectorXd> base_turning_;    // per piece, radians
  std::vector<Eigen::VectorXd> base_direction_;  // per piece, edge directions, radians
  std::vector<Eigen::VectorXd> base_length_;     // per piece, edge lengths, mm (>= 1e-3)
};

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_OBJECTIVES_H_
