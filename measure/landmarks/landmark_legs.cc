// Legs: thigh, knee, calf and the inside and outside ankle points, from
// each leg's own piece in the slices below the crotch.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "measure/landmarks/landmark_context.h"
#include "measure/landmarks/profile_extreme.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// Heights as shares of the crotch height, where the scan shows no shape
// cue: the leg's width changes smoothly at the malleoli (about 0.09-0.10)
// and round the knee. The knee's first estimate: knee (mid-patella) height
// about 0.285 and crotch height about 0.47 of stature (ISO 7250-1 style
// survey data) give 0.61; the MakeHuman bodies' knees sit lower (0.58), the
// parametric body's at 0.62, so 0.595 between them (KneeLevel refines it).
constexpr double kKneeShare = 0.595;
constexpr double kAnkleShare = 0.095;

// The knee's level is sought this far either side of the estimate, mm.
constexpr double kKneeSearchMm = 50;
// Mid-patella above the steepest climb of the leg's front profile, mm: about
// half a kneecap over its lower edge, set between the offsets the oracle's
// two body models show (the knee's median height error it leaves on the
// full-range sets is in docs/landmarks.md).
constexpr double kPatellaAboveSteepestMm = 16;
// The least climb (mm of front per mm of height) that counts as the
// kneecap's edge; a flatter front keeps the estimate.
constexpr double kKneeMinSlope = 0.15;

// The leg's rows per slice (index = slice), tracked from mid-shin up to the
// crotch and down to the sole; empty where the leg was lost.
std::vector<std::vector<int>> TrackLeg(const Context& c, int sign) {
  std::vector<std::vector<int>> leg(c.slices.size());
  if (c.structure.ok) {
    // The structure's leg: its points in each slice up to the crotch.
    const Part part = sign > 0 ? Part::kLegRight : Part::kLegLeft;
    const int end = SliceAt(c.slices, c.crotch_z - c.step);
    bool any = false;
    // Between the feet's path and a crotch above it (thighs that touch),
    // the trunk's points on this side of x = 0 are the leg's.
    const double joined = c.structure.crotch.z();
    for (int s = 0; s <= end; ++s)
      for (int r : c.slices[static_cast<size_t>(s)].rows)
        if (c.PartOf(r) == part ||
            (c.PartOf(r) == Part::kTrunk && c.points(r, 2) > joined && sign * c.points(r, 0) > 0))
          leg[static_cast<size_t>(s)].push_back(r), any = true;
    if (!any)
      throw InputError("landmarks: no " + std::string(sign > 0 ? "right" : "left") + " leg found");
    return leg;
  }
  const int start = SliceAt(c.slices, 0.3 * c.crotch_z);
  const Slice& s0 = c.slices[static_cast<size_t>(start)];
  int first = -1;
  for (size_t i = 0; i < s0.pieces.size(); ++i) {
    const Piece& p = s0.pieces[i];
    if (sign * p.centroid.x() > 0 &&
        (first < 0 || p.rows.size() > s0.pieces[static_cast<size_t>(first)].rows.size())) {
      first = static_cast<int>(i);
    }
  }
  if (first < 0)
    throw InputError("landmarks: no " + std::string(sign > 0 ? "right" : "left") + " leg found");
  for (int dir : {+1, -1}) {
    Eigen::Vector2d centre = s0.pieces[static_cast<size_t>(first)].centroid;
    const int end = dir > 0 ? SliceAt(c.slices, c.crotch_z - c.step) : 0;
    for (int s = start; dir > 0 ? s <= end : s >= end; s += dir) {
      const Slice& slice = c.slices[static_cast<size_t>(s)];
      int best = -1;
      double best_d = 80;
      for (size_t i = 0; i < slice.pieces.size(); ++i) {
        const double d = (slice.pieces[i].centroid - centre).norm();
        if (d < best_d && slice.pieces[i].rows.size() >= 4) best_d = d, best = static_cast<int>(i);
      }
      if (best < 0) continue;
      centre = slice.pieces[static_cast<size_t>(best)].centroid;
      leg[static_cast<size_t>(s)] = slice.pieces[static_cast<size_t>(best)].rows;
    }
  }
  return leg;
}

