// Crown, crotch and the trunk levels: bust, under-bust, waist, middle hip,
// hip (docs/landmarks.md has the definitions and why).
#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/landmarks/landmark_context.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {

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

void PutSeam(Context* c, const std::string& name, double z, bool front, double confidence,
             const std::string& method) {
  Eigen::Vector3d p;
  if (!SeamPoint(*c, z, front, &p)) {
    c->Missing(name, "no scan points on the centre line near z = " +
                         std::to_string(static_cast<int>(z)) + " mm");
    return;
  }
  c->Put(name, p, confidence, method);
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
  // Crotch level: the lowest slice (above 30 % of stature) with one trunk
  // piece spanning x = 0 from side to side; below it the legs are two
  // pieces. A hole under the crotch leaves the front and back walls of the
  // pelvis ring, which still span x = 0, so the level survives it.
  double level = -1;
  for (const Slice& s : c->slices) {
    if (s.z < 0.3 * h || s.z > 0.65 * h) continue;
    for (const Piece& p : s.pieces) {
      if (p.lo.x() < -40 && p.hi.x() > 40 && p.rows.size() > 20) {
        bool crosses = false;
        for (int r : p.rows) crosses |= std::abs(c->points(r, 0)) < 10;
        if (crosses) {
          level = s.z;
          break;
        }
      }
    }
    if (level > 0) break;
  }
  if (level < 0)
    throw InputError("landmarks: no legs found (the trunk never splits into two legs)");
  // The crotch point: the lowest centre-line point near that level.
  int best = -1;
  for (int s = SliceAt(c->slices, level - 40); s <= SliceAt(c->slices, level + 10); ++s) {
    for (int r : c->slices[static_cast<size_t>(s)].rows) {
      if (std::abs(c->points(r, 0)) < 10 && (best < 0 || c->points(r, 2) < c->points(best, 2)))
        best = r;
    }
  }
  if (best >= 0 && c->points(best, 2) > level - 40) {
    // The bottom of the crotch is a ridge running front to back: its middle
    // (median y of the centre-line points within 8 mm of the lowest). The
    // noise-averaged lowest point instead was tried: worse on MakeHuman
    // bodies (mean 35 -> 46 mm), whose crotch ridge is nearly flat.
    std::vector<double> ys;
    for (int s = SliceAt(c->slices, level - 40); s <= SliceAt(c->slices, level + 10); ++s) {
      for (int r : c->slices[static_cast<size_t>(s)].rows) {
        if (std::abs(c->points(r, 0)) < 10 && c->points(r, 2) < c->points(best, 2) + 8)
          ys.push_back(c->points(r, 1));
      }
    }
    std::nth_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(ys.size() / 2), ys.end());
    c->crotch_z = c->points(best, 2);
    c->Put("crotch", Eigen::Vector3d(0, ys[ys.size() / 2], c->crotch_z), 0.7,
           "legs_join_lowest_centre_point");
  } else {
    // Nothing on the centre line: a hole under the crotch.
    const Slice& s = c->At(level);
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const Piece& p : s.pieces)
      if (p.lo.x() < -40 && p.hi.x() > 40) centre = p.centroid;
    c->crotch_z = level - 0.5 * c->step;
    c->Put("crotch", Eigen::Vector3d(0, centre.y(), c->crotch_z), 0.5, "legs_join_level",
           {"in_hole"});
  }
}

namespace {

// The bust points: the most forward trunk point on each side between 2 %
// and 10 % of stature below the armpit, between 30 % and 100 % of the
// armpit's distance from the centre line.
void Bust(Context* c, double* bust_z) {
  const double h = c->crown_z;
  for (int sign : {+1, -1}) {
    const std::string name = "bust" + Side(sign);
    const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
    if (!arm.found) {
      c->Missing(name, "the armpit was not found");
      continue;
    }
    const double ax = sign * arm.armpit.x();
    std::vector<int> candidates;
    for (int s = SliceAt(c->slices, arm.armpit_z - 0.10 * h);
         s <= SliceAt(c->slices, arm.armpit_z - 0.02 * h); ++s) {
      for (int r : c->TrunkRows(c->slices[static_cast<size_t>(s)])) {
        const double x = sign * c->points(r, 0);
        if (x > 0.3 * ax && x < ax) candidates.push_back(r);
      }
    }
    // Breasts point forward and a little outward: the extreme along a
    // direction turned ~11 deg out from straight ahead.
    const int best =
        c->SmoothExtreme(candidates, Eigen::Vector3d(sign * 0.2, 1, 0).normalized(), 10, 4);
    if (best < 0) {
      c->Missing(name, "no chest points below the armpit");
      continue;
    }
    c->Put(name, c->P(best), 0.8, "front_max_below_armpit");
    if (sign > 0) *bust_z = c->points(best, 2);
  }
}

// Most forward y of the trunk within 8 mm of x = x0 in the slice at z.
double FrontAt(const Context& c, double z, double x0) {
  double best = -kInf;
  for (int r : c.TrunkRows(c.At(z))) {
    if (std::abs(c.points(r, 0) - x0) < 8) best = std::max(best, c.points(r, 1));
  }
  return best;
}

}  // namespace

