// Armpits: where the arm's section joins the trunk's (A-pose: the arm's own
// piece beside the trunk disappears; T-pose: the trunk's section suddenly
// reaches along the arm), and each arm's centre line for landmark_arms.cc.
#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/landmarks/arm_notch.h"
#include "measure/landmarks/landmark_context.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// The lateral pieces of slice `s` (not trunk, on the `sign` side, at least
// 4 points) whose centroid lies within `radius` of `centre` (xy).
std::vector<int> LateralPiecesNear(const Context& c, const Slice& s, int sign,
                                   const Eigen::Vector2d& centre, double radius) {
  const std::vector<int> trunk = c.TrunkPieces(s);
  std::vector<int> out;
  for (size_t i = 0; i < s.pieces.size(); ++i) {
    if (std::find(trunk.begin(), trunk.end(), static_cast<int>(i)) != trunk.end()) continue;
    const Piece& p = s.pieces[i];
    if (sign * p.centroid.x() > 0 && p.rows.size() >= 4 && (p.centroid - centre).norm() < radius)
      out.push_back(static_cast<int>(i));
  }
  return out;
}

// Of those, the one nearest `centre`; -1 when none.
int LateralPieceNear(const Context& c, const Slice& s, int sign, const Eigen::Vector2d& centre,
                     double radius) {
  int best = -1;
  for (int i : LateralPiecesNear(c, s, sign, centre, radius))
    if (best < 0 || (s.pieces[static_cast<size_t>(i)].centroid - centre).norm() <
                        (s.pieces[static_cast<size_t>(best)].centroid - centre).norm())
      best = i;
  return best;
}

// Of those, the one with the most points; -1 when none. At the armpit the
// arm's section is the big piece beside the trunk; the nearest piece can be
// a fragment of the armpit fold (a sparse scan's thin slice).
int LargestLateralPieceNear(const Context& c, const Slice& s, int sign,
                            const Eigen::Vector2d& centre, double radius) {
  int best = -1;
  for (int i : LateralPiecesNear(c, s, sign, centre, radius))
    if (best < 0 || s.pieces[static_cast<size_t>(i)].rows.size() >
                        s.pieces[static_cast<size_t>(best)].rows.size())
      best = i;
  return best;
}

// Lateral extent of the trunk's section on one side (x' = sign * x).
double Extent(const Context& c, const Slice& s, int sign) {
  double ext = -kInf;
  for (int r : c.TrunkRows(s)) ext = std::max(ext, sign * c.points(r, 0));
  return ext;
}

// A-pose: follows the arm's piece down from slice k, recording centroids.
void TrackArmDown(const Context& c, int k, int piece, int sign, ArmInfo* arm) {
  Eigen::Vector2d centre =
      c.slices[static_cast<size_t>(k)].pieces[static_cast<size_t>(piece)].centroid;
  int lost = 0;
  for (int s = k; s >= 0 && lost < 4; --s) {
    const Slice& slice = c.slices[static_cast<size_t>(s)];
    const int i = LateralPieceNear(c, slice, sign, centre, 60);
    if (i < 0) {
      ++lost;
      continue;
    }
    lost = 0;
    const Piece& p = slice.pieces[static_cast<size_t>(i)];
    centre = p.centroid;
    arm->centre_line.emplace_back(centre.x(), centre.y(), slice.z);
    arm->rows.insert(arm->rows.end(), p.rows.begin(), p.rows.end());
  }
}

// T-pose: the arm is every point beyond the trunk's side above the armpit;
// its centre line from vertical (x = const) bands 10 mm apart.
void CollectTPoseArm(const Context& c, double side_x, double armpit_z, int sign, ArmInfo* arm) {
  std::vector<std::vector<int>> bands;
  for (Eigen::Index r = 0; r < c.points.rows(); ++r) {
    const double x = sign * c.points(r, 0);
    if (x < side_x + 5 || c.points(r, 2) < armpit_z - 40) continue;
    arm->rows.push_back(static_cast<int>(r));
    const size_t b = static_cast<size_t>((x - side_x) / 10);
    if (bands.size() <= b) bands.resize(b + 1);
    bands[b].push_back(static_cast<int>(r));
  }
  for (const auto& band : bands) {
    if (band.size() < 4) continue;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int r : band) sum += c.P(r);
    arm->centre_line.push_back(sum / static_cast<double>(band.size()));
  }
}

