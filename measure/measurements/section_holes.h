// The skin a limb's section continues with across a scan hole, for the tape
// to pass over (section_girth.h, step 5).
//
// A booth leaves the inner side of an arm or a thigh unscanned (the trunk or
// the other thigh hides it). The convex hull bridges such a hole with its
// chord, but a limb's section is convex there too, so the tape runs outside
// the chord (upper-arm girths 1-6 mm short at the true datum points of the
// MakeHuman population; docs/measuring.md, step 5). This fits an ellipse to
// the scanned loop (ellipse_fit.h) and, across each hole, follows it from
// one end of the hole to the other, blended so that it starts and ends on
// the scanned points: q(s) = E(t(s)) + (1 - s) (A - E(tA)) + s (B - E(tB)), s in [0, 1].
//
// It does nothing when the loop is whole, when the ellipse does not fit the
// scanned points (their RMS radial residual above max_residual_share of the
// mean radius: not a limb's section), or across a hole wider than
// max_hole_deg of the ellipse (too little of the loop to say what is in it).
// Input: #P x 2 points of one loop (mm, any order). Output: points over the
// holes (#Q x 2, mm) and their polyline's length; the hull of loop and fill
// is the tape.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_SECTION_HOLES_H_
#define BESPOKE_MEASURE_MEASUREMENTS_SECTION_HOLES_H_

#include <Eigen/Core>

namespace bespoke {

struct SkinOverHolesOptions {
  double open_gap_mm = 30.0;        // default 30 mm: a wider gap between neighbours is a hole
  double step_mm = 3.0;             // default 3 mm: spacing of the points laid over a hole
  double max_hole_deg = 150.0;      // default 150 deg: wider holes are left to the chord
  double max_residual_share = 0.1;  // default 0.1: the ellipse's RMS radial misfit / radius
  int min_points = 12;              // default 12: fewer scanned points fix no ellipse
  void Check() const;               // InputError when out of range
};

struct SkinOverHoles {
  Eigen::MatrixX2d points = Eigen::MatrixX2d(0, 2);  // #Q x 2 over the holes, mm
  double bridged_mm = 0;  // length of the fill's polylines, hole end to hole end
  int holes = 0;          // holes filled
};

SkinOverHoles FillSectionHoles(const SkinOverHolesOptions& options, const Eigen::MatrixX2d& loop);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_SECTION_HOLES_H_
