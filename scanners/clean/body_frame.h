// The body frame of a cleaned scan of a standing person.
//
// Body frame (docs/contracts.md): millimetres, +z up, feet on z = 0, origin
// centred between the feet, the person faces +y, so their right is +x.
// Computed from the cleaned points (scanner frame, mm):
//
//  up    The floor's normal when a floor was found (scanners/clean/floor.h).
//        Otherwise the major principal axis of the points (a standing body
//        is longest head to feet), signed by comparing the two ends: the
//        convex-hull area of the lowest `end_fraction` of the body (two feet
//        with toes and heels) is 3-6 times that of the top (the crown of
//        the head); a ratio below `min_end_area_ratio` is flagged
//        `up_uncertain`. Fails for a person with arms raised above the head
//        or a crouching person.
//  z = 0 The floor plane, else the lowest body point (the soles are never
//        scanned, so this is the lower rim of the feet's sides; a few mm).
//  x     Left-right: the major horizontal principal axis of the body between
//        35 % and 80 % of its height (hips, torso and arms are wider than
//        deep). Ratio of horizontal variances below 1.15 is flagged
//        `lateral_axis_uncertain`.
//  +y    Which way the person faces, from the feet: each foot's footprint
//        (points below `foot_fraction` of the height) reaches far ahead of
//        the ankle above it (toes) and little behind (heel), so the centre of
//        the footprint lies 50-90 mm in front of the centre of the ankle's
//        section (the band `ankle_low_fraction`..`ankle_high_fraction` of
//        the height, above the foot). Trusted when both feet agree and the mean offset is at
//        least `min_foot_offset_mm`. Otherwise the nose decides: between the
//        chin and the eyes each horizontal section of the head ends in a
//        narrow tip at the front (10 mm from its tip the nose is ~30 mm
//        wide) and a round one at the back (the occiput, ~75 mm); the cue is
//        the narrowest back tip minus the narrowest front tip, trusted from
//        `min_nose_cue_mm`; flag `front_from_nose`. (The head's centre
//        against the neck's is no cue: MakeHuman bodies' necks lean
//        forward.) A body model without a nose gives no cue. When neither
//        cue is clear the result is flagged `front_uncertain` (the larger cue
//        still picks the sign). Cues that disagree are flagged
//        `front_cues_disagree`.
//        Fails for feet hidden by long garments or cut off by the floor band,
//        feet turned out by 90 degrees, or a scan of the upper body only.
//  +x    = +y x +z: the person's right.
//  origin The midpoint between the two ankle centres (centres of the robust
//        extents of the legs' sections in the ankle band), on z = 0: the
//        convention of the generated bodies (oracle/body, stance measured
//        between the ankle centres). The footprint centres would lie ~65 mm
//        further forward. One leg only: flag `one_ankle_found`.
#ifndef BESPOKE_SCANNERS_CLEAN_BODY_FRAME_H_
#define BESPOKE_SCANNERS_CLEAN_BODY_FRAME_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "scanners/clean/floor.h"

namespace bespoke {

struct BodyFrameOptions {
  double end_fraction = 0.04;         // of the length, per end, for the up sign. Default 0.04.
  double min_end_area_ratio = 1.5;    // feet/head hull areas for a sure up sign. Default 1.5.
  double foot_fraction = 0.035;       // of the height: the footprint band. Default 0.035 (~60 mm).
  double ankle_low_fraction = 0.05;   // ankle band, from. Default 0.05 (~90 mm).
  double ankle_high_fraction = 0.09;  // ankle band, to. Default 0.09 (~160 mm).
  double min_foot_offset_mm = 20.0;   // footprint ahead of the ankles. Default 20 mm.
  double min_nose_cue_mm = 15.0;      // back tip minus nose tip width. Default 15 mm.
  // Throws InputError when a value is out of range.
  void Check() const;
};

struct BodyFrame {
  Eigen::Isometry3d body_from_scanner = Eigen::Isometry3d::Identity();  // rigid, mm
  std::string up_source;           // "floor" or "principal_axis"
  double end_area_ratio = 0.0;     // feet/head hull area (principal-axis up; also with a floor)
  double lateral_ratio = 0.0;      // major/minor horizontal variance
  std::string front_source;        // "feet", "nose" or "none"
  double foot_offset_mm = 0.0;     // footprint centre ahead of the ankle (mean of both feet), +y
  int feet_found = 0;              // 0, 1 or 2 sides with footprint and ankle points
  double nose_cue_mm = 0.0;        // occiput tip width minus nose tip width (> 0: nose at +y)
  double height_mm = 0.0;          // top of the body above z = 0
  std::vector<std::string> flags;  // see above; empty when every cue was clear
};

// points: #P x 3, scanner frame, mm, cleaned (a single standing person);
// floor: the floor plane when one was found. Throws InputError when there
// are fewer than 100 points or the body is shorter than 300 mm.
BodyFrame EstimateBodyFrame(const BodyFrameOptions& options, const Eigen::MatrixX3d& points,
                            const std::optional<FloorPlane>& floor);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_BODY_FRAME_H_