// How far (mm) the scan reaches beyond the trunk's side `side_x` (x' =
// sign * x) at or above `z` - 40 mm: a T-pose arm's length, a few cm of
// shoulder for an A-pose arm.
double TPoseReach(const Context& c, double side_x, double z, int sign) {
  double reach = 0;
  for (Eigen::Index r = 0; r < c.points.rows(); ++r) {
    if (c.points(r, 2) >= z - 40) reach = std::max(reach, sign * c.points(r, 0) - side_x);
  }
  return reach;
}

// Whether slice s's extent `ext` (x' = sign * x of the trunk's piece, with
// the arm while they are one) lies 30 mm below the widest of the 60 mm above
// it (up to slice `top`): the arm has left the trunk's piece there.
bool Dropped(const std::vector<double>& ext, int s, int top) {
  double above = -kInf;
  for (int t = s + 1; t <= std::min(top, s + 12); ++t)
    above = std::max(above, ext[static_cast<size_t>(t)]);
  return std::isfinite(above) && ext[static_cast<size_t>(s)] < above - 30;
}

// Where the arm leaves the trunk's section, going down the slices from
// `top` to `bottom`: the first slice Dropped whose extent passes
// `trunk_like`, for three slices; -1 when none.
template <typename TrunkLike>
int ArmLeavesTrunk(const std::vector<double>& ext, int bottom, int top, TrunkLike trunk_like) {
  auto dropped = [&](int s) {
    return Dropped(ext, s, top) && trunk_like(ext[static_cast<size_t>(s)]);
  };
  for (int s = top - 1; s >= bottom + 2; --s)
    if (dropped(s) && dropped(s - 1) && dropped(s - 2)) return s;
  return -1;
}

// Above the apex of a gap between arm and trunk the section still shows the
// notch for a few slices while the armpit's dome closes (5-15 mm on the
// oracle's MakeHuman and parametric sets, 240 armpits); an arm resting on
// the trunk leaves it for centimetres. Climbs shorter than this (mm) keep
// the join.
constexpr double kRestingArmMinClimbMm = 20;

// A slice without the notch whose dip still reaches this ratio (arm_notch.h;
// the notch's own is 0.7) is a weakened notch, not its end: on a heavy body
// whose upper arm rests on the trunk the crease thins for a few slices
// below the armpit (0.72-0.74 over 15 mm, MakeHuman full seed 2 subject 29,
// the notch back at 0.56-0.67 up to the true armpit), while above the
// armpit the shoulder's taper takes the ratio past it within 10-15 mm.
constexpr double kWeakNotchRatio = 0.8;
// The longest run of weakened slices the climb bridges, mm.
constexpr double kMaxWeakRunMm = 20;

// From slice `level`, where the arm's and the trunk's sections join, up
// while the section (`rows_at(s)`: the trunk's and this arm's points) still
// shows the arm's notch (arm_notch.h), one slice without it allowed (a thin
// slice's noise), or a run of up to kMaxWeakRunMm of weakened ones
// (kWeakNotchRatio); up to 84 % of stature. Returns the notches of slices
// level + 1 up to the last with one (a slice without: found = false), or
// nothing when that climb is shorter than kRestingArmMinClimbMm. An arm
// resting on the trunk joins its section far below the armpit: the notch's
// top is the armpit.
template <typename RowsAt>
std::vector<ArmNotch> ClimbArmNotch(const Context& c, int level, int sign, RowsAt rows_at) {
  const int top = SliceAt(c.slices, 0.84 * c.crown_z);
  const size_t max_weak = static_cast<size_t>(kMaxWeakRunMm / c.step);
  std::vector<ArmNotch> climb;
  size_t kept = 0;
  bool weak = true;  // every slice since the last notch a weakened one
  for (int s = level + 1; s <= top; ++s) {
    climb.push_back(FindArmNotch(ArmNotchOptions{}, c.points, rows_at(s), sign));
    if (climb.back().found) {
      kept = climb.size(), weak = true;
      continue;
    }
    weak = weak && climb.back().ratio <= kWeakNotchRatio;
    const size_t run = climb.size() - kept;
    if (run >= 2 && (!weak || run > max_weak)) break;
  }
  climb.resize(kept);
  if (static_cast<double>(kept) * c.step < kRestingArmMinClimbMm) climb.clear();
  return climb;
}

