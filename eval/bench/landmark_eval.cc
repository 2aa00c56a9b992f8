// Evidence run: the landmark detector on virtual scans against the truth.
//
//   build/eval/bench/landmark_eval [--subjects N] [--seed S] [--arm-deg A]
//                               [--makehuman ../shared/data/bodies/makehuman]
//                               [--noise MM] [--width W --height H] [--verbose]
//
// For each subject i: a parametric body (arm abduction A deg) or a MakeHuman
// body drawn from seed S*1000+i+1, scanned by the simulated booth in a random
// rigid pose (oracle/scan_sim), cleaned (scanners/clean), then
// DetectLandmarks. Prints per landmark the median, mean and max 3-D error
// and the median height error (mm) against the body's exact datum points
// mapped into the cleaned frame, how often it was placed, and the detection
// time. A report, not a test (exit code 0; the tests keep a small version:
// measure/landmarks/landmarks_test.cc).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "measure/landmarks/landmarks.h"
#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/scan_sim/scanned_body.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
double Mean(const std::vector<double>& v) {
  return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}
double Max(const std::vector<double>& v) {
  return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

int Run(int argc, char** argv) {
  CLI::App app{"The landmark detector on virtual scans of generated bodies, against their truth"};
  int subjects = 5, width = 160, height = 120;
  unsigned seed = 1;
  double arm_deg = 30, noise = 1.0;
  bool verbose = false;
  std::string makehuman;
  app.add_option("--subjects", subjects, "Number of subjects")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the set")->capture_default_str();
  app.add_option("--arm-deg", arm_deg, "Parametric bodies: arm abduction (deg)")
      ->capture_default_str();
  app.add_option("--noise", noise, "Range noise SD (mm)")->capture_default_str();
  app.add_option("--width", width, "Depth image width per sensor")->capture_default_str();
  app.add_option("--height", height, "Depth image height per sensor")->capture_default_str();
  app.add_option("--makehuman", makehuman, "MakeHuman data folder: MakeHuman bodies instead");
  app.add_flag("--verbose", verbose, "Print every landmark's error per subject");
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<MakeHumanModel> model;
  if (!makehuman.empty()) model = std::make_unique<MakeHumanModel>(makehuman);
  std::map<std::string, std::vector<double>> err, dz;
  std::map<std::string, int> missing;
  std::vector<double> times, points, all;
  for (int i = 0; i < subjects; ++i) {
    const std::uint64_t subject_seed =
        static_cast<std::uint64_t>(seed) * 1000 + static_cast<std::uint64_t>(i) + 1;
    Body body;
    if (model) {
      MakeHumanBodyOptions options;
      options.seed = subject_seed;
      body = GenerateMakeHumanBody(options, model.get());
    } else {
      ParametricBodyOptions options;
      options.seed = subject_seed;
      options.arm_abduction_deg = arm_deg;
      body = GenerateParametricBody(options);
    }
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = subject_seed;
    scan_options.width_px = width;
    scan_options.height_px = height;
    scan_options.noise_sigma_mm = noise;
    const testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
    const auto start = std::chrono::steady_clock::now();
    LandmarkSet set;
    try {
      set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    } catch (const Error& e) {
      std::printf("subject %d: %s\n", i, e.what());
      continue;
    }
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    points.push_back(static_cast<double>(scan.cloud.size()));
    for (const auto& [name, truth] : scan.truth) {
      if (!set.Has(name)) {
        ++missing[name];
        if (verbose)
          std::printf("subject %d %-22s missing: %s\n", i, name.c_str(),
                      set.missing.count(name) ? set.missing.at(name).c_str() : "?");
        continue;
      }
      const Landmark& l = set.At(name);
      const Eigen::Vector3d d = l.position_mm - truth;
      err[name].push_back(d.norm());
      dz[name].push_back(std::abs(d.z()));
      all.push_back(d.norm());
      if (verbose) {
        std::printf("truth z %.1f y %.1f  ", truth.z(), truth.y());
        std::printf("subject %d %-22s err %6.1f  d(%6.1f %6.1f %6.1f)  conf %.2f %s\n", i,
                    name.c_str(), d.norm(), d.x(), d.y(), d.z(), l.confidence, l.method.c_str());
      }
    }
  }
  std::printf("\n%-22s %6s %8s %8s %8s %8s %7s\n", "landmark", "found", "med_mm", "mean_mm",
              "max_mm", "med_dz", "missing");
  for (const auto& [name, e] : err) {
    std::printf("%-22s %6zu %8.1f %8.1f %8.1f %8.1f %7d\n", name.c_str(), e.size(), Median(e),
                Mean(e), Max(e), Median(dz[name]), missing[name]);
  }
  for (const auto& [name, count] : missing) {
    if (!err.count(name))
      std::printf("%-22s %6d %8s %8s %8s %8s %7d\n", name.c_str(), 0, "-", "-", "-", "-", count);
  }
  std::printf(
      "\nall landmarks: median %.1f mm, mean %.1f mm over %zu placements; %s bodies, %d subjects, "
      "noise %.1f mm\n",
      Median(all), Mean(all), all.size(), model ? "MakeHuman" : "parametric", subjects, noise);
  std::printf("detection: median %.3f s, max %.3f s for median %.0f points\n", Median(times),
              Max(times), Median(points));
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("landmark_eval", bespoke::Run, argc, argv);
}
