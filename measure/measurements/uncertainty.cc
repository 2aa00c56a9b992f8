#include "measure/measurements/uncertainty.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Typical 3-D error (mm, median) of each landmark kind on the oracle's
// MakeHuman and parametric virtual scans, both sides pooled, as
// uncertainty_eval prints it on the calibration set (docs/measuring.md,
// "Uncertainty", has the run). The back neck takes the MakeHuman median
// alone: the parametric body's truth there is its construction's point, not
// the catalogue's (docs/landmarks.md, "Where the truth comes from").
const std::map<std::string, double>& TypicalError() {
  static const std::map<std::string, double> table = {
      {"crown", 3.5},         {"back_neck", 14.1},
      {"front_neck", 5.6},    {"side_neck", 21.3},
      {"shoulder", 5.4},      {"axilla_front", 6.6},
      {"axilla_back", 5.6},   {"armpit", 11.8},
      {"bust", 7.5},          {"under_bust", 4.3},
      {"front_waist", 5.1},   {"back_waist", 4.5},
      {"side_waist", 6.7},    {"middle_hip_front", 3.6},
      {"hip_back", 5.5},      {"hip", 6.1},
      {"crotch", 5.2},        {"upper_arm", 7.8},
      {"elbow", 11.6},        {"wrist", 8.3},
      {"thigh", 2.4},         {"knee", 5.4},
      {"calf", 3.2},          {"ankle_inside", 16.9},
      {"ankle_outside", 6.8},
  };
  return table;
}

}  // namespace

void UncertaintyOptions::Check() const {
  if (!(scale > 0) || !(bridge_share >= 0) || !(noise_factor >= 0) || !(spacing_factor >= 0))
    throw InputError("uncertainty: scale must be > 0 and the factors >= 0");
}

double LandmarkSigma(const std::string& name, const Landmark& landmark, double scale) {
  if (std::find(landmark.flags.begin(), landmark.flags.end(), "override") != landmark.flags.end())
    return 1.0;
  const auto& table = TypicalError();
  const auto it = table.find(UnsidedLandmarkName(name));
  // The median of the 3-D distance of an isotropic Gaussian is 1.54 SDs per axis.
  const double sd = (it == table.end() ? 20.0 : it->second) / 1.54;
  double sigma = sd * 0.8 / std::max(landmark.confidence, 0.1);
  if (!landmark.flags.empty()) sigma *= 2;
  return scale * sigma;
}

double ScanNoise(const PointIndex& index, double* spacing_mm, double* surface_spacing_mm,
                 int samples) {
  *spacing_mm = index.MedianSpacing();
  if (surface_spacing_mm) *surface_spacing_mm = 0;
  const Eigen::Index n = index.size();
  if (n < 32) return 0;
  const Eigen::Index step = std::max<Eigen::Index>(1, n / samples);
  std::vector<int> near;
  std::vector<double> d2, area_per_point;
  double sum = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < n; i += step) {
    index.Knn(index.point(i), 16, &near, &d2);
    area_per_point.push_back(kPi * d2.back() / 15);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int k : near) mean += index.point(k);
    mean /= static_cast<double>(near.size());
    for (int k : near) cov += (index.point(k) - mean) * (index.point(k) - mean).transpose();
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues()(0);
    sum += std::max(smallest, 0.0) / static_cast<double>(near.size()), ++count;
  }
  if (surface_spacing_mm && !area_per_point.empty()) {
    auto middle = area_per_point.begin() + static_cast<std::ptrdiff_t>(area_per_point.size() / 2);
    std::nth_element(area_per_point.begin(), middle, area_per_point.end());
    *surface_spacing_mm = std::sqrt(*middle);
  }
  return count > 0 ? std::sqrt(sum / count) : 0;
}

double Uncertainty95(const UncertaintyOptions& o, double landmark_sd_mm, double noise_mm,
                     double spacing_mm, double bridged_mm) {
  const double scan = o.noise_factor * noise_mm + o.spacing_factor * spacing_mm;
  const double bridge = o.bridge_share * bridged_mm;
  return 1.96 * std::sqrt(landmark_sd_mm * landmark_sd_mm + scan * scan + bridge * bridge);
}

}  // namespace bespoke