// Gives the structure's trunk points of the climbed slices (level + 1 on,
// `climb` from ClimbArmNotch) lateral of their notch to the arm `arm_part`
// (and `arm->rows`): an upper arm resting on the trunk above a contact the
// surface graph crossed (a bent elbow against a heavy body) is no trunk.
void ClaimRestingArm(Context* c, int level, int sign, const std::vector<ArmNotch>& climb,
                     Part arm_part, ArmInfo* arm) {
  double x = 0;  // the notch of the slice, or of the nearest one below with one
  for (const ArmNotch& n : climb)
    if (n.found) {
      x = sign * n.x_mm;
      break;
    }
  for (size_t i = 0; i < climb.size(); ++i) {
    if (climb[i].found) x = sign * climb[i].x_mm;
    const Slice& slice = c->slices[static_cast<size_t>(level + 1) + i];
    for (int r : slice.rows) {
      if (c->PartOf(r) != Part::kTrunk || sign * c->points(r, 0) <= x) continue;
      c->structure.part[static_cast<size_t>(r)] = arm_part;
      arm->rows.push_back(r);
    }
  }
}

void FindArmpit(Context* c, int sign) {
  ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
  const std::string name = "armpit" + Side(sign);
  const double h = c->crown_z;
  const int top = SliceAt(c->slices, 0.84 * h), bottom = SliceAt(c->slices, c->crotch_z + 0.15 * h);
  std::vector<double> ext(c->slices.size(), -kInf);
  for (int s = bottom; s <= top; ++s)
    ext[static_cast<size_t>(s)] = Extent(*c, c->slices[static_cast<size_t>(s)], sign);
  // The trunk's own half-width for reference: its narrowest between 40 %
  // and 60 % of the crotch-to-crown height (the waist; no arm reaches in).
  double waist_ext = kInf;
  for (int s = SliceAt(c->slices, c->crotch_z + 0.4 * (h - c->crotch_z));
       s <= SliceAt(c->slices, c->crotch_z + 0.6 * (h - c->crotch_z)); ++s) {
    waist_ext = std::min(waist_ext, Extent(*c, c->slices[static_cast<size_t>(s)], sign));
  }
  // Descending, the first slice whose trunk extent drops 30 mm below the
  // widest of the 60 mm above it down to a trunk-like width (within 90 mm
  // of the waist's; a T-pose arm tilted upwards shortens gradually in the
  // slices through it), and stays there for two more slices.
  const int k = ArmLeavesTrunk(ext, bottom, top, [&](double e) { return e < waist_ext + 90; });
  if (k < 0) {
    // No gap between arm and trunk anywhere: the arm touches the torso.
    arm.touching = true;
    const double z = c->crotch_z + 0.56 * (h - c->crotch_z);
    const Slice& s = c->At(z);
    const std::vector<int> rows = c->TrunkRows(s);
    if (rows.empty()) {
      c->Missing(name, "the arm touches the torso and no trunk section was found");
      return;
    }
    int side = rows.front();
    for (int r : rows)
      if (sign * c->points(r, 0) > sign * c->points(side, 0)) side = r;
    arm.found = true;
    arm.armpit_z = z;
    arm.armpit = c->P(side);
    c->Put(name, arm.armpit, 0.3, "proportion_arm_touching", {"arm_touching_torso"});
    return;
  }
  const Slice& below = c->slices[static_cast<size_t>(k)];
  const std::vector<int> trunk = c->TrunkRows(below);
  const Eigen::Vector2d trunk_side(sign * ext[static_cast<size_t>(k)], 0);
  int piece = LargestLateralPieceNear(*c, below, sign, trunk_side, 250);
  // An A-pose arm leaves the trunk right beside it; a piece far out is a
  // T-pose forearm or hand hanging below the arm's line.
  if (piece >= 0) {
    const Piece& p = below.pieces[static_cast<size_t>(piece)];
    const double inner = sign > 0 ? p.lo.x() : -p.hi.x();
    if (inner > ext[static_cast<size_t>(k)] + 100) {
      piece = -1;
    } else if (inner < ext[static_cast<size_t>(k)] - 40 &&
               TPoseReach(*c, ext[static_cast<size_t>(k)], below.z, sign) > 0.15 * h) {
      // A piece reaching inside the trunk's side is no A-pose arm when a
      // T-pose arm stretches out above. On a sparse scan (under ~60k
      // cleaned points) the trunk's back can break up in a thin slice and
      // its side fragment join the arm's piece; then nothing reaches out
      // above the armpit and the piece is the A-pose arm after all.
      piece = -1;
    }
  }
  arm.found = true;
  if (piece >= 0) {
    // A-pose. The sections join between slice k and the one above; the
    // armpit is the trunk's side there, facing the arm (a hole in the
    // armpit can only raise the level where the pieces join, by its size).
    // Its y: the arm's centre there (the hollow lies under the arm's middle).
    const double arm_y = below.pieces[static_cast<size_t>(piece)].centroid.y();
    double side_x = -kInf;
    for (int r : trunk) {
      const double x = sign * c->points(r, 0);
      if (std::abs(c->points(r, 1) - arm_y) < 10 && x > ext[static_cast<size_t>(k)] - 40)
        side_x = std::max(side_x, x);
    }
    if (!std::isfinite(side_x)) side_x = ext[static_cast<size_t>(k)];
    double apex = below.z + 0.5 * c->step;
    Eigen::Vector2d mid(sign * side_x, arm_y);
    // An arm resting on the trunk above the join: the notch's top.
    const std::vector<ArmNotch> climb = ClimbArmNotch(
        *c, k, sign, [&](int s) { return c->TrunkRows(c->slices[static_cast<size_t>(s)]); });
    if (!climb.empty()) {
      apex = c->slices[static_cast<size_t>(k) + climb.size()].z + 0.5 * c->step;
      mid = Eigen::Vector2d(climb.back().x_mm, climb.back().lobe_y_mm);
    }
    arm.t_pose = false;
    arm.armpit_z = apex;
    arm.armpit = Eigen::Vector3d(mid.x(), mid.y(), apex);
    c->Put(name, arm.armpit, 0.85, climb.empty() ? "arm_trunk_gap_apex" : "arm_notch_top");
    TrackArmDown(*c, k, piece, sign, &arm);
    // Above the armpit the arm is part of the trunk's section: its points
    // beyond the armpit (the deltoid) belong to the arm too.
    for (int s = k + 1;
         s < static_cast<int>(c->slices.size()) && c->slices[static_cast<size_t>(s)].z < apex + 160;
         ++s) {
      for (int r : c->slices[static_cast<size_t>(s)].rows) {
        if (sign * c->points(r, 0) > sign * arm.armpit.x() + 5) arm.rows.push_back(r);
      }
    }
  } else {
    // T-pose: the arm's underside; its bottom meets the trunk's side.
    arm.t_pose = true;
    const double side_x = ext[static_cast<size_t>(k)];
    const Slice& above = c->slices[static_cast<size_t>(
        std::min<int>(k + 1, static_cast<int>(c->slices.size()) - 1))];
    double y = 0;
    int n = 0;
    for (int r : above.rows) {
      const double x = sign * c->points(r, 0);
      if (x > side_x - 10 && x < side_x + 30) y += c->points(r, 1), ++n;
    }
    arm.armpit_z = below.z + 0.5 * c->step;
    arm.armpit = Eigen::Vector3d(sign * side_x, n ? y / n : 0.0, arm.armpit_z);
    c->Put(name, arm.armpit, 0.75, "arm_underside_meets_trunk");
    CollectTPoseArm(*c, side_x, arm.armpit_z, sign, &arm);
  }
}

