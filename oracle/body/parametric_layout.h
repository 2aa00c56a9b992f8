// The skeleton and key cross-sections of the parametric body (a helper of
// parametric_body.cc): from the options (after seeding) to heights, key
// sections along the torso, legs and arms, and the crotch and arm geometry.
// No mesh here; parametric_body.cc turns this into rings and faces.
//
// All lengths in millimetres, body frame (see parametric_body.h). Torso and
// leg sections are horizontal, (u, v) = (x, y); arm sections are in the
// arm's (U, F) plane (U: up/out, F = +y), see ArmFrame.
#ifndef BESPOKE_ORACLE_BODY_PARAMETRIC_LAYOUT_H_
#define BESPOKE_ORACLE_BODY_PARAMETRIC_LAYOUT_H_

#include <string>
#include <vector>

#include "oracle/body/body_section.h"
#include "oracle/body/parametric_body.h"

namespace bespoke {

// A key section at coordinate `at` (z for torso and legs, arc length along
// the arm's centre path for arms). `girth` names the girth measurement the
// key is built to ("" when none).
struct SectionKey {
  double at = 0;
  Section section;
  std::string girth;
  // Torso only: the ring's plane is turned about the line x || (0, cv, at)
  // by `tilt` radians, front down (the neck base). 0 = horizontal.
  double tilt = 0;
};

// Linear interpolation of the keys' tilt (clamped at the ends).
double InterpolateTilt(const std::vector<SectionKey>& keys, double at);

// Monotone cubic (Fritsch-Carlson) interpolation of every field of the key
// sections; clamps to the end keys outside their range. `keys` sorted by `at`
// ascending.
Section InterpolateSection(const std::vector<SectionKey>& keys, double at);

struct BodyLayout {
  ParametricBodyOptions options;  // after seeding

  // Heights (z, mm).
  double z_crotch = 0, z_hip = 0, z_middle_hip = 0, z_waist = 0, z_under_bust = 0;
  double z_bust = 0, z_armpit = 0, z_shoulder = 0;
  double z_jugulare = 0, z_back_neck = 0;  // front and back centre of the (tilted) neck base ring
  double z_chin = 0, z_dome = 0;
  double z_thigh = 0, z_knee = 0, z_calf = 0, z_ankle = 0;
  double z_malleolus_inside = 0, z_malleolus_outside = 0;

  // Torso keys from the hip up to the dome (z ascending); below the hip the
  // torso blends into the crotch lobes. The dome closes the head above
  // z_dome: rings are `dome` scaled by sqrt(1 - u^2), u = (z - z_dome) /
  // (stature - z_dome).
  std::vector<SectionKey> torso;
  Section dome;

  // Right crotch lobe: the ellipse (x - lobe_x)^2/rx^2 + (y - lobe_y)^2/ry^2 = 1
  // clipped to x >= 0 (lobe_x < lobe_rx), at z_crotch.
  double lobe_x = 0, lobe_y = 0, lobe_rx = 0, lobe_ry = 0;

  // Right leg keys from the sole (z = 0) up to the thigh (z ascending);
  // above z_thigh the leg blends into the crotch loop.
  std::vector<SectionKey> leg;

  // Right arm: keys by arc length along the centre path, measured from the
  // armscye. The path bends by (90 - abduction) deg about a pivot below the
  // armscye's centre, then runs straight; see parametric_body.cc.
  // Arm keys: `at` is the distance along the arm's lateral line (its
  // outside: over the shoulder, then straight) from the acromion; the mesh
  // builder maps it to the centre path. Keys with a girth must land on the
  // straight part, after the bend: the builder moves them there if needed.
  std::vector<SectionKey> arm;
  double arm_upper_lateral = 0;  // acromion -> upper-arm girth level
  double arm_elbow_lateral = 0;  // acromion -> elbow
  double arm_wrist_lateral = 0;  // acromion -> wrist (= arm_length_mm)
  double arm_tip_lateral = 0;    // acromion -> fingertip
  double armhole_width = 0;      // arc length across the armscye at armpit level (target)
};

// Validates and seeds the options, then lays the body out. Throws InputError
// for options out of range or inconsistent girths.
BodyLayout MakeLayout(const ParametricBodyOptions& options);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_PARAMETRIC_LAYOUT_H_
