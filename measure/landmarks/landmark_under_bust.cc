// The under-bust: the fold under the breast on the bust points' verticals
// (docs/landmarks.md, step 5, has the definition and why).
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "measure/landmarks/landmark_context.h"
#include "measure/landmarks/profile_extreme.h"

namespace bespoke::landmarks {
namespace {

// The fold's weight in the under-bust's level by its strength (FoldOnBends):
// none under kNoFoldBendMm (a slope change of 0.1, 6 deg: a flat chest,
// whose level is kNoFoldDrop of stature under the bust point), all over
// kFoldBendMm (0.3, 17 deg: a visible fold), in proportion between. A single
// threshold would move the level the whole way from the fold to the flat
// chest's for a bend read 0.1 mm flatter on a scan than on the mesh. The
// oracle's truth uses the same rule (oracle/truth/defined_landmarks.cc).
constexpr double kNoFoldBendMm = 1, kFoldBendMm = 3, kNoFoldDrop = 0.04;

double FoldWeight(double strength_mm) {
  return std::clamp((strength_mm - kNoFoldBendMm) / (kFoldBendMm - kNoFoldBendMm), 0.0, 1.0);
}

// The plane y = a + b (z' - z) + c (x' - x0) through the points `rows` by
// least squares: (a, b, c), a in mm.
Eigen::Vector3d FitFrontPlane(const Context& c, const std::vector<int>& rows, double z, double x0) {
  Eigen::MatrixX3d a(static_cast<Eigen::Index>(rows.size()), 3);
  Eigen::VectorXd y(a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const int r = rows[static_cast<size_t>(i)];
    a.row(i) << 1, c.points(r, 2) - z, c.points(r, 0) - x0;
    y(i) = c.points(r, 1);
  }
  return a.colPivHouseholderQr().solve(y);
}

// The trunk's front (largest y) on the vertical x = x0 at the plane of the
// slice at z: a plane (FitFrontPlane) fitted to the slice's trunk points
// within 8 mm of x0 and 25 mm of the foremost, points more than 4 mm behind
// it dropped and the plane refitted (at most three times: the chest wall
// under an overhanging breast), its value at x0, kept within the fitted
// points' range of y (a few points in a thin band of z fix the slopes
// badly: a 60k-point scan holds 0-6 points here). The foremost point alone
// depends on which points the slice happens to hold: on a breast's steep
// underside it moves a few mm from slice to slice, and the fold's second
// difference had noise peaks over the fold's own. With fewer than 4 points
// the foremost; -inf with none.
double FrontAt(const Context& c, double z, double x0) {
  const Slice& slice = c.At(z);
  std::vector<int> rows;
  double top = -kInf;
  for (int r : c.TrunkRows(slice)) {
    if (std::abs(c.points(r, 0) - x0) >= 8) continue;
    rows.push_back(r);
    top = std::max(top, c.points(r, 1));
  }
  const auto far_behind = [&](int r) { return c.points(r, 1) < top - 25; };
  rows.erase(std::remove_if(rows.begin(), rows.end(), far_behind), rows.end());
  double front = top, lowest = top;
  for (int r : rows) lowest = std::min(lowest, c.points(r, 1));
  for (int pass = 0; pass < 3 && rows.size() >= 4; ++pass) {
    const Eigen::Vector3d plane = FitFrontPlane(c, rows, slice.z, x0);
    front = plane(0);
    const auto behind = [&](int r) {
      const Eigen::Vector3d at(1, c.points(r, 2) - slice.z, c.points(r, 0) - x0);
      return c.points(r, 1) - plane.dot(at) < -4;
    };
    const size_t before = rows.size();
    rows.erase(std::remove_if(rows.begin(), rows.end(), behind), rows.end());
    if (rows.size() == before) break;
  }
  return std::clamp(front, lowest, top);
}

// The fold on the bend profile (bends[k] at heights at[k], `inside` the
// search window, with samples beyond both ends): going down, the first
// local peak that reaches half the window's sharpest bend (a flat chest's
// pectoral edge is a weak fold, and a belly's top lower down can bend
// more), then the vertex of the profile's parabola around it
// (profile_extreme.h), off the slice grid. Above the fold the breast's front
// is convex (negative bend), so nothing there competes. Its level (-1 when
// no bend in the window is positive), the window's sharpest bend and its
// strength: the sharpest of the bends averaged over three slices (+-5 mm at
// the default step), as the truth's; the largest of a row of single noisy
// bends reads a flat front sharper than it is.
struct Fold {
  double level_mm = -1;
  double sharpest_mm = 0;
  double strength_mm = 0;
};
Fold FoldOnBends(const std::vector<double>& at, const std::vector<double>& bends,
                 const std::vector<bool>& inside) {
  Fold fold;
  const std::vector<double> mean = WindowMean(bends, 1, 3);
  for (size_t k = 0; k < at.size(); ++k) {
    if (!inside[k]) continue;
    if (std::isfinite(bends[k])) fold.sharpest_mm = std::max(fold.sharpest_mm, bends[k]);
    if (std::isfinite(mean[k])) fold.strength_mm = std::max(fold.strength_mm, mean[k]);
  }
  if (!(fold.sharpest_mm > 0)) return fold;
  for (size_t k = at.size() - 1; k-- > 1;) {
    // The window's top sample is a peak when the bend still rises above it:
    // the window hangs from the found bust point, and where that lies low
    // (a bust point placed by proportion) the fold can sit at its top.
    const bool rising_out = !inside[k + 1];
    if (inside[k] && bends[k] >= 0.5 * fold.sharpest_mm && !(bends[k - 1] > bends[k]) &&
        (rising_out || !(bends[k + 1] > bends[k]))) {
      ProfileExtremeOptions peak;
      peak.minimum = false;
      peak.half_window = 2;
      fold.level_mm = ProfileExtreme(peak, at, bends, k);
      break;
    }
  }
  return fold;
}

}  // namespace

double FindUnderBust(Context* c) {
  if (!c->Has("bust_right") && !c->Has("bust_left")) {
    c->Missing("under_bust", "needs the bust point");
    return -1;
  }
  const double h = c->crown_z;
  const Eigen::Vector3d bust = c->Has("bust_right") ? c->Pos("bust_right") : c->Pos("bust_left");
  // The bend (second difference over +-10 mm) averaged over both breasts'
  // verticals where found: the range noise in one profile's second
  // difference rivals a small fold's bend.
  std::vector<double> xs;
  for (const char* name : {"bust_right", "bust_left"})
    if (c->Has(name)) xs.push_back(c->Pos(name).x());
  // FrontAt per vertical and slice, computed once: each slice serves
  // three stations' second differences.
  std::vector<std::map<int, double>> fronts(xs.size());
  const auto front = [&](size_t i, double z) {
    const int s = SliceAt(c->slices, z);
    auto it = fronts[i].find(s);
    if (it == fronts[i].end()) it = fronts[i].emplace(s, FrontAt(*c, z, xs[i])).first;
    return it->second;
  };
  std::vector<double> at, bends;
  std::vector<bool> inside;
  for (double z = bust.z() - 0.08 * h - 2 * c->step; z < bust.z() - 0.01 * h + 2 * c->step;
       z += c->step) {
    at.push_back(c->At(z).z);
    double sum = 0;
    for (size_t i = 0; i < xs.size(); ++i)
      sum += front(i, at.back() + 10) - 2 * front(i, at.back()) + front(i, at.back() - 10);
    bends.push_back(sum / static_cast<double>(xs.size()));
    inside.push_back(z >= bust.z() - 0.08 * h && z < bust.z() - 0.01 * h);
  }
  // A flat chest (most men) has a weak fold that noise can rival, hence
  // the lower confidence; the level moves from the fold to the flat chest's
  // as the fold weakens (FoldWeight, docs/landmarks.md).
  const Fold fold = FoldOnBends(at, bends, inside);
  const double flat = bust.z() - kNoFoldDrop * h;
  const double under_z =
      fold.level_mm < 0 ? flat : flat + FoldWeight(fold.strength_mm) * (fold.level_mm - flat);
  PutSeam(c, "under_bust", under_z, true, 0.6, "front_profile_bend");
  return under_z;
}

}  // namespace bespoke::landmarks