// The arm's centre line from the structure: the centroids of its points in
// bands of geodesic distance from the hand (15 mm), from the armpit out.
void CentreLineFromHand(const Context& c, int side, ArmInfo* arm) {
  const std::vector<double>& d = c.structure.from_hand[side];
  double top = 0;
  for (int r : arm->rows)
    if (std::isfinite(d[static_cast<size_t>(r)])) top = std::max(top, d[static_cast<size_t>(r)]);
  const int bands = static_cast<int>(top / 15) + 1;
  std::vector<Eigen::Vector3d> sum(static_cast<size_t>(bands), Eigen::Vector3d::Zero());
  std::vector<int> count(static_cast<size_t>(bands), 0);
  for (int r : arm->rows) {
    if (!std::isfinite(d[static_cast<size_t>(r)])) continue;  // a piece apart from the body
    const size_t b = static_cast<size_t>(d[static_cast<size_t>(r)] / 15);
    sum[b] += c.P(r), ++count[b];
  }
  for (int b = bands - 1; b >= 0; --b)
    if (count[static_cast<size_t>(b)] >= 8)
      arm->centre_line.push_back(sum[static_cast<size_t>(b)] / count[static_cast<size_t>(b)]);
}

// The rows of slice `s` that are the trunk's or the arm `arm_part`'s (other
// limbs left out).
std::vector<int> TrunkAndArmRows(const Context& c, const Slice& s, Part arm_part) {
  std::vector<int> rows;
  for (int r : s.rows) {
    const Part p = c.PartOf(r);
    if (p == Part::kTrunk || p == arm_part) rows.push_back(r);
  }
  return rows;
}

