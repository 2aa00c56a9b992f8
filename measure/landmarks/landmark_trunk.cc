// Crown, crotch and the trunk levels: bust, under-bust, waist, middle hip,
// hip (docs/landmarks.md has the definitions and why).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "measure/landmarks/landmark_context.h"
#include "measure/landmarks/profile_extreme.h"
#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// The lowest slice (above 30 % of stature) with one piece spanning x = 0
// from side to side: below it the legs are two pieces. A hole under the
// crotch leaves the front and back walls of the pelvis ring, which still
// span x = 0, so the level survives it. -1 when there is none.
double CrotchLevelFromSlices(const Context& c, double h) {
  for (const Slice& s : c.slices) {
    if (s.z < 0.3 * h || s.z > 0.65 * h) continue;
    for (const Piece& p : s.pieces) {
      if (p.lo.x() < -40 && p.hi.x() > 40 && p.rows.size() > 20) {
        for (int r : p.rows)
          if (std::abs(c.points(r, 0)) < 10) return s.z;
      }
    }
  }
  return -1;
}

// The hip (seat) level: the most backward point of the buttocks between
// the crotch and `top` (mm). The buttocks' back is flat in height over a
// few centimetres, so the single most backward point jumps with the noise
// between scans of one body; the back profile (per 5 mm slice the mean y
// of the trunk's five most backward points, |x| < 150 mm) is smooth, and
// the vertex of its parabola round the most backward slice
// (profile_extreme.h) is the level. Throws InputError when no slice there
// has points.
double HipLevel(const Context& c, double top) {
  std::vector<double> at, back;
  for (int s = SliceAt(c.slices, c.crotch_z); s <= SliceAt(c.slices, top); ++s) {
    const Slice& slice = c.slices[static_cast<size_t>(s)];
    std::vector<double> y;
    for (int r : c.TrunkRows(slice, 150))
      if (std::abs(c.points(r, 0)) < 150) y.push_back(c.points(r, 1));
    at.push_back(slice.z);
    if (y.size() < 5) {
      back.push_back(kNaN);
      continue;
    }
    std::partial_sort(y.begin(), y.begin() + 5, y.end());
    back.push_back((y[0] + y[1] + y[2] + y[3] + y[4]) / 5);
  }
  const size_t best = BestSample({}, back, std::vector<bool>(back.size(), true));
  if (best == back.size()) throw InputError("landmarks: no buttocks found above the crotch");
  return ProfileExtreme({}, at, back, best);
}

// The crotch on the mid-sagittal profile: the trunk's lowest point in 5 mm
// bins of y (|x| < 6 mm, from 60 mm below `level` to 80 mm above) is a
// U rising to the pubis in front and the buttocks behind; the vertex of a
// parabola fitted to its bottom 25 mm is the lowest point's y - stable on a
// flat ridge, where the single lowest point wanders with the noise, and
// across a hole in the bottom, which it bridges. False when the profile has no
// bottom (fewer than three bins, or no upward curve).
bool CrotchFromProfile(const Context& c, double level, Eigen::Vector3d* out) {
  std::map<int, std::vector<double>> bins;
  for (int s = SliceAt(c.slices, level - 60); s <= SliceAt(c.slices, level + 80); ++s)
    for (int r : c.slices[static_cast<size_t>(s)].rows)
      if (std::abs(c.points(r, 0)) < 6 && c.PartOf(r) == Part::kTrunk)
        bins[static_cast<int>(std::floor(c.points(r, 1) / 5))].push_back(c.points(r, 2));
  std::vector<Eigen::Vector2d> bottom;  // (y, z) of each bin's second lowest point
  double lowest = kInf;
  for (auto& [bin, z] : bins) {
    if (z.size() < 2) continue;
    std::nth_element(z.begin(), z.begin() + 1, z.end());
    bottom.emplace_back(5.0 * bin + 2.5, z[1]);
    lowest = std::min(lowest, z[1]);
  }
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  double y_lo = kInf, y_hi = -kInf;
  int n = 0;
  for (const Eigen::Vector2d& b : bottom) {
    if (b.y() > lowest + 25) continue;
    const Eigen::Vector3d a(1, b.x(), b.x() * b.x());
    ata += a * a.transpose(), atb += a * b.y(), ++n;
    y_lo = std::min(y_lo, b.x()), y_hi = std::max(y_hi, b.x());
  }
  if (n < 3 || y_hi - y_lo < 15) return false;
  const Eigen::Vector3d k = ata.ldlt().solve(atb);
  if (!(k(2) > 1e-5)) return false;
  const double y = std::clamp(-k(1) / (2 * k(2)), y_lo, y_hi);
  // Its height: the lowest bin within 10 mm of it; in a hole, the lowest
  // rim (the ridge's bottom is flat more often than it dips further).
  double z = kInf;
  for (const Eigen::Vector2d& b : bottom)
    if (std::abs(b.x() - y) <= 10) z = std::min(z, b.y());
  if (!std::isfinite(z)) z = lowest;
  *out = Eigen::Vector3d(0, y, z);
  return true;
}

