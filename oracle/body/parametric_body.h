// The built-in parametric body: a closed, watertight human-shaped triangle
// mesh with its datum points known exactly from its construction. Needs no
// external data; the default is an average adult woman in an A-pose.
//
// Construction (details in docs/oracle.md, "The parametric body"): one quad
// network of rings (cross-sections) along a simple skeleton, stitched into a
// single genus-0 surface:
//  - the main tube runs from the crotch up to the crown: horizontal rings
//    (torso, neck, head), closed by a pole vertex at the crown;
//  - below the crotch the bottom ring splits into two leg loops that share a
//    "bridge" of vertices along x = 0 (the crotch); each leg is a tube of
//    horizontal rings down to a flat sole on z = 0 (the foot points +y);
//  - each arm starts from a hole (the armscye) cut in the torso's quad grid
//    between the armpit and the shoulder, sweeps along a bend from the
//    horizontal (+x) into the arm's direction, with rings perpendicular to
//    the arm, and is closed by a cap at the hand.
// Girths: every girth level is a ring of vertices lying exactly in the
// catalogue's girth plane (horizontal; the neck base tilted through the back
// and front neck points; arm girths perpendicular to the catalogue's axis).
// The ring lies on a convex curve (two superellipse halves, possibly with a
// flat middle part, body_section.h) whose perimeter is computed analytically
// (adaptive Gauss-Kronrod quadrature, relative error 1e-10) and scaled to
// the requested girth. Girth rings are refined to at least
// `girth_ring_segments` vertices (their edges split, new vertices on the
// curve), so the ring polygon is shorter than the curve by less than
// `max_girth_deficit_mm` (checked) while the rest of the mesh stays light
// (about 23k vertices by default) for exact geodesics.
//
// Frame: body frame, millimetres, +z up, soles on z = 0, origin centred
// between the feet, facing +y, the person's right is +x.
//
// Failure: InputError from Check() for parameters out of range (e.g. a waist
// larger than the hip by more than 40 %, an abduction outside 15-90 deg);
// InternalError when the construction breaks an invariant.
#ifndef BESPOKE_ORACLE_BODY_PARAMETRIC_BODY_H_
#define BESPOKE_ORACLE_BODY_PARAMETRIC_BODY_H_

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "oracle/body/body.h"

namespace bespoke {

struct ParametricBodyOptions {
  // --- size (defaults: an average adult woman, EN 13402-3 size 40) ---
  double stature_mm = 1660;          // crown height (exact: the crown vertex)
  double neck_girth_mm = 350;        // horizontal, at the side neck points
  double chest_girth_mm = 900;       // horizontal, at armpit level
  double bust_girth_mm = 930;        // horizontal, through the bust points
  double under_bust_girth_mm = 780;  // horizontal, below the breasts
  double waist_girth_mm = 760;       // horizontal, natural waist
  double middle_hip_girth_mm = 900;  // horizontal, halfway waist to hip
  double hip_girth_mm = 1000;        // horizontal, through the buttock point
  double upper_arm_girth_mm = 290;   // perpendicular to the arm, mid upper arm
  double wrist_girth_mm = 155;       // perpendicular to the forearm, at the wrist point
  double thigh_girth_mm = 570;       // horizontal, just below the gluteal fold
  double knee_girth_mm = 370;        // horizontal, at the middle of the kneecap
  double calf_girth_mm = 360;        // horizontal, maximum of the calf
  double ankle_girth_mm = 220;       // horizontal, minimum above the malleoli
  double arm_length_mm = 560;        // shoulder point to wrist along the outside (target, approx.)
  double crotch_height_mm = 760;     // crotch point above the floor (exact)
  double shoulder_width_mm = 370;    // x distance between the two shoulder points (exact)
  double stance_width_mm = 220;      // x distance between the ankle centres
  // --- pose ---
  // Angle between each arm and the vertical: about 20-45 deg is an A-pose,
  // 90 a T-pose. Allowed 15-90.
  double arm_abduction_deg = 30;
  // --- variation ---
  // 0: build exactly the size values above. N > 0: draw a plausible adult
  // instead (sex, stature, build and proportions vary with realistic
  // correlations), deterministically from N; pose, stance and resolution are
  // kept. The values used are reported in Body::parameters. To draw a body
  // and then change some sizes, call SeededOptions(), edit, and generate.
  std::uint64_t seed = 0;
  // --- resolution ---
  int torso_segments = 64;      // vertices around each torso and leg ring (multiple of 8, >= 48)
  int arm_segments = 48;        // vertices around each arm ring (multiple of 4, >= 32)
  double ring_spacing_mm = 15;  // target distance between rings (mm, 2-40)
  int girth_ring_segments =
      256;  // girth rings get at least this many vertices (edges split, >= 16)
  double max_girth_deficit_mm =
      0.1;  // ring polygon vs analytic perimeter (mm); InternalError above
  std::uint64_t drawn_from_seed = 0;  // set by SeededOptions (reporting only)

