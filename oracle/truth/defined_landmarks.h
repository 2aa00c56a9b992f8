// Datum points placed by their catalogue definition on the exact (posed)
// mesh, not as fixed vertices: where the catalogue defines a point by a
// level or an extreme of the surface, the level is searched on each body.
//
// Sections are exact horizontal mesh sections (mesh_section.h); the trunk's
// section at a level is its loop of largest area with the loops a tape round
// it passes over (TrunkLoopIndices: a heavy breast the plane cuts apart from
// the chest wall; arms and hands are separate loops beside it); a girth
// level is judged by the section's convex hull perimeter (the tape). Levels
// are searched in step_mm steps, then refined to step_mm / 8 around the best.
//
//   under_bust: the inframammary fold: in the sagittal planes of the bust
//     points, 1-8 % of stature below them, going down, the first corner of
//     the front profile (a local maximum of the second difference of its
//     depth over +-10 mm, at least half the band's largest: a belly's top
//     lower down can bend more); the fold's strength is the band's largest
//     bend averaged over +-5 mm: under 1 mm (a flat chest) there is no fold
//     and the level is 4 % of stature below them, over 3 mm the fold's, in
//     between the point between them in proportion (the detector's rule; no
//     threshold where a bend read a little differently jumps the level); the
//     point on x = 0 at that level. A hanging breast's underside is that
//     bend; where the breast is a loop of its own there, the level moves
//     down (0.5 mm steps, at most 60 mm) until the section is free of it.
//     A breast that hangs inwards, or whose underside slopes down to the
//     chest wall, reaches below that fold: the level moves down (0.5 mm
//     steps, at most 40 mm) while the girth rises over the 2 mm above it
//     more than 2 mm per mm faster than over 10-20 mm below it (taken as 0
//     where a belly there narrows upwards). The tape goes just below the
//     breasts.
//   hip (hip_back, hip_right, hip_left): the level of the most prominent
//     buttock (the trunk section reaching furthest back, -y) between 20 mm
//     above the crotch and halfway up to the under-bust; hip_back the
//     back-most point of that section on x = 0, hip_* its lateral extremes.
//   waist (front_waist, back_waist, side_waist_*): the narrowest trunk
//     section between the lowest rib and the iliac crest, taken as the band
//     from 30 % to 85 % of the way from the hip level up to the under-bust
//     level (proxies: the iliac crest lies above the hip level, the lowest
//     rib below the breasts); front and back on x = 0, sides the lateral
//     extremes.
//   middle_hip_front: the front of the trunk section on x = 0 midway between
//     the hip and waist levels.
//   crotch: the lowest point of the trunk's mid-sagittal line, the seam
//     vertices the caller names (`seam`), below the hip level: a U whose
//     bottom is often flat over 60-90 mm, so its lowest vertex flips
//     between a front and a back dip. The vertex of a parabola z(y) through
//     the U's bottom 25 mm (the detector's rule), at the U's height there.
//   calf_*: the back of the leg at the level of its largest girth between
//     the ankle and the knee datum points (25-90 % of the way up) that has
//     a section 3 mm of girth smaller above it in that band (the calf's
//     bulge, not the widening below the knee); the band's largest girth
//     where no level has.
//   upper_arm_*: midway between the shoulder point and the elbow, the
//     outermost point (lateral, across the axis) of the arm's section
//     perpendicular to that axis.
// Points not listed here stay as given (anatomical points: cervicale,
// acromion, malleoli, ...). Each moved point becomes the surface point
// closest to its position.
#ifndef BESPOKE_ORACLE_TRUTH_DEFINED_LANDMARKS_H_
#define BESPOKE_ORACLE_TRUTH_DEFINED_LANDMARKS_H_

#include <map>
#include <string>
#include <vector>

#include "oracle/body/body.h"

namespace bespoke {

struct DefinedLandmarkOptions {
  double step_mm = 4;  // level search step, mm (refined to step_mm / 8); default 4; 0.5-20
  // Throws InputError when out of range.
  void Check() const;
};

struct DefinedLevels {
  double hip_mm = 0, waist_mm = 0, middle_hip_mm = 0, under_bust_mm = 0;  // heights (z)
  double calf_right_mm = 0, calf_left_mm = 0;
};

// Moves the defined datum points of `body` (in place) to where their
// definitions put them. `seam`: the mesh's mid-sagittal vertices (for the
// crotch; empty keeps the crotch). Needs crotch, bust_*, knee_*,
// ankle_inside_*, calf_*, shoulder_* and elbow_* to start from; InputError when one is missing or
// a section is empty.
DefinedLevels PlaceDefinedLandmarks(const DefinedLandmarkOptions& options,
                                    const std::vector<int>& seam, Body* body);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_DEFINED_LANDMARKS_H_
