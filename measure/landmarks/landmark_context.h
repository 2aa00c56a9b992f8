// The landmark detector's working state, shared by its stages (internal to
// measure/landmarks; the public interface is landmarks.h).
//
// Stages, in order (each in its own .cc): trunk levels and the crotch
// (landmark_trunk.cc; the under-bust in landmark_under_bust.cc), armpits
// and axilla folds (landmark_armpits.cc), neck and shoulders
// (landmark_neck.cc), arms (landmark_arms.cc), legs (landmark_legs.cc). A
// stage reads what earlier ones found from `found`.
// Sides: a paired stage runs once per side with `sign` = +1 for the right
// (+x) and -1 for the left; it works in x' = sign * x.
#ifndef BESPOKE_MEASURE_LANDMARKS_LANDMARK_CONTEXT_H_
#define BESPOKE_MEASURE_LANDMARKS_LANDMARK_CONTEXT_H_

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "measure/cloud_geodesic/point_index.h"
#include "measure/landmarks/body_structure.h"
#include "measure/landmarks/landmark_slices.h"
#include "measure/landmarks/landmarks.h"
#include "scanners/core/constants.h"

namespace bespoke::landmarks {

// What the armpit stage learnt about one arm (used by later stages).
struct ArmInfo {
  bool found = false;
  bool t_pose = false;    // the arm leaves the trunk above the armpit, not beside it
  bool touching = false;  // no gap between arm and trunk was seen
  double armpit_z = 0;    // height where arm and trunk sections join (mm)
  Eigen::Vector3d armpit = Eigen::Vector3d::Zero();
  // Centre line of the arm from the armpit outwards (body frame, mm).
  std::vector<Eigen::Vector3d> centre_line;
  std::vector<int> rows;  // cloud rows of the arm below/beyond the armpit (may repeat)
};

struct Context {
  const Eigen::MatrixX3d& points;
  const Eigen::MatrixX3d& normals;  // #P x 3 outward unit normals, or 0 x 3
  std::unique_ptr<PointIndex> index;
  std::vector<Slice> slices;
  // The parts from geodesic structure (body_structure.h); when it failed
  // (structure.ok false) the stages fall back to slice pieces alone.
  BodyStructure structure;
  double step = 5;
  double crown_z = 0;  // stature (mm)
  double crotch_z = 0;
  ArmInfo arm[2];  // [0] right, [1] left
  LandmarkSet found;

  Context(const Eigen::MatrixX3d& p, const Eigen::MatrixX3d& n) : points(p), normals(n) {}
  bool has_normals() const { return normals.rows() == points.rows() && points.rows() > 0; }
  Eigen::Vector3d P(int row) const { return points.row(row).transpose(); }
  const Slice& At(double z) const { return slices[static_cast<size_t>(SliceAt(slices, z))]; }

  // Records a landmark; flags "in_hole" when no scan point lies within
  // 12 mm (the position was interpolated over a hole).
  void Put(const std::string& name, const Eigen::Vector3d& position, double confidence,
           const std::string& method, std::vector<std::string> flags = {});
  void Missing(const std::string& name, const std::string& why);
  bool Has(const std::string& name) const { return found.Has(name); }
  Eigen::Vector3d Pos(const std::string& name) const { return found.points.at(name).position_mm; }

  // The row among `candidates` that is most extreme along `direction` once
  // the scan's noise is averaged out: the candidates within `band_mm` of
  // the raw extreme are scored by the mean of p . direction over their
  // cloud neighbours within `radius_mm`. -1 when `candidates` is empty.
  int SmoothExtreme(const std::vector<int>& candidates, const Eigen::Vector3d& direction,
                    double radius_mm = 12, double band_mm = 6) const;
  // The row nearest the centre of the cap the candidates form at their
  // extreme along `direction` (unit): the mean position of those within
  // `depth_mm` of the extreme, which the fifth highest value sets so that
  // no single noisy point does. On a rounded corner the extreme value is
  // flat along the curve and the single most extreme point wanders; the
  // cap's centre does not. -1 when `candidates` is empty.
  int CapCentre(const std::vector<int>& candidates, const Eigen::Vector3d& direction,
                double depth_mm = 5) const;
  // Rows of the trunk in slice `s`: those the structure labels trunk; without
  // a structure, the pieces reaching the body's middle (|x| < core_mm),
  // which arms and hands away from the body never do.
  std::vector<int> TrunkRows(const Slice& s, double core_mm = 50) const;
  // The part of cloud row `row` (kTrunk without a structure).
  Part PartOf(int row) const {
    return structure.ok ? structure.part[static_cast<size_t>(row)] : Part::kTrunk;
  }
  // Trunk pieces of slice `s` (indices into s.pieces).
  std::vector<int> TrunkPieces(const Slice& s, double core_mm = 50) const;
};

std::string Side(int sign);

// The centre-line point (|x| < half_width_mm) of the trunk at height z, on
// the front (most forward) or back; false when the slices within 15 mm
// hold none. `out` gets z exactly.
bool SeamPoint(const Context& c, double z, bool front, Eigen::Vector3d* out,
               double half_width_mm = 10);
// Puts `name` at SeamPoint(z, front), or marks it missing.
void PutSeam(Context* c, const std::string& name, double z, bool front, double confidence,
             const std::string& method);  // "_right" for +1, "_left" for -1

void FindCrownAndCrotch(Context* c);
void FindArmpits(Context* c);
void FindTrunkLevels(Context* c);
// The under-bust fold's height (mm), placed as "under_bust"; -1 (and the
// point missing) without a bust point (landmark_under_bust.cc).
double FindUnderBust(Context* c);
void FindNeckAndShoulders(Context* c);
void FindArms(Context* c);
void FindLegs(Context* c);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_LANDMARK_CONTEXT_H_
