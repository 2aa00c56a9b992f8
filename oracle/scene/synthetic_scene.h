// A synthetic scan scene for tests: a person made of primitives standing on a
// floor, with noise, stray points and a second object, seen from a known
// scanner pose in a known unit.
//
// The person (body frame, docs/contracts.md: mm, +z up, soles on z = 0,
// facing +y, right at +x, origin between the ankles as in oracle/body),
// 1750 mm tall, A-pose:
//   legs    capsules (shin r 48, thigh r 72) on axes at x = +-100, y = 0
//   feet    boxes 100 x 250 x 70 mm centred at x = +-100 under the legs,
//           with `feet_forward` at y = 65 (toes 190 mm ahead of the ankle
//           axis, heel 60 behind), else at y = 0 (no front cue from the
//           feet); no sole faces
//   torso   ellipsoid 350 x 230 x 780 mm; neck capsule r 55
//   head    ellipsoid 156 x 196 x 200 mm, top at z = 1750; with
//           `head_forward` its centre is 25 mm ahead of the neck and a nose
//           sticks out in front
//   arms    capsules from the shoulders, 30 degrees out from vertical; a
//           hand capsule beyond each wrist, separated from the forearm by an
//           unscanned band of `wrist_gap_mm` (0: joined)
// Only the union's outer surface is sampled (samples inside another part are
// dropped), uniformly by area, each with its true outward normal, and moved
// along it by Gaussian noise.
// The rest: a square floor patch at z = 0 (not under the feet or the
// object), a box 200 x 200 x 1100 mm (a pole, a coat stand) whose nearest
// face is `object_gap_mm` to the right of the right hand, isolated stray points and clumps of 3
// stray points at least 40 mm from every surface, within the surfaces' bounding box grown by 50 mm
// (some below the floor). Note the whole scene's extent decides whether a reader can guess the unit
// (GuessLengthUnit accepts 0.5-2.6 m): a small floor and no object keep any rotation of it
// under 2.6 m. Finally every point and normal is mapped by `scanner_from_body` and the points are
// divided by `mm_per_unit` (1000 writes metres).
#ifndef BESPOKE_ORACLE_SCENE_SYNTHETIC_SCENE_H_
#define BESPOKE_ORACLE_SCENE_SYNTHETIC_SCENE_H_

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke::testing {

enum class ScenePart : std::uint8_t { kBody, kFloor, kObject, kOutlier };

struct SyntheticSceneOptions {
  unsigned seed = 1;
  double spacing_mm = 4.0;  // mean distance between samples on a surface
  double noise_mm = 1.0;    // sigma of the noise along the normal
  bool floor = true;
  double floor_half_size_mm = 800.0;  // the floor is a square of twice this side
  bool second_object = true;
  double object_gap_mm = 150.0;
  int isolated_outliers = 400;
  int outlier_clumps = 60;  // of 3 points each
  double wrist_gap_mm = 0.0;
  bool feet_forward = true;
  bool head_forward = true;
  Eigen::Isometry3d scanner_from_body = Eigen::Isometry3d::Identity();
  double mm_per_unit = 1.0;
};

struct SyntheticScene {
  PointCloud cloud;               // scanner frame, file units, no normals
  Eigen::MatrixX3d true_normals;  // #P x 3, scanner frame; floor +up, outliers 0
  std::vector<ScenePart> part;    // #P
  Eigen::Isometry3d scanner_from_body = Eigen::Isometry3d::Identity();
  double mm_per_unit = 1.0;
  double height_mm = 1750.0;
  double right_hand_max_x_mm = 0.0;  // body frame: the hand's outermost x

  std::int64_t Count(ScenePart p) const;
  // Rows of `cloud.points` (times mm_per_unit: mm) belonging to part p.
  Eigen::MatrixX3d PointsMm(ScenePart p) const;
};

SyntheticScene MakeSyntheticScene(const SyntheticSceneOptions& options);

// A rigid transform with a uniformly random rotation and a translation of
// each coordinate uniform in [-max_translation_mm, max_translation_mm].
Eigen::Isometry3d RandomRigid(unsigned seed, double max_translation_mm);

// Angle between two unit vectors, degrees.
double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace bespoke::testing

#endif  // BESPOKE_ORACLE_SCENE_SYNTHETIC_SCENE_H_