void FindTrunkLevels(Context* c) {
  const double h = c->crown_z;
  double bust_z = -1;
  Bust(c, &bust_z);
  // Under-bust: on the vertical through the bust point, the front profile
  // bends most sharply (largest second difference over +-10 mm) where the
  // breast's underside meets the chest wall; searched 1-8 % of stature below.
  double under_z = -1;
  if (c->Has("bust_right") || c->Has("bust_left")) {
    const Eigen::Vector3d bust = c->Has("bust_right") ? c->Pos("bust_right") : c->Pos("bust_left");
    double best_bend = -kInf;
    for (double z = bust.z() - 0.08 * h; z < bust.z() - 0.01 * h; z += c->step) {
      const double bend = FrontAt(*c, z + 10, bust.x()) - 2 * FrontAt(*c, z, bust.x()) +
                          FrontAt(*c, z - 10, bust.x());
      if (std::isfinite(bend) && bend > best_bend) best_bend = bend, under_z = z;
    }
    // A flat chest (most men) has no clear fold: the noise's largest bend
    // wins, hence the lower confidence (docs/landmarks.md).
    if (under_z < 0) under_z = bust.z() - 0.04 * h;
    PutSeam(c, "under_bust", under_z, true, 0.6, "front_profile_bend");
  } else {
    c->Missing("under_bust", "needs the bust point");
  }
  // Hip (seat) level: the most backward point of the buttocks, between the
  // crotch and 10 % of stature under the under-bust level.
  const double top = under_z > 0 ? under_z - 0.1 * h : c->crotch_z + 0.15 * h;
  std::vector<int> behind;
  for (int s = SliceAt(c->slices, c->crotch_z); s <= SliceAt(c->slices, top); ++s) {
    for (int r : c->TrunkRows(c->slices[static_cast<size_t>(s)], 150)) {
      if (std::abs(c->points(r, 0)) < 150) behind.push_back(r);
    }
  }
  const int buttock = c->SmoothExtreme(behind, -Eigen::Vector3d::UnitY(), 15, 5);
  if (buttock < 0) throw InputError("landmarks: no buttocks found above the crotch");
  const double hip_z = c->points(buttock, 2);
  // Waist: the smallest convex-hull girth of the trunk between 3 % of
  // stature above the hip level and 2 % below the under-bust level.
  const double waist_top = under_z > 0 ? under_z - 0.02 * h : hip_z + 0.25 * h;
  double waist_z = -1, best = kInf;
  for (double z = hip_z + 0.03 * h; z <= waist_top; z += c->step) {
    const std::vector<int> rows = c->TrunkRows(c->At(z));
    if (rows.size() < 20) continue;
    const double girth = HullPerimeter(c->points, rows);
    if (girth < best) best = girth, waist_z = z;
  }
  if (waist_z < 0) throw InputError("landmarks: no waist found between the hip and the bust");
  // No narrowing (the girth keeps falling up to the chest, common on men):
  // the waist level from trunk proportions, the crotch-to-shoulder height
  // split 0.455 : 0.545, the shoulder taken 7.8 % of stature above the armpit.
  double waist_confidence = 0.8;
  std::string waist_method = "min_hull_girth";
  if (waist_z > waist_top - 2 * c->step) {
    double armpit_z = 0;
    for (const ArmInfo& arm : c->arm) armpit_z = std::max(armpit_z, arm.found ? arm.armpit_z : 0.0);
    if (armpit_z > 0) {
      waist_z = c->crotch_z + 0.455 * (armpit_z + 0.078 * h - c->crotch_z);
      waist_confidence = 0.5;
      waist_method = "proportion_no_narrowing";
    }
  }
  PutSeam(c, "hip_back", hip_z, false, 0.85, "back_min_y");
  PutSeam(c, "front_waist", waist_z, true, waist_confidence, waist_method);
  PutSeam(c, "back_waist", waist_z, false, waist_confidence, waist_method);
  PutSeam(c, "middle_hip_front", 0.5 * (hip_z + waist_z), true, 0.8, "midway_waist_hip");
  for (const auto& [name, z] : {std::pair{"side_waist", waist_z}, std::pair{"hip", hip_z}}) {
    const std::vector<int> rows = c->TrunkRows(c->At(z));
    for (int sign : {+1, -1}) {
      const int side = c->SmoothExtreme(rows, Eigen::Vector3d(sign, 0, 0), 10, 3);
      if (side < 0) {
        c->Missing(std::string(name) + Side(sign), "empty trunk section");
        continue;
      }
      Eigen::Vector3d p = c->P(side);
      p.z() = z;
      p.z() = z;
      c->Put(std::string(name) + Side(sign), p, z == hip_z ? 0.85 : waist_confidence,
             "section_side_extreme");
    }
  }
}

}  // namespace bespoke::landmarks
