// The body's structure from geodesic distances over the scan's surface
// (internal to measure/landmarks): where the head, hands and feet are, where
// the limbs join the trunk, and which points belong to which part. It does
// not depend on the posture: a T-pose, arms hanging against the sides and
// thighs that touch give the same structure, because the surface graph
// (body_graph.h) does not link skins that merely touch.
//
// Method (docs/landmarks.md, "Structure"):
//  1. Extremities: the maxima of the geodesic distance from the trunk's
//     ring at 60 % of stature that stand out by `persistence` of stature
//     (the merge tree of the field): the lowest on each side are the feet,
//     the highest of the rest the head, the others the hands (side by x).
//  2. Crotch: the highest node of the shortest path between the two feet
//     (the path climbs one inside leg and comes down the other; holes only
//     move it to the hole's rim).
//  3. Armpits: on the shortest path from a hand to the foot of its side,
//     the node farthest from the chord hand-foot (the corner where the path
//     leaves the arm for the trunk), in any arm posture.
//  4. Parts: a node belongs to a limb when it is geodesically closer to the
//     limb's end than the limb's junction is (arm: the armpit; leg: the
//     crotch); the rest is trunk (with neck and head).
// Frame: body frame (mm, +z up, facing +y, the person's right is +x).
#ifndef BESPOKE_MEASURE_LANDMARKS_BODY_STRUCTURE_H_
#define BESPOKE_MEASURE_LANDMARKS_BODY_STRUCTURE_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "measure/landmarks/body_graph.h"
#include "measure/landmarks/landmarks.h"

namespace bespoke::landmarks {

// kNone: a stray piece of the scan away from the body (not used).
using Part = ScanPart;  // landmarks.h

struct BodyStructureOptions {
  BodyGraphOptions graph;  // the surface graph (body_graph.h)
  // An end of the body (head, hand, foot) stands out of the distance field
  // from the trunk by at least this share of stature (default 0.1).
  double persistence = 0.1;
  // Below this share of stature the surface graph links nothing across
  // x = 0 (BodyGraphOptions::midline_apart_below_mm; default 0.3: below the
  // knees, well under any crotch, where feet set together touch).
  double legs_apart_share = 0.3;
};

struct BodyStructure {
  bool ok = false;  // false: no two feet found; the fields below are then empty
  std::string why;  // when !ok, why
  Eigen::Vector3d head = Eigen::Vector3d::Zero();
  Eigen::Vector3d foot[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  // [0] right
  bool has_hand[2] = {false, false};
  Eigen::Vector3d hand[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d crotch = Eigen::Vector3d::Zero();  // the apex of the feet's path (mm)
  bool has_armpit[2] = {false, false};
  Eigen::Vector3d armpit[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Per cloud row (#P): the part it belongs to.
  std::vector<Part> part;
  // Per cloud row (#P), per arm: geodesic distance from the hand (mm, +inf
  // where not reached); empty for an arm without a hand.
  std::vector<double> from_hand[2];
};

// `points` #P x 3 and `normals` #P x 3 (or 0 x 3) in the body frame (mm);
// `stature_mm` the crown's height. Never throws; `ok` says whether it worked.
BodyStructure FindBodyStructure(const BodyStructureOptions& options, const Eigen::MatrixX3d& points,
                                const Eigen::MatrixX3d& normals, double stature_mm);

// Gives back to the trunk the points of arm `side` (0 right, 1 left) of `s`
// that lie under and medial of the found armpit `armpit` (body frame, mm;
// `armpit_row` the cloud row nearest it) and farther from the hand than that
// row (`from_hand`): the skin between a raised arm's underside and the
// trunk's side, which the structure's corner (the bottom of that fillet,
// where the side turns vertical) leaves to the arm (a T-pose's chest
// section would lose its sides). An arm hanging beside the trunk is nearer
// the hand than its armpit and the outside of the upper arm lies lateral of
// it: both stay arm. A side without a hand distance is left as it is.
void ReturnFilletToTrunk(const Eigen::MatrixX3d& points, int side, const Eigen::Vector3d& armpit,
                         int armpit_row, BodyStructure* s);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_BODY_STRUCTURE_H_