// A part the pelvis's sections hold: the trunk's or a leg's (no arm).
bool TrunkOrLeg(Part p) { return p == Part::kTrunk || p == Part::kLegRight || p == Part::kLegLeft; }

// Whether the body's front at x = 0 in the slice at height z is a crease
// between two thighs that touch. Two signs, either enough:
//  - the walls: the three most forward points within 6 mm of x = 0 (trunk
//    and legs) have normals turned sideways (mean |n_x| > 0.45: the crease's
//    walls face each other), or no point lies there in front;
//  - the notch: the most forward point within 6 mm of x = 0 lies more than
//    10 mm behind the most forward points 12-24 mm either side. A tight
//    crease's bottom is rounded and faces forward, and a normal estimated
//    across it averages its two walls, so the walls' sign misses it; over
//    the pubis the front is a dome or a shallow trough between the thighs.
// Over the pubis and the belly the front faces forward or down (|n_x| small).
// Fewer than three points within 6 mm widen the strip to 10, then 14 mm: a
// sparse scan (60k points) has one or two there on the pubis as often as
// not, which would read as a hole and put the crotch 30-80 mm high. In a true
// hole between touching thighs the wider strip meets the thighs' walls,
// whose normals still face sideways.
bool FrontIsCrease(const Context& c, double z) {
  std::vector<int> near;
  double middle = 0, front[2] = {-kInf, -kInf};
  for (int r : c.At(z).rows) {
    if (TrunkOrLeg(c.PartOf(r))) {
      middle += c.points(r, 1);
      const double ax = std::abs(c.points(r, 0));
      if (ax < 14) near.push_back(r);
      if (ax >= 12 && ax < 24) {
        double& f = front[c.points(r, 0) > 0 ? 0 : 1];
        f = std::max(f, c.points(r, 1));
      }
    }
  }
  middle /= std::max<double>(1, static_cast<double>(c.At(z).rows.size()));
  std::vector<int> rows;
  for (const double width : {6.0, 10.0, 14.0}) {
    rows.clear();
    for (int r : near)
      if (std::abs(c.points(r, 0)) < width && c.points(r, 1) >= middle) rows.push_back(r);
    if (rows.size() >= 3) break;
  }
  if (rows.size() < 3) return true;
  std::partial_sort(rows.begin(), rows.begin() + 3, rows.end(),
                    [&](int a, int b) { return c.points(a, 1) > c.points(b, 1); });
  double nx = 0, centre = -kInf;
  for (int k = 0; k < 3; ++k) nx += std::abs(c.normals(rows[static_cast<size_t>(k)], 0)) / 3;
  for (int r : near)
    if (std::abs(c.points(r, 0)) < 6) centre = std::max(centre, c.points(r, 1));
  const bool notch = std::isfinite(centre) && std::min(front[0], front[1]) > centre + 10;
  return nx > 0.45 || notch;
}

}  // namespace