// The 2-D pieces of slice `s` made of the trunk's and this arm's points
// (TrunkAndArmRows, linked within `link_mm`), the central ones (holding
// trunk points within 60 mm of the middle; a hole can split the trunk's
// section) merged into the first. `central` gets 0 when there is one, -1
// when none.
std::vector<Piece> TrunkAndArmPieces(const Context& c, const Slice& s, Part arm_part,
                                     double link_mm, int* central) {
  std::vector<Piece> out(1);
  for (Piece& piece : SplitPieces(c.points, TrunkAndArmRows(c, s, arm_part), link_mm)) {
    bool centre = false;
    for (int r : piece.rows) centre |= std::abs(c.points(r, 0)) < 60 && c.PartOf(r) == Part::kTrunk;
    if (centre)
      out[0].rows.insert(out[0].rows.end(), piece.rows.begin(), piece.rows.end());
    else
      out.push_back(std::move(piece));
  }
  *central = out[0].rows.empty() ? -1 : 0;
  return out;
}

// The least links of the armpit's pieces (mm): the wide one, the fine one.
constexpr double kWideLinkMm = 12, kFineLinkMm = 7;

// Near the apex the gap between arm and trunk narrows slowly, so pieces
// linked within 12 mm join them below it on a dense scan. From the
// wide link's level `k` (`wide`: the trunk extents at that link), the level
// rises while the pieces of a finer link (`fine`: their trunk extents) still
// show the arm apart (Dropped) from a trunk as wide as at `k` (within 15 mm).
// The finer link is trusted only where it keeps the trunk's piece as the
// wide link has it at `k` and the two slices below (extent within 1 mm): on
// a sparser scan it breaks pieces off the trunk's side and off the folds
// round the armpit, and would part the arm from the trunk above the apex.
int RaiseWithFineLink(const std::vector<double>& wide, const std::vector<double>& fine, int k,
                      int top) {
  for (int s = std::max(0, k - 2); s <= k; ++s)
    if (!(fine[static_cast<size_t>(s)] >= wide[static_cast<size_t>(s)] - 1)) return k;
  const double side = wide[static_cast<size_t>(k)];
  for (int s = k + 1; s < top; ++s) {
    const double e = fine[static_cast<size_t>(s)];
    if (!Dropped(fine, s, top) || std::abs(e - side) > 15) break;
    k = s;
  }
  return k;
}