  // Throws InputError naming the parameter when a value is out of range.
  void Check() const;
  // Sets a parameter by its field name ("waist_girth_mm", "seed", ...); InputError
  // for an unknown name. Lets the CLI take --param name=value.
  void Set(const std::string& name, double value);
  // Every numeric parameter by field name (seed included).
  std::map<std::string, double> ToMap() const;
  // An average adult man (chest = bust, broader shoulders, taller).
  static ParametricBodyOptions AverageMan();
};

// The options with the size values drawn for `options.seed` and seed = 0
// (the draw's seed is kept in `drawn_from_seed`); a copy when seed == 0.
// `population` "default" draws an everyday spread (stature SD about 65 mm,
// build SD 10 %); "full" the whole range a shop sees (stature 1450-2050 mm,
// build 0.65-1.5, belly, hips and bust far from the average combinations),
// from its own stream of the seed. InputError for another name.
ParametricBodyOptions SeededOptions(const ParametricBodyOptions& options,
                                    const std::string& population = "default");

// One girth level built into the body: the ring of mesh vertices that lies
// exactly in `plane_normal . (x - plane_point) = 0` (up to rounding of the
// coordinates) is the section of that body part, in the catalogue's plane
// through `landmark` (horizontal for torso and legs; the neck base tilted
// through back_neck and front_neck; arm girths perpendicular to the
// catalogue's axis, e.g. shoulder -> elbow for the upper arm). Because the
// ring's vertices lie ON the plane, a mesh-plane section should count a
// vertex on the plane as being on one side (e.g. signed distance >= 0);
// faces touching the plane only along ring edges (the arm above the armpit
// ring) then add nothing.
struct AnalyticGirth {
  std::string measurement;       // catalogue name, e.g. "waist_girth", "thigh_girth"
  std::string side;              // "", "left" or "right"
  std::string landmark;          // the datum point on the ring (catalogue name)
  Eigen::Vector3d plane_point;   // centre of the section, body frame, mm
  Eigen::Vector3d plane_normal;  // unit; +z for horizontal girths, the limb axis for arm girths
  double girth_mm = 0;           // analytic perimeter of the (convex) section curve
  double polygon_girth_mm = 0;   // the ring's convex hull perimeter in the plane (<= girth_mm)
  std::vector<int> ring;         // the ring's vertex indices, in order around it
};

enum class BodyPart : std::uint8_t { kTorso, kArmRight, kArmLeft, kLegRight, kLegLeft };

// What the construction knows beyond the Body.
struct ParametricBodyDetails {
  std::vector<AnalyticGirth> girths;  // every girth level built in, both sides for limbs
  std::vector<BodyPart> part;  // #V: the part each vertex belongs to (torso: with neck and head)
  // The skeleton's joint centres (body frame, mm) under MakeHuman's joint
  // names, so MakeHuman's landmark rules (landmark_analysis.h) run on this
  // body: "pelvis", "spine-4" .. "spine-1", "neck", "head" are the torso
  // sections' centres at the hip, waist, under-bust, bust, armpit, back neck
  // and chin levels; "r-shoulder" the armscye's centre; "r-elbow", "r-hand"
  // the arm's centre path at its elbow and wrist girth levels;
  // "r-upper-leg" the leg's centre 3 % of stature above the crotch; "r-knee",
  // "r-ankle" the leg sections' centres at the knee and ankle levels; "l-*"
  // their mirror images.
  std::map<std::string, Eigen::Vector3d> joints;
};

// Builds the body. Body::parameters holds every option used (after seeding),
// "<measurement>[_<side>]_analytic_mm" for each girth level and a few
// construction values (e.g. "arm_lateral_line_mm"). `details` may be null.
Body GenerateParametricBody(const ParametricBodyOptions& options,
                            ParametricBodyDetails* details = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_PARAMETRIC_BODY_H_