bool SeamPoint(const Context& c, double z, bool front, Eigen::Vector3d* out, double half_width_mm) {
  // Nearest slices first: a hole on the centre line at z borrows the
  // neighbouring slices' seam point (flagged by Put's in_hole test).
  const int centre = SliceAt(c.slices, z);
  for (int k = 0; k <= 3; ++k) {
    for (int s : {centre - k, centre + k}) {
      if (s < 0 || s >= static_cast<int>(c.slices.size())) continue;
      // The narrowest strip (2.5, 5, then 10 mm) that holds points: the
      // centre line itself can lie in a fold (the gluteal cleft, between
      // the breasts), which a wider strip would miss.
      int best_row = -1;
      const std::vector<int> rows = c.TrunkRows(c.slices[static_cast<size_t>(s)]);
      if (rows.empty()) continue;
      // A front point must lie in front of the section's middle (a hole in
      // the front, e.g. the throat under the chin, leaves only the back).
      double middle = 0;
      for (int r : rows) middle += c.points(r, 1);
      middle /= static_cast<double>(rows.size());
      for (double width :
           {std::min(2.5, half_width_mm), std::min(5.0, half_width_mm), half_width_mm}) {
        double best = front ? -kInf : kInf;
        for (int r : rows) {
          const double y = c.points(r, 1);
          if (std::abs(c.points(r, 0)) > width || (front ? y < middle : y > middle)) continue;
          if (front ? y > best : y < best) best = y, best_row = r;
        }
        if (best_row >= 0) break;
      }
      if (best_row >= 0) {
        *out = c.P(best_row);
        out->z() = z;
        return true;
      }
    }
  }
  return false;
}

// A sparse scan can hold no point within 10 mm of x = 0 in a fold (the
// gluteal cleft at the hip's level on 60k-point scans): a 20 mm strip then,
// at a lower confidence, as the point's height is what its girth needs.
void PutSeam(Context* c, const std::string& name, double z, bool front, double confidence,
             const std::string& method) {
  Eigen::Vector3d p;
  if (SeamPoint(*c, z, front, &p)) {
    c->Put(name, p, confidence, method);
  } else if (SeamPoint(*c, z, front, &p, 20)) {
    c->Put(name, p, 0.8 * confidence, method);
  } else {
    c->Missing(name, "no scan points on the centre line near z = " +
                         std::to_string(static_cast<int>(z)) + " mm");
  }
}

void FindCrownAndCrotch(Context* c) {
  // Crown: the top of the head; x, y from the points within 4 mm of the
  // top (the scan's noise moves the single highest point sideways), z from
  // the third highest point (less biased upwards by noise than the highest).
  c->crown_z = c->points.col(2).maxCoeff();
  std::vector<double> top_z;
  Eigen::Vector2d top_xy = Eigen::Vector2d::Zero();
  for (Eigen::Index r = 0; r < c->points.rows(); ++r) {
    if (c->points(r, 2) < c->crown_z - 4) continue;
    top_z.push_back(c->points(r, 2));
    top_xy += c->points.row(r).head<2>().transpose();
  }
  std::sort(top_z.rbegin(), top_z.rend());
  top_xy /= static_cast<double>(top_z.size());
  c->Put("crown",
         Eigen::Vector3d(top_xy.x(), top_xy.y(), top_z[std::min<size_t>(2, top_z.size() - 1)]), 1.0,
         "head_top");
  const double h = c->crown_z;
  // Crotch level: from the structure, the top of the path between the feet
  // (where the legs part); without one, from the slices.
  const double level =
      c->structure.ok ? c->structure.crotch.z() + 10 : CrotchLevelFromSlices(*c, h);
  if (level < 0)
    throw InputError("landmarks: no legs found (the trunk never splits into two legs)");
  Eigen::Vector3d crotch;
  if (c->structure.ok && c->has_normals()) {
    // Thighs that touch: the legs meet below the crotch, and so does the
    // path between the feet. Going up from it, the crotch is where the front
    // at x = 0 turns from the crease between the thighs (its walls face each
    // other) to the pubis, for two slices.
    const double apex = c->structure.crotch.z();
    double top = apex;
    for (double z = apex; z < apex + 0.2 * h; z += c->step) {
      top = z;
      if (!FrontIsCrease(*c, z) && !FrontIsCrease(*c, z + c->step)) break;
    }
    if (top > apex + 20) {
      Eigen::Vector3d front, back;
      const bool has_front = SeamPoint(*c, top, true, &front),
                 has_back = SeamPoint(*c, top, false, &back);
      const double y =
          has_front && has_back ? 0.5 * (front.y() + back.y()) : c->structure.crotch.y();
      c->crotch_z = top;
      c->Put("crotch", Eigen::Vector3d(0, y, top), 0.4, "top_of_thigh_contact",
             {"thighs_touching"});
      return;
    }
  }
  if (CrotchFromProfile(*c, level, &crotch)) {
    c->crotch_z = crotch.z();
    c->Put("crotch", crotch, 0.7, "sagittal_profile_lowest");
    return;
  }
  // Nothing on the centre line: a hole under the crotch.
  const Slice& s = c->At(level);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Piece& p : s.pieces)
    if (p.lo.x() < -40 && p.hi.x() > 40) centre = p.centroid;
  c->crotch_z = level - 0.5 * c->step;
  c->Put("crotch", Eigen::Vector3d(0, centre.y(), c->crotch_z), 0.5, "legs_join_level",
         {"in_hole"});
}

