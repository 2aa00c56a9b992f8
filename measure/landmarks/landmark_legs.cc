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
// cue: the leg's width changes smoothly at the malleoli and round the
// knee. The knee's first estimate: knee (mid-patella) height
// about 0.285 and crotch height about 0.47 of stature (ISO 7250-1 style
// survey data) give 0.61; the MakeHuman bodies' knees sit lower (0.58), the
// parametric body's at 0.62, so 0.595 between them (KneeLevel refines it).
constexpr double kKneeShare = 0.595;
// The ankle's level, which the calf's band and the ankle's centre (the
// leg's section 40 mm above it) hang from.
constexpr double kAnkleShare = 0.095;
// The malleoli's own heights, as shares of the crotch height. The medial
// malleolus sits higher than the lateral one, whose tip reaches further
// down. The oracle's two body models place them by different conventions
// (MakeHuman: both at the ankle joint's height, inside 0.077 and outside
// 0.079 of the crotch height; the parametric body: inside 0.105, outside
// 0.088), and neither scan shows a bump to find, so each share is set
// between the two.
constexpr double kAnkleInsideShare = 0.091;
constexpr double kAnkleOutsideShare = 0.083;
// Half the height of the band an ankle point is sought in, mm: the leg
// widens towards the foot, so the most medial (lateral) point of a wider
// band lies at its bottom.
constexpr double kAnkleBandMm = 4;

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

// The leg's profile along y between lo and hi (mm): per slice the mean of
// the three most forward (`front`) or most backward points (one point's
// noise moves a slope, and any level found from it), then the mean of
// five slices; NaN where the leg has fewer than three points.
struct LegProfile {
  std::vector<double> at;     // slice heights, mm
  std::vector<double> y;      // smoothed profile, mm
  std::vector<double> slope;  // dy/dz over +-2 slices, NaN at the ends
};

LegProfile ProfileOf(const Context& c, const std::vector<std::vector<int>>& leg, double lo,
                     double hi, bool front) {
  LegProfile p;
  std::vector<double> raw;
  for (int s = std::max(0, SliceAt(c.slices, lo)); s <= SliceAt(c.slices, hi); ++s) {
    std::vector<double> y;
    for (int r : leg[static_cast<size_t>(s)]) y.push_back((front ? 1 : -1) * c.points(r, 1));
    const size_t n = std::min<size_t>(3, y.size());
    std::partial_sort(y.begin(), y.begin() + static_cast<long>(n), y.end(), std::greater<>());
    p.at.push_back(c.slices[static_cast<size_t>(s)].z);
    raw.push_back(n < 3 ? kNaN : (front ? 1 : -1) * (y[0] + y[1] + y[2]) / 3);
  }
  p.y = WindowMean(raw, 2, 3);
  p.slope.assign(p.at.size(), kNaN);
  for (size_t k = 2; k + 2 < p.at.size(); ++k)
    p.slope[k] = (p.y[k + 2] - p.y[k - 2]) / (p.at[k + 2] - p.at[k - 2]);
  return p;
}

// The front cue: the shin lies behind the kneecap, so the front profile
// climbs fastest at the kneecap's lower edge, and mid-patella lies
// kPatellaAboveSteepestMm above that (the climb's peak refined off the
// slice grid, profile_extreme.h), within kKneeSearchMm of `estimate_z`.
// NaN when the front climbs less than kKneeMinSlope there.
double FrontKnee(const LegProfile& front, double estimate_z) {
  std::vector<bool> inside(front.at.size());
  for (size_t k = 0; k < front.at.size(); ++k)
    inside[k] = std::abs(front.at[k] - estimate_z) <= kKneeSearchMm;
  ProfileExtremeOptions steepest;
  steepest.minimum = false;
  steepest.half_window = 4;
  const size_t best = BestSample(steepest, front.slope, inside);
  if (best == front.at.size() || front.slope[best] < kKneeMinSlope) return kNaN;
  return ProfileExtreme(steepest, front.at, front.slope, best) + kPatellaAboveSteepestMm;
}

