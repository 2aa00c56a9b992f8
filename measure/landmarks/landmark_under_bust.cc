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

// The under-bust fold's smallest bend (second difference of the front
// profile over +-10 mm, mm): a slope change of 0.2 (11 deg), a visible
// corner; a chest whose sharpest bend is smaller is flat (no fold). The
// oracle's truth uses the same rule (oracle/truth/defined_landmarks.cc). On
// a scan the bend is noisy, so a flat chest can still show a fold here:
// docs/landmarks.md, known limits.
constexpr double kMinFoldBendMm = 2;

// Most forward y of the trunk within 8 mm of x = x0 in the slice at z.
double FrontAt(const Context& c, double z, double x0) {
  double best = -kInf;
  for (int r : c.TrunkRows(c.At(z))) {
    if (std::abs(c.points(r, 0) - x0) < 8) best = std::max(best, c.points(r, 1));
  }
  return best;
}

// The fold on the bend profile (bends[k] at heights at[k], `inside` the
// search window): going down, the first local peak that reaches half the
// window's sharpest bend (a flat chest's pectoral edge is a weak fold, and a
// belly's top lower down can bend more), then the vertex of the profile's
// parabola around it (profile_extreme.h), off the slice grid. Above the fold
// the breast's front is convex (negative bend), so nothing there competes.
// -1 when the sharpest bend is under kMinFoldBendMm (a flat chest).
double FoldOnBends(const std::vector<double>& at, const std::vector<double>& bends,
                   const std::vector<bool>& inside) {
  double sharpest = -kInf;
  for (size_t k = 0; k < at.size(); ++k)
    if (inside[k] && std::isfinite(bends[k])) sharpest = std::max(sharpest, bends[k]);
  if (!(sharpest >= kMinFoldBendMm)) return -1;
  for (size_t k = at.size() - 1; k-- > 1;) {
    if (inside[k] && bends[k] >= 0.5 * sharpest && !(bends[k - 1] > bends[k]) &&
        !(bends[k + 1] > bends[k])) {
      ProfileExtremeOptions peak;
      peak.minimum = false;
      peak.half_window = 2;
      return ProfileExtreme(peak, at, bends, k);
    }
  }
  return -1;
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
  // the lower confidence; with no bend of kMinFoldBendMm, 4 % of stature
  // under the bust point (docs/landmarks.md).
  double under_z = FoldOnBends(at, bends, inside);
  if (under_z < 0) under_z = bust.z() - 0.04 * h;
  PutSeam(c, "under_bust", under_z, true, 0.6, "front_profile_bend");
  return under_z;
}

}  // namespace bespoke::landmarks