namespace {

// The level of the breast in the candidate rows: going down from the top,
// the first slice whose front (along `dir`, mean of three slices) stands
// out - no higher within 25 mm around it and at least 3 mm higher than the
// front somewhere in the 60 mm below (the fold under the breast) - or -1
// when the front only grows downwards (no breast ahead of a belly). The
// rows span slices lo..hi; the fold is sought down to lo, the peak only
// down to `peak_lo`.
double BreastLevel(const Context& c, const std::vector<int>& rows, const Eigen::Vector3d& dir,
                   int lo, int hi, int peak_lo) {
  std::vector<double> front(static_cast<size_t>(hi - lo + 1), -kInf);
  for (int r : rows) {
    const size_t k = static_cast<size_t>(SliceAt(c.slices, c.points(r, 2)) - lo);
    if (k < front.size()) front[k] = std::max(front[k], c.P(r).dot(dir));
  }
  std::vector<double> mean(front.size(), -kInf);
  for (size_t k = 1; k + 1 < front.size(); ++k)
    mean[k] = (front[k - 1] + front[k] + front[k + 1]) / 3;
  const int around = static_cast<int>(std::lround(25 / c.step)),
            below = static_cast<int>(std::lround(60 / c.step));
  for (int k = static_cast<int>(mean.size()) - 2; k >= std::max(1, peak_lo - lo); --k) {
    if (!std::isfinite(mean[static_cast<size_t>(k)])) continue;
    bool top = true;
    for (int j = std::max(1, k - around); j <= std::min<int>(k + around, mean.size() - 2); ++j)
      top &= !(mean[static_cast<size_t>(j)] > mean[static_cast<size_t>(k)]);
    // The fold under the breast: somewhere within `below` under it the
    // front lies 3 mm further back (a belly lower down may then stand out
    // further still: the breast is the first such peak from the top).
    double fold = kInf;
    for (int j = std::max(1, k - below); j < k; ++j)
      fold = std::min(fold, mean[static_cast<size_t>(j)]);
    if (top && k - below >= 1 && fold < mean[static_cast<size_t>(k)] - 3)
      return c.slices[static_cast<size_t>(lo + k)].z;
  }
  return -1;
}

// The bust points: the most forward trunk point on each side between 2 %
// and 10 % of stature below the armpit, between 30 % and 100 % of the
// armpit's distance from the centre line; where a breast stands out ahead
// of a belly below it (its peak down to 12 % of stature below the armpit),
// at the breast's level (BreastLevel).
void Bust(Context* c) {
  const double h = c->crown_z;
  for (int sign : {+1, -1}) {
    const std::string name = "bust" + Side(sign);
    const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
    if (!arm.found) {
      c->Missing(name, "the armpit was not found");
      continue;
    }
    const double ax = sign * arm.armpit.x();
    // The breast is sought from above the found armpit: where an arm rests
    // on a heavy body's side the armpit is found low, and a breast hanging
    // just under the true armpit would lie above the window.
    // A low breast (down to 12 % of stature under the armpit) keeps its
    // fold in view: the rows reach 60 mm further down.
    const int top = SliceAt(c->slices, arm.armpit_z + 0.03 * h),
              lo = SliceAt(c->slices, arm.armpit_z - 0.10 * h),
              hi = SliceAt(c->slices, arm.armpit_z - 0.02 * h),
              peak_lo = SliceAt(c->slices, arm.armpit_z - 0.12 * h),
              fold_lo = SliceAt(c->slices, arm.armpit_z - 0.12 * h - 60);
    std::vector<int> candidates;
    for (int s = fold_lo; s <= top; ++s) {
      for (int r : c->TrunkRows(c->slices[static_cast<size_t>(s)])) {
        const double x = sign * c->points(r, 0);
        if (x > 0.3 * ax && x < ax) candidates.push_back(r);
      }
    }
    // Breasts point forward and a little outward: the extreme along a
    // direction turned ~11 deg out from straight ahead.
    const Eigen::Vector3d dir = Eigen::Vector3d(sign * 0.2, 1, 0).normalized();
    const double level = BreastLevel(*c, candidates, dir, fold_lo, top, peak_lo);
    const double hi_z = c->slices[static_cast<size_t>(hi)].z,
                 lo_z = c->slices[static_cast<size_t>(lo)].z;
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                    [&](int r) {
                                      const double z = c->points(r, 2);
                                      return level > 0 ? std::abs(z - level) > 15
                                                       : z > hi_z || z < lo_z - 0.5 * c->step;
                                    }),
                     candidates.end());
    int best = c->SmoothExtreme(candidates, dir, 10, 4);
    if (best < 0) {
      c->Missing(name, "no chest points below the armpit");
      continue;
    }
    // No breast, and the front still grows at the window's foot: a belly
    // below a flat chest. The nipple then lies 3 % of stature under the
    // armpit (adult anthropometry: bust height ~72 %, axilla ~75 %).
    std::string method = level > 0 ? "breast_front_max" : "front_max_below_armpit";
    if (level < 0 && c->points(best, 2) < lo_z + 4 * c->step) {
      const double z0 = arm.armpit_z - 0.03 * h;
      std::vector<int> chest;
      for (int r : candidates)
        if (std::abs(c->points(r, 2) - z0) <= 15) chest.push_back(r);
      const int flat = c->SmoothExtreme(chest, dir, 10, 4);
      if (flat >= 0) best = flat, method = "proportion_above_belly";
    }
    c->Put(name, c->P(best), method == "breast_front_max" ? 0.8 : 0.5, method);
  }
}