// The back cue: above the calf's bulge the back of the leg recedes to the
// hollow behind the knee and then runs flat or turns back out into the
// thigh. The knee is where that recession has slowed to half its fastest
// rate (within kCalfRecessionMm above the calf; the calf is the most
// backward level between kCalfLowShare and kCalfHighShare of the crotch
// height). NaN when the back does not recede there.
double BackKnee(const LegProfile& back, double crotch_z) {
  constexpr double kCalfLowShare = 0.3, kCalfHighShare = 0.55, kCalfRecessionMm = 200;
  constexpr double kMinRecession = 0.05;  // mm of back per mm of height
  const size_t n = back.at.size();
  size_t calf = n;
  for (size_t k = 0; k < n; ++k) {
    if (back.at[k] < kCalfLowShare * crotch_z || back.at[k] > kCalfHighShare * crotch_z ||
        !std::isfinite(back.y[k]))
      continue;
    if (calf == n || back.y[k] < back.y[calf]) calf = k;
  }
  if (calf == n) return kNaN;
  size_t peak = n;
  for (size_t k = calf + 1; k < n && back.at[k] < back.at[calf] + kCalfRecessionMm; ++k)
    if (std::isfinite(back.slope[k]) && (peak == n || back.slope[k] > back.slope[peak])) peak = k;
  if (peak == n || back.slope[peak] < kMinRecession) return kNaN;
  for (size_t k = peak; k < n; ++k)
    if (std::isfinite(back.slope[k]) && back.slope[k] < 0.5 * back.slope[peak]) return back.at[k];
  return kNaN;
}

// The knee's level (mm) and how it was found. Two shape cues that fail on
// different legs: the front cue (a steady climb from shin to a heavy thigh
// leaves its steepest point anywhere in the window) and the back cue (a leg
// without a calf bulge). Where they agree within two slices, their mean;
// where they disagree, the median of the two and kKneeShare of the crotch
// height, so that the failing one is outvoted; with one missing, its mean
// with that proportion; with neither, the proportion (`shaped` false).
struct KneeLevel {
  double z_mm = kNaN;
  const char* method = "";
  double confidence = 0.6;
  bool shaped = true;
};

KneeLevel FindKneeLevel(const Context& c, const std::vector<std::vector<int>>& leg) {
  const double estimate_z = kKneeShare * c.crotch_z;
  const LegProfile front = ProfileOf(c, leg, estimate_z - kKneeSearchMm - 4 * c.step,
                                     estimate_z + kKneeSearchMm + 4 * c.step, true);
  const LegProfile back = ProfileOf(c, leg, 0.25 * c.crotch_z, 0.85 * c.crotch_z, false);
  const double f = FrontKnee(front, estimate_z), b = BackKnee(back, c.crotch_z);
  KneeLevel k;
  if (std::isfinite(f) && std::isfinite(b) && std::abs(f - b) <= 2 * c.step) {
    k = {(f + b) / 2, "front_back_mean", 0.7, true};
  } else if (std::isfinite(f) && std::isfinite(b)) {
    k = {std::max(std::min(f, b), std::min(std::max(f, b), estimate_z)),
         "front_back_proportion_median", 0.6, true};
  } else if (std::isfinite(f) || std::isfinite(b)) {
    k = {((std::isfinite(f) ? f : b) + estimate_z) / 2, "shape_proportion_mean", 0.6, true};
  } else {
    k = {estimate_z, "proportion_front_max", 0.6, false};
  }
  return k;
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
  const KneeLevel level = FindKneeLevel(*c, leg);
  const double knee_z = level.z_mm;
  const int knee = BestNear(*c, leg, knee_z, level.shaped ? 4 : 15, all, Eigen::Vector3d::UnitY());
  if (knee >= 0) {
    // A shape cue sets the level; the proportion alone keeps the point's own.
    Eigen::Vector3d p = c->P(knee);
    if (level.shaped) p.z() = knee_z;
    c->Put("knee" + side, p, level.confidence, level.method);
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
    for (const bool inside : {true, false}) {
      const double z = (inside ? kAnkleInsideShare : kAnkleOutsideShare) * c->crotch_z;
      const Eigen::Vector3d direction(inside ? -sign : sign, 0, 0);
      const int best = BestNear(*c, leg, z, kAnkleBandMm, near_axis, direction);
      const std::string name = (inside ? "ankle_inside" : "ankle_outside") + side;
      if (best < 0) {
        c->Missing(name, inside ? "no points at the inner ankle" : "no points at the outer ankle");
        continue;
      }
      Eigen::Vector3d p = c->P(best);
      p.z() = z;
      c->Put(name, p, 0.6, inside ? "proportion_section_inside" : "proportion_section_outside");
    }
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
