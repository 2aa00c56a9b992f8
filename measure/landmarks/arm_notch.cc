// The notch between an arm and the trunk in a section (arm_notch.h).
#include "measure/landmarks/arm_notch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bespoke::landmarks {
namespace {

struct Bin {
  int count = 0;
  double y_min = std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
};

// The section's points on side `sign` in bins of x' = sign * x from 0.
std::vector<Bin> DepthBins(const ArmNotchOptions& o, const Eigen::MatrixX3d& points,
                           const std::vector<int>& rows, int sign) {
  std::vector<Bin> bins;
  for (int r : rows) {
    const double x = sign * points(r, 0);
    if (x < 0) continue;
    const size_t b = static_cast<size_t>(x / o.bin_mm);
    if (bins.size() <= b) bins.resize(b + 1);
    Bin& bin = bins[b];
    ++bin.count;
    bin.y_min = std::min(bin.y_min, points(r, 1));
    bin.y_max = std::max(bin.y_max, points(r, 1));
  }
  return bins;
}

// Mean y of `rows` at or beyond x' = `from_mm` on side `sign`; 0 if none.
double MeanYBeyond(const Eigen::MatrixX3d& points, const std::vector<int>& rows, int sign,
                   double from_mm) {
  double sum = 0;
  int count = 0;
  for (int r : rows)
    if (sign * points(r, 0) >= from_mm) sum += points(r, 1), ++count;
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

ArmNotch FindArmNotch(const ArmNotchOptions& o, const Eigen::MatrixX3d& points,
                      const std::vector<int>& rows, int sign) {
  const std::vector<Bin> bins = DepthBins(o, points, rows, sign);
  const size_t n = bins.size();
  std::vector<double> depth(n, std::numeric_limits<double>::quiet_NaN());
  for (size_t i = 0; i < n; ++i)
    if (bins[i].count >= o.min_bin_points) depth[i] = bins[i].y_max - bins[i].y_min;
  // The deepest bin inside each bin (the trunk) and outside it (the lobe).
  std::vector<double> inside(n + 1, 0), outside(n + 1, 0);
  std::vector<size_t> deepest_outside(n + 1, n);
  for (size_t i = 0; i < n; ++i)
    inside[i + 1] = std::max(inside[i], std::isfinite(depth[i]) ? depth[i] : 0.0);
  for (size_t i = n; i-- > 0;) {
    outside[i] = outside[i + 1], deepest_outside[i] = deepest_outside[i + 1];
    if (std::isfinite(depth[i]) && depth[i] > outside[i])
      outside[i] = depth[i], deepest_outside[i] = i;
  }
  ArmNotch notch;
  for (size_t i = n / 3; i + 1 < n; ++i) {
    if (!std::isfinite(depth[i])) continue;
    const double lobe = outside[i + 1];
    if (lobe < o.min_lobe_depth_mm) continue;
    // A notch reaches into the middle half of the lobe's depth: the crease
    // between a resting arm and the trunk runs deep, in front and behind,
    // and where the contact itself is unseen a bin may hold only the front
    // crease's or the back one's points. A bin holding only the front's or
    // the back's outline (the other side unseen: a hole, a sparse scan's
    // thin slice) is shallow too, but lies out at the lobe's front or back.
    const Bin& arm = bins[deepest_outside[i + 1]];
    const double arm_mid_y = 0.5 * (arm.y_min + arm.y_max), reach = 0.25 * lobe;
    if (bins[i].y_min > arm_mid_y + reach || bins[i].y_max < arm_mid_y - reach) continue;
    const double ratio = depth[i] / std::min(inside[i], lobe);
    if (ratio < notch.ratio) {
      notch.ratio = ratio;
      notch.x_mm = sign * (static_cast<double>(i) + 0.5) * o.bin_mm;
      notch.y_mm = 0.5 * (bins[i].y_min + bins[i].y_max);
    }
  }
  notch.found = notch.ratio < o.max_ratio;
  notch.lobe_y_mm = MeanYBeyond(points, rows, sign, sign * notch.x_mm + 0.5 * o.bin_mm);
  return notch;
}

}  // namespace bespoke::landmarks
