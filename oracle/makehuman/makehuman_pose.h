// Postures of MakeHuman bodies with MakeHuman's default skeleton and skin
// weights (CC0, ../shared/data/bodies/makehuman/rig/).
//
// The rig (MakeHumanRig): the bones (head and tail joints, parent) of
// default.mhskel, each joint the mean of its base.obj vertices, computed on
// the morphed body (so the skeleton follows the targets), and the skin
// weights of default_weights.mhw normalised per skin vertex (a vertex
// without weights stays with the root).
//
// Posing (PoseMakeHumanSkin): linear blend skinning. A posture is a
// rotation R_b per bone, expressed in the rest pose's body frame about the
// bone's head joint h_b; a bone's transform composes its parent's with its
// own, G_b = G_parent * T(h_b) R_b T(-h_b), so a rotation moves the whole
// chain below the bone, and a skin vertex moves to sum_b w_b G_b v.
//
// The postures (MakeHumanPosture), all in the body frame (+z up, facing +y):
//   arm_abduction_deg: both upper arms turned about the front axis through
//     the shoulder joint until the shoulder-to-wrist line makes this angle
//     with the vertical in the frontal plane (5 = touching the sides,
//     90 = T-pose);
//   stance_mm: both legs turned about the front axis through the hip joint
//     until the ankle joints are this far apart (the feet turned back flat);
//   lean_deg, twist_deg: the trunk bent forward / turned to the left about
//     the vertical, spread evenly over the five spine bones;
//   head_turn_deg: the neck and head turned to the left, spread over the
//     three neck bones and the head.
// Contact: arms or legs moved towards the body can press into it (a linear
// blend has no collision). With stop_at_contact (default) each limb turns
// only as far as the mesh gains no new self-intersection (faces crossing
// that did not cross in the rest pose; bisection to 0.25 deg), and the
// angle reached is reported; without it the posture is applied and the new
// crossings counted.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POSE_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POSE_H_

#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "oracle/body/body.h"
#include "scanners/core/types.h"

namespace bespoke {

class MakeHumanModel;

struct MakeHumanRig {
  struct Bone {
    std::string name;
    int parent = -1;         // index in bones, -1 for the root; parents come first
    std::string head, tail;  // joint names
  };
  std::vector<Bone> bones;
  std::map<std::string, std::vector<int>> joint_vertices;  // joint -> base.obj vertices
  // Per skin vertex (MakeHumanModel::base_body() rows): (bone index, weight),
  // weights summing to 1.
  std::vector<std::vector<std::pair<int, double>>> weights;
  int BoneIndex(const std::string& name) const;  // InputError when unknown
};

// Reads default.mhskel and default_weights.mhw from `rig_dir` for `model`'s
// skin. InputError naming the file when missing or malformed.
MakeHumanRig LoadMakeHumanRig(const std::filesystem::path& rig_dir, const MakeHumanModel& model);

// Per skin vertex (MakeHumanModel::base_body() rows), its limb: the limb
// whose bones (upper arm to fingers; upper leg to toes; ".R" the person's
// right, +x) hold more than half of its skin weight; otherwise the trunk
// (the shoulder and pelvis bones are the trunk's).
std::vector<BodyLimb> RigLimbs(const MakeHumanRig& rig);

// Joint positions: the mean of each joint's vertices in `all_vertices`
// (#base.obj vertices x 3, any frame and unit; MakeHumanModel::MorphAll).
std::map<std::string, Eigen::Vector3d> RigJoints(const MakeHumanRig& rig,
                                                 const Eigen::MatrixX3d& all_vertices);

struct MakeHumanPosture {
  std::optional<double> arm_abduction_deg;  // unset: the rest pose's arms; 0-100 deg
  std::optional<double> stance_mm;          // unset: the rest pose's legs; 0-600 mm
  double lean_deg = 0;                      // forward bend of the trunk, -30..30 deg
  double twist_deg = 0;                     // turn of the trunk to the left, -45..45 deg
  double head_turn_deg = 0;                 // turn of the head to the left, -80..80 deg
  bool stop_at_contact = true;              // limbs stop where they touch the body
  bool empty() const;
  // InputError naming the value out of range.
  void Check() const;
};

// Named postures: "rest" (MakeHuman's), "arms-5", "arms-15", "arms-30",
// "arms-45", "arms-90" (abduction), "feet-together" (stance 0: the legs
// close until they touch), "feet-40" (400 mm), "lean-5", "twist-5",
// "head-turn" (30 deg); joined with '+' they combine ("arms-30+feet-40").
// InputError naming the known ones for another name.
MakeHumanPosture ParseMakeHumanPosture(const std::string& name);
const std::vector<std::string>& MakeHumanPostureNames();

struct PoseResult {
  Eigen::MatrixX3d vertices;              // #V x 3 posed skin, same frame and unit as input
  std::map<std::string, double> reached;  // "arm_abduction_deg", "stance_mm", ... reached
  std::map<std::string, double> rest;     // the same quantities in the rest pose
  int new_self_intersections = 0;         // face pairs crossing that did not at rest
  bool arms_stopped = false, legs_stopped = false;  // stopped at contact before the target
  // Per rig bone (MakeHumanRig::bones order), its rest-to-posed transform in
  // the input's frame (G_b above): a point fixed to the bone moves by it.
  std::vector<Eigen::Affine3d> bone_from_rest;
};

// Poses a skin.
// @param[in] skin   the rest skin, body frame (mm), topology of base_body()
// @param[in] joints RigJoints of the same body, body frame (mm)
// InputError for a bad posture.
PoseResult PoseMakeHumanSkin(const MakeHumanRig& rig, const TriangleMesh& skin,
                             const std::map<std::string, Eigen::Vector3d>& joints,
                             const MakeHumanPosture& posture);

// Linear blend skinning with given rotations (bone index -> rotation in the
// body frame about the bone's head joint); bones not listed do not turn.
// @param[in] rest #V x 3 rest skin; returns #V x 3.
Eigen::MatrixX3d SkinWithRotations(const MakeHumanRig& rig, const Eigen::MatrixX3d& rest,
                                   const std::map<std::string, Eigen::Vector3d>& joints,
                                   const std::map<int, Eigen::Matrix3d>& rotations);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_POSE_H_