// The trunk's rows of slice `s` with, above the crotch, those the structure
// gives a leg. A leg's part is the nodes nearer its foot than the crotch is,
// and on a wide pelvis that can reach above the crotch up the hip's side (an
// obese body's whole left hip side 31 mm above the crotch: its hip point
// was placed 75 mm inside). Above the crotch the legs have joined and the
// section is the pelvis's; arms stay out.
std::vector<int> PelvisRows(const Context& c, const Slice& s) {
  if (!c.structure.ok || s.z <= c.crotch_z) return c.TrunkRows(s);
  std::vector<int> rows;
  for (int r : s.rows)
    if (TrunkOrLeg(c.PartOf(r))) rows.push_back(r);
  return rows;
}

}  // namespace

void FindTrunkLevels(Context* c) {
  const double h = c->crown_z;
  Bust(c);
  const double under_z = FindUnderBust(c);
  // Hip (seat) level: the most backward point of the buttocks, between the
  // crotch and 10 % of stature under the under-bust level, at least 10 % of
  // stature above the crotch (an under-bust found low on a big belly).
  const double top =
      std::max(under_z > 0 ? under_z - 0.1 * h : c->crotch_z + 0.15 * h, c->crotch_z + 0.1 * h);
  const double hip_z = HipLevel(*c, top);
  // Waist: the natural waist, the smallest convex-hull girth of the trunk
  // between the iliac crest and the lowest rib, placed at 30 % and 85 % of
  // the hip-to-under-bust height (the oracle's truth uses the same band).
  // A girth that keeps falling to the band's top (no narrowing, common on
  // men and on a belly) leaves the waist at the top: the lowest rib.
  double waist_z = -1, waist_confidence = 0.8;
  std::string waist_method = "min_hull_girth";
  const double span = under_z - hip_z;
  if (under_z > 0 && span > 0.05 * h) {
    const double waist_lo = hip_z + 0.3 * span, waist_top = hip_z + 0.85 * span;
    // The girth profile on the band's slices (and three beyond each end,
    // for the fit): the narrowest slice in the band, then the vertex of the
    // profile's parabola around it (profile_extreme.h).
    std::vector<double> at, girth;
    std::vector<bool> in_band;
    for (double z = waist_lo - 3 * c->step; z <= waist_top + 3 * c->step; z += c->step) {
      const Slice& slice = c->At(z);
      const std::vector<int> rows = c->TrunkRows(slice);
      at.push_back(slice.z);
      girth.push_back(rows.size() < 20 ? kNaN : HullPerimeter(c->points, rows));
      in_band.push_back(z >= waist_lo && z <= waist_top);
    }
    const size_t best = BestSample({}, girth, in_band);
    if (best < at.size()) waist_z = at[best];
    if (waist_z > waist_top - 2 * c->step) {
      waist_confidence = 0.5, waist_method = "band_top_no_narrowing";
    } else if (waist_z > 0) {
      waist_z = ProfileExtreme({}, at, girth, best);
    }
  }
  if (waist_z < 0) {
    // No under-bust (or one found below the hip's reach): the waist from
    // trunk proportions, the crotch-to-shoulder height split 0.455 : 0.545,
    // the shoulder taken 7.8 % of stature above the armpit.
    double armpit_z = 0;
    for (const ArmInfo& arm : c->arm) armpit_z = std::max(armpit_z, arm.found ? arm.armpit_z : 0.0);
    waist_z = armpit_z > 0 ? c->crotch_z + 0.455 * (armpit_z + 0.078 * h - c->crotch_z)
                           : hip_z + 0.15 * h;
    waist_confidence = 0.5, waist_method = "proportion_no_under_bust";
  }
  PutSeam(c, "hip_back", hip_z, false, 0.85, "back_min_y");
  PutSeam(c, "front_waist", waist_z, true, waist_confidence, waist_method);
  PutSeam(c, "back_waist", waist_z, false, waist_confidence, waist_method);
  PutSeam(c, "middle_hip_front", 0.5 * (hip_z + waist_z), true, 0.8, "midway_waist_hip");
  for (const auto& [name, z] : {std::pair{"side_waist", waist_z}, std::pair{"hip", hip_z}}) {
    const std::vector<int> rows = PelvisRows(*c, c->At(z));
    for (int sign : {+1, -1}) {
      const int side = c->SmoothExtreme(rows, Eigen::Vector3d(sign, 0, 0), 10, 3);
      if (side < 0) {
        c->Missing(std::string(name) + Side(sign), "empty trunk section");
        continue;
      }
      Eigen::Vector3d p = c->P(side);
      p.z() = z;
      c->Put(std::string(name) + Side(sign), p, z == hip_z ? 0.85 : waist_confidence,
             "section_side_extreme");
    }
  }
}

}  // namespace bespoke::landmarks
