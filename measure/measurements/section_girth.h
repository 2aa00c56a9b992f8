// A girth on a point cloud: the length of a tape pulled tight around one body
// part, in a given cutting plane (thesis 3.7; ISO 8559-1 girths).
//
//   1. slab      the cloud's points within half_thickness_mm of the plane,
//                moved onto it: with normals, along the surface (the
//                tangent closest to the plane's normal; a plain projection
//                would push points of a surface sloping through the slab
//                outwards, +4 mm on an arm cut at 30 degrees; points needing a
//                slide longer than max_slide_mm are dropped), else projected;
//   2. pieces    2-D single-linkage clusters (points closer than
//                piece_gap_mm are one piece): the trunk, each arm, each
//                leg, a hand beside the hip are separate pieces;
//   3. the part  the seed piece holds the body part: with several anchors
//                (datum points of a trunk girth) the piece whose convex hull
//                encloses their centroid, else the piece nearest anchor 0.
//                Scan holes (occluded armpits, crotch, under the chin) cut a
//                loop into arcs: a piece joins the seed when it lies within
//                bridge_gap_mm of it, in the angular gap the seed leaves open
//                (seen from the seed's centre) and at the radius the seed has
//                on both sides of that gap, i.e. it continues the same loop.
//                A hand beside the hip lies farther out and stays outside;
//   4. gap points `members.gap_only` (the trunk beside an arm's girth) join
//                the part one by one: a point in a bin the part leaves empty,
//                at the radius interpolated between the part's nearest
//                occupied bins on either side (within radius_tolerance), its
//                normal turned at most gap_normal_max_deg from the direction
//                out of the centre. Where an arm rests on the trunk the scan
//                merges the two skins and the body structure may give the
//                arm's inner side to the trunk; the trunk's own skin lies
//                farther out and, under the arm, faces it;
//   5. hull      perimeter of the 2-D convex hull of the part's points and
//                of each of `members.tape_points` that lies in a hole of the
//                loop (its angular neighbours in the part farther apart than
//                open_gap_mm; where the skin is scanned, the skin decides).
//                The tape bridges concavities and holes alike; across the
//                holes of a limb's loop (`members.skin_over_holes`) it
//                passes over the skin the loop's fitted ellipse continues
//                with (section_holes.h), not the chord. Optional
//                denoising first: the mean of the points in angular bins of
//                smooth_arc_mm of arc, so range noise does not push the hull
//                outwards.
// `open` is set when, going round the part by angle, two consecutive points
// are more than open_gap_mm apart: the hull bridged a scan hole there.
// Input: #P x 3 cloud (body frame, mm), #P x 3 unit normals or 0 x 3, a plane (point, unit normal),
// #D x 3 anchors (D >= 1), `members` (SectionMembers: which points may join). Output:
// SectionGirth (mm). Failure: InputError for bad options or a non-unit normal; a plane that misses
// the cloud gives `points == 0` and girth 0 (the caller flags or skips it), never a throw.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_SECTION_GIRTH_H_
#define BESPOKE_MEASURE_MEASUREMENTS_SECTION_GIRTH_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke {

struct SectionGirthOptions {
  double half_thickness_mm = 2.5;  // default 2.5 mm: slab half thickness around the plane
  double max_slide_mm = 4.0;       // default 4 mm: longest slide along the surface onto the plane
  double piece_gap_mm = 12.0;      // default 12 mm: 2-D points closer than this are one piece
  double bridge_gap_mm = 150.0;    // default 150 mm: widest hole a loop is joined across
  double radius_tolerance =
      0.25;  // default 0.25: an arc's radius may differ this share from the loop's
  // default 60 deg: a gap point whose normal (on the plane) turns farther
  // than this from the direction out of the part's centre faces the part
  // (the trunk's skin under an arm) and stays outside (step 4)
  double gap_normal_max_deg = 60.0;
  double open_gap_mm = 30.0;   // default 30 mm: a longer gap between neighbours marks the loop open
  double smooth_arc_mm = 6.0;  // default 6 mm: angular bin width of the denoising mean (0 = off)
  int min_piece_points = 4;    // default 4: smaller pieces are noise (unless nothing else)
  // default 4: SlabForSpacing widens the slab of a sparse scan until a
  // piece gap holds this many points along the loop (0 = fixed slab)
  double points_per_gap = 4;
  // default 2.5: SlabForSpacing makes piece_gap_mm at least this many times
  // the scan's surface spacing (0 = fixed gap)
  double gap_per_spacing = 2.5;
  double max_half_thickness_mm = 12;  // default 12 mm: the widest slab SlabForSpacing makes
  void Check() const;                 // InputError when out of range
};

// Which cloud points a section may hold: #P flags each, or empty (none).
struct SectionMembers {
  // Points of other body parts, never in the section (the arms beside a
  // trunk girth, from the body structure).
  std::vector<bool> leave_out;
  // Points that join the part only one by one across its gap (step 4).
  std::vector<bool> gap_only;
  // Every point not left out belongs to the part (a trunk girth with the
  // limbs left out): every piece of at least min_piece_points, however the
  // scan's holes cut the loop.
  bool one_part = false;
  // #T x 3 points off the cloud the tape passes over where the loop has a
  // hole (mm, body frame), projected onto the plane (step 5): the armpits
  // under a chest's tape, where a booth leaves the trunk's sides unscanned.
  // Empty: none.
  Eigen::MatrixX3d tape_points;
  // A limb's section: the tape passes over its holes on the skin the
  // scanned loop continues with (step 5), not on the chord.
  bool skin_over_holes = false;
};

struct SectionGirth {
  double girth_mm = 0;           // hull perimeter of the part
  Eigen::MatrixX3d hull;         // #K x 3 hull polygon on the plane (closed implicitly), mm
  Eigen::MatrixX3d part;         // #Q x 3 the part's slab points projected onto the plane, mm
  Eigen::Index points = 0;       // slab points (all pieces; gap points not counted)
  int pieces = 0;                // pieces in the slab
  int pieces_joined = 0;         // pieces joined to the seed across holes
  int gap_points_joined = 0;     // members.gap_only points joined (step 4)
  double largest_gap_mm = 0;     // widest gap between angular neighbours of the part
  double bridged_mm = 0;         // skin laid over the holes (members.skin_over_holes), mm
  bool open = false;             // largest_gap_mm > open_gap_mm
  bool anchor_enclosed = false;  // the seed was chosen by enclosing the anchors' centroid
};

// `options` with the slab widened for a sparse scan. A scan whose points each
// cover a square of side `surface_spacing_mm` (s) puts 2 h / s^2 points per
// mm of loop into a slab of half thickness h; fewer than points_per_gap
// within the piece gap g break a limb's loop into pieces (a 29 mm knee girth
// at 60k points with the 2.5 mm slab). Scanners sample in rows, so points
// in a slab clump, and g grows with s too: g = max(piece_gap_mm,
// gap_per_spacing * s); h = max(half_thickness_mm, points_per_gap * s^2 /
// (2 g)), at most max_half_thickness_mm; max_slide_mm grows as h does (the
// slide of a point on a surface across the plane is its offset). A dense
// scan keeps `options`.
SectionGirthOptions SlabForSpacing(const SectionGirthOptions& options, double surface_spacing_mm);

SectionGirth MeasureSectionGirth(const SectionGirthOptions& options, const Eigen::MatrixX3d& cloud,
                                 const Eigen::MatrixX3d& normals,
                                 const Eigen::Vector3d& plane_point,
                                 const Eigen::Vector3d& plane_normal,
                                 const Eigen::MatrixX3d& anchors,
                                 const SectionMembers& members = {});

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_SECTION_GIRTH_H_