// The armpit with the structure: in the slices from 160 mm above to 120 mm
// below the structure's corner (which lies 12-133 mm under the true armpit
// of the T-posed bodies of the completeness set: the hand-to-foot path
// turns low round a heavy body's lats), the lateral extent of the trunk's piece
// (with the arm while they are one section) drops where the arm leaves it:
// the first slice, going down, 30 mm below the widest of the 60 mm above,
// for three slices, to within 60 mm of the corner's side (a T-pose arm's
// section shortens where the hand ends). Then as without the structure: an arm piece beside the
// trunk (A-pose) puts the armpit on the trunk's side at the arm's centre;
// none (T-pose), under the arm's underside. No drop: the arm touches the
// trunk down its side; the corner is kept, flagged. The pieces' links scale
// with `spacing_q90_mm`, the 90th percentile of the scan's nearest-neighbour
// distance (mm); the level rises with the finer one (RaiseWithFineLink).
void FindArmpitFromStructure(Context* c, int sign, double spacing_q90_mm) {
  const int side = sign > 0 ? 0 : 1;
  ArmInfo& arm = c->arm[side];
  const BodyStructure& b = c->structure;
  const std::string name = "armpit" + Side(sign);
  if (!b.has_hand[side] || !b.has_armpit[side]) {
    c->Missing(name, "no arm reaches out of the trunk on this side");
    return;
  }
  const Part arm_part = side == 0 ? Part::kArmRight : Part::kArmLeft;
  for (Eigen::Index r = 0; r < c->points.rows(); ++r)
    if (c->PartOf(static_cast<int>(r)) == arm_part) arm.rows.push_back(static_cast<int>(r));
  CentreLineFromHand(*c, side, &arm);
  if (arm.centre_line.size() >= 2) {
    const Eigen::Vector3d axis = (arm.centre_line.back() - arm.centre_line.front()).normalized();
    arm.t_pose = std::abs(axis.z()) < 0.5;  // more than 60 deg from the vertical
  }
  arm.found = true;
  const Eigen::Vector3d corner = b.armpit[side];
  const int top = SliceAt(c->slices, corner.z() + 160),
            bottom = SliceAt(c->slices, corner.z() - 120);
  auto extents = [&](double link_mm) {
    std::vector<double> ext(c->slices.size(), -kInf);
    for (int s = bottom; s <= top; ++s) {
      int central = -1;
      const auto pieces =
          TrunkAndArmPieces(*c, c->slices[static_cast<size_t>(s)], arm_part, link_mm, &central);
      if (central >= 0)
        for (int r : pieces[static_cast<size_t>(central)].rows)
          ext[static_cast<size_t>(s)] =
              std::max(ext[static_cast<size_t>(s)], sign * c->points(r, 0));
    }
    return ext;
  };
  // Pieces linked within 12 mm keep a dense scan's trunk in one piece; a
  // sparser one needs three times the spacing of its sparse parts (15 mm on
  // a 60k-point scan, where 12 mm breaks the trunk's sides off and the arm
  // seems to leave it far below the armpit). At most 18 mm.
  const double wide_link = std::clamp(3 * spacing_q90_mm, kWideLinkMm, 18.0);
  const std::vector<double> ext = extents(wide_link);
  const int k =
      ArmLeavesTrunk(ext, bottom, top, [&](double e) { return e < sign * corner.x() + 60; });
  if (k < 0) {
    arm.touching = true;
    arm.armpit = corner;
    arm.armpit_z = corner.z();
    c->Put(name, corner, 0.4, "structure_corner_arm_touching", {"arm_touching_torso"});
    return;
  }
  // The level rises with a finer link, twice the spacing of the scan's
  // sparse parts (RaiseWithFineLink); the arm's and the trunk's pieces that
  // place the point across are the wide link's.
  const double fine_link = std::clamp(2 * spacing_q90_mm, kFineLinkMm, kWideLinkMm);
  const int level = RaiseWithFineLink(ext, extents(fine_link), k, top);
  const Slice& below = c->slices[static_cast<size_t>(k)];
  int central = -1;
  const auto pieces = TrunkAndArmPieces(*c, below, arm_part, wide_link, &central);
  const double side_x = ext[static_cast<size_t>(k)];
  // The arm's piece: the largest lateral piece within 250 mm of the trunk's side.
  int piece = -1;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    if (static_cast<int>(i) == central || p.rows.size() < 4 ||
        sign * p.centroid.x() < side_x - 40 ||
        (p.centroid - Eigen::Vector2d(sign * side_x, p.centroid.y())).norm() > 250)
      continue;
    if (piece < 0 || p.rows.size() > pieces[static_cast<size_t>(piece)].rows.size())
      piece = static_cast<int>(i);
  }
  // An arm resting on the trunk above the join: the notch's top. Above a
  // raised arm's armpit the sections cut the arm lengthwise, a lobe beside
  // the trunk up to the arm's top: no climb there.
  const std::vector<ArmNotch> climb =
      piece < 0 || arm.t_pose
          ? std::vector<ArmNotch>{}
          : ClimbArmNotch(*c, level, sign, [&](int s) {
              return TrunkAndArmRows(*c, c->slices[static_cast<size_t>(s)], arm_part);
            });
  if (!climb.empty()) {
    ClaimRestingArm(c, level, sign, climb, arm_part, &arm);
    arm.centre_line.clear();
    CentreLineFromHand(*c, side, &arm);
    arm.armpit_z = c->slices[static_cast<size_t>(level) + climb.size()].z + 0.5 * c->step;
    arm.armpit = Eigen::Vector3d(climb.back().x_mm, climb.back().lobe_y_mm, arm.armpit_z);
    c->Put(name, arm.armpit, 0.85, "arm_notch_top");
    return;
  }
  arm.armpit_z = c->slices[static_cast<size_t>(level)].z + 0.5 * c->step;
  double y = corner.y();
  if (piece >= 0) {
    // The hollow lies under the arm's middle: the trunk's side at the arm's centre y.
    y = pieces[static_cast<size_t>(piece)].centroid.y();
  } else {
    // Under a T-pose arm: the middle of the arm's underside where it meets the trunk.
    double sum = 0;
    int n = 0;
    for (int r : c->slices[static_cast<size_t>(std::min<int>(k + 1, top))].rows) {
      const double x = sign * c->points(r, 0);
      if (x > side_x - 10 && x < side_x + 30) sum += c->points(r, 1), ++n;
    }
    if (n > 0) y = sum / n;
  }
  double x = -kInf;
  if (central >= 0)
    for (int r : pieces[static_cast<size_t>(central)].rows)
      if (std::abs(c->points(r, 1) - y) < 10) x = std::max(x, sign * c->points(r, 0));
  if (!(x > 0)) x = side_x;
  if (!(x > 0)) x = sign * corner.x();
  arm.armpit = Eigen::Vector3d(sign * x, y, arm.armpit_z);
  c->Put(name, arm.armpit, 0.85, piece >= 0 ? "arm_trunk_gap_apex" : "arm_underside_meets_trunk");
}

}  // namespace

void FindArmpits(Context* c) {
  // The spacing of the scan's sparse parts (90th percentile of the
  // nearest-neighbour distance, mm) sets the armpit's links.
  const double spacing_q90_mm = c->structure.ok ? c->index->SpacingQuantile(0.9) : 0;
  for (int sign : {+1, -1}) {
    if (c->structure.ok)
      FindArmpitFromStructure(c, sign, spacing_q90_mm);
    else
      FindArmpit(c, sign);
  }
}

}  // namespace bespoke::landmarks