// The leg row within `half` of height z passing `keep` that is most
// extreme along `direction` (noise averaged); -1 when none.
template <typename Keep>
int BestNear(const Context& c, const std::vector<std::vector<int>>& leg, double z, double half,
             Keep keep, const Eigen::Vector3d& direction, double radius_mm = 12) {
  std::vector<int> candidates;
  for (int s = SliceAt(c.slices, z - half); s <= SliceAt(c.slices, z + half); ++s) {
    for (int r : leg[static_cast<size_t>(s)]) {
      const Eigen::Vector3d p = c.P(r);
      if (std::abs(p.z() - z) <= half && keep(p)) candidates.push_back(r);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  return c.SmoothExtreme(candidates, direction, radius_mm, radius_mm / 2);
}

// The calf's level: the height of the leg's largest girth (convex hull of
// its section) between lo and hi (mm), refined off the slice grid
// (profile_extreme.h); -1 when the leg has no section there. The girth
// profile is smoothed over five slices first: on a leg whose girth barely
// changes between the calf and the knee the single largest slice is noise.
// The calf is a bulge: only a level with a section at least kCalfDipMm
// smaller somewhere above it in the band counts, so the widening below the
// knee, which outgrows the calf on many heavy legs, is not taken for it (the
// band's largest girth when no level has such a dip above it).
double CalfLevel(const Context& c, const std::vector<std::vector<int>>& leg, double lo, double hi) {
  constexpr double kCalfDipMm = 3;
  std::vector<double> at, raw;
  for (int s = SliceAt(c.slices, lo) - 5; s <= SliceAt(c.slices, hi) + 5; ++s) {
    if (s < 0 || s >= static_cast<int>(c.slices.size())) continue;
    const std::vector<int>& rows = leg[static_cast<size_t>(s)];
    at.push_back(c.slices[static_cast<size_t>(s)].z);
    raw.push_back(rows.size() < 12 ? kNaN : HullPerimeter(c.points, rows));
  }
  const std::vector<double> girth = WindowMean(raw, 2, 3);
  std::vector<bool> inside(raw.size());
  for (size_t k = 0; k < raw.size(); ++k)
    inside[k] = at[k] >= lo - 0.5 * c.step && at[k] <= hi + 0.5 * c.step;
  // Below a dip: the smallest girth in the band above each level.
  std::vector<bool> bulge(raw.size(), false);
  double above = kInf;
  for (size_t k = raw.size(); k-- > 0;) {
    bulge[k] = inside[k] && girth[k] > above + kCalfDipMm;
    if (inside[k] && std::isfinite(girth[k])) above = std::min(above, girth[k]);
  }
  ProfileExtremeOptions largest;
  largest.minimum = false;
  size_t best = BestSample(largest, girth, bulge);
  if (best == raw.size()) best = BestSample(largest, girth, inside);
  return best < at.size() ? ProfileExtreme(largest, at, girth, best) : -1;
}

// The knee's level near `estimate_z` (mm): the shin lies behind the
// kneecap, so the leg's front profile (mean of the three most forward
// points per slice, then of five slices) climbs fastest at the kneecap's
// lower edge, and mid-patella lies kPatellaAboveSteepestMm above that (the
// climb's peak refined off the slice grid, profile_extreme.h). `estimate_z`
// when the front climbs less than kKneeMinSlope anywhere within
// kKneeSearchMm.
double KneeLevel(const Context& c, const std::vector<std::vector<int>>& leg, double estimate_z,
                 bool* found) {
  const int lo = SliceAt(c.slices, estimate_z - kKneeSearchMm) - 4,
            hi = SliceAt(c.slices, estimate_z + kKneeSearchMm) + 4;
  std::vector<double> at, front;
  for (int s = std::max(0, lo); s <= std::min<int>(hi, c.slices.size() - 1); ++s) {
    // The mean of the three most forward points: one point's noise moves
    // the profile's slope, and the knee with it.
    std::vector<double> y;
    for (int r : leg[static_cast<size_t>(s)]) y.push_back(c.points(r, 1));
    const size_t n = std::min<size_t>(3, y.size());
    std::partial_sort(y.begin(), y.begin() + static_cast<long>(n), y.end(), std::greater<>());
    at.push_back(c.slices[static_cast<size_t>(s)].z);
    front.push_back(n < 3 ? kNaN : (y[0] + y[1] + y[2]) / 3);
  }
  const std::vector<double> mean = WindowMean(front, 2, 3);
  std::vector<double> slope(at.size(), kNaN);
  std::vector<bool> inside(at.size(), false);
  for (size_t k = 2; k + 2 < at.size(); ++k) {
    slope[k] = (mean[k + 2] - mean[k - 2]) / (at[k + 2] - at[k - 2]);
    inside[k] = std::abs(at[k] - estimate_z) <= kKneeSearchMm;
  }
  ProfileExtremeOptions steepest;
  steepest.minimum = false;
  steepest.half_window = 4;
  const size_t best = BestSample(steepest, slope, inside);
  *found = best < at.size() && slope[best] >= kKneeMinSlope;
  if (!*found) return estimate_z;
  return ProfileExtreme(steepest, at, slope, best) + kPatellaAboveSteepestMm;
}

void FindLeg(Context* c, int sign) {
  const std::string side = Side(sign);
  const auto leg = TrackLeg(*c, sign);
  auto all = [](const Eigen::Vector3d&) { return true; };
  // Thigh: 20 mm below the crotch, the outside of the leg.
  const double thigh_z = c->crotch_z - 20;
  const int thigh = BestNear(*c, leg, thigh_z, 4, all, Eigen::Vector3d(sign, 0, 0));
  if (thigh >= 0) {
    Eigen::Vector3d p = c->P(thigh);
    p.z() = thigh_z;
    c->Put("thigh" + side, p, 0.8, "below_crotch_outside");
  } else {
    c->Missing("thigh" + side, "no leg section below the crotch");
  }
  bool from_profile = false;
  const double knee_z = KneeLevel(*c, leg, kKneeShare * c->crotch_z, &from_profile);
  const int knee = BestNear(*c, leg, knee_z, from_profile ? 4 : 15, all, Eigen::Vector3d::UnitY());
  if (knee >= 0 && from_profile) {
    Eigen::Vector3d p = c->P(knee);
    p.z() = knee_z;
    c->Put("knee" + side, p, 0.7, "front_profile_steepest");
  } else if (knee >= 0) {
    c->Put("knee" + side, c->P(knee), 0.6, "proportion_front_max");
  } else {
    c->Missing("knee" + side, "no leg section at knee height");
  }
  const double ankle_z = kAnkleShare * c->crotch_z;
  // The ankle's centre: the leg's section 40 mm higher, above the foot.
  double ay = 0;
  int n = 0;
  for (int r : leg[static_cast<size_t>(SliceAt(c->slices, ankle_z + 40))])
    ay += c->points(r, 1), ++n;
  if (n == 0) {
    c->Missing("ankle_inside" + side, "no leg section above the ankle");
    c->Missing("ankle_outside" + side, "no leg section above the ankle");
  } else {
    ay /= n;
    auto near_axis = [&](const Eigen::Vector3d& p) { return std::abs(p.y() - ay) < 30; };
    const int in = BestNear(*c, leg, ankle_z, 12, near_axis, Eigen::Vector3d(-sign, 0, 0));
    const int out = BestNear(*c, leg, ankle_z, 12, near_axis, Eigen::Vector3d(sign, 0, 0));
    if (in >= 0)
      c->Put("ankle_inside" + side, c->P(in), 0.6, "proportion_section_inside");
    else
      c->Missing("ankle_inside" + side, "no points at the inner ankle");
    if (out >= 0)
      c->Put("ankle_outside" + side, c->P(out), 0.6, "proportion_section_outside");
    else
      c->Missing("ankle_outside" + side, "no points at the outer ankle");
  }
  // Calf: the level of the leg's largest girth (CalfLevel), the back of the
  // leg there.
  const double calf_z =
      CalfLevel(*c, leg, ankle_z + 0.25 * (knee_z - ankle_z), ankle_z + 0.9 * (knee_z - ankle_z));
  const int calf =
      calf_z > 0 ? BestNear(*c, leg, calf_z, 4, all, -Eigen::Vector3d::UnitY(), 12) : -1;
  if (calf >= 0) {
    Eigen::Vector3d p = c->P(calf);
    p.z() = calf_z;
    c->Put("calf" + side, p, 0.6, "leg_girth_max");
  } else {
    c->Missing("calf" + side, "no leg section between ankle and knee");
  }
}

}  // namespace

void FindLegs(Context* c) {
  for (int sign : {+1, -1}) {
    try {
      FindLeg(c, sign);
    } catch (const InputError& e) {
      for (const char* n : {"thigh", "knee", "calf", "ankle_inside", "ankle_outside"})
        c->Missing(n + Side(sign), e.what());
    }
  }
}

}  // namespace bespoke::landmarks
