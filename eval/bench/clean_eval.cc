// Evidence run: the cleaning chain on many virtual scans against their truth.
//
//   build/eval/bench/clean_eval [--subjects N] [--seed S] [--no-floor] [--stray N]
//                            [--width W --height H] [--misalign-deg D]
//                            [--makehuman ../shared/data/bodies/makehuman]
//
// For each subject i: a parametric (or MakeHuman) body drawn from seed S*1000+i+1, scanned
// by the simulated booth (oracle/scan_sim) in a random rigid pose, then
// CleanScan with the default options. Prints one row per subject (pose
// errors against the truth's scanner_from_body, points, time, flags) and a
// summary (median and worst). Exit code 0 always; it is a report, not a test
// (the tests keep a small version: scanners/clean/clean_oracle_test.cc).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "scanners/clean/clean.h"

namespace bespoke {
namespace {

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

int Run(int argc, char** argv) {
  CLI::App app{"The cleaning chain on virtual scans of generated bodies, against their truth"};
  int subjects = 10, stray = 0, width = 160, height = 120;
  unsigned seed = 1;
  bool no_floor = false;
  double misalign_deg = 0;
  std::string makehuman;
  app.add_option("--subjects", subjects, "Number of subjects")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the set")->capture_default_str();
  app.add_flag("--no-floor", no_floor, "Scan without a floor patch");
  app.add_option("--stray", stray, "Stray poles and boxes in the booth")->capture_default_str();
  app.add_option("--width", width, "Depth image width per sensor")->capture_default_str();
  app.add_option("--height", height, "Depth image height per sensor")->capture_default_str();
  app.add_option("--misalign-deg", misalign_deg, "Per-sensor calibration error SD, degrees");
  app.add_option("--makehuman", makehuman, "MakeHuman data folder: MakeHuman bodies instead");
  CLI11_PARSE(app, argc, argv);
  std::unique_ptr<MakeHumanModel> model;
  if (!makehuman.empty()) model = std::make_unique<MakeHumanModel>(makehuman);

  std::vector<double> up, facing, lateral, along, vertical, times;
  int front_wrong = 0;
  std::printf("%4s %8s %8s %8s %8s %8s %8s %8s %7s %7s %7s  %s\n", "subj", "points", "up_deg",
              "face_deg", "x_mm", "y_mm", "z_mm", "clean_s", "front", "foot_mm", "nose_mm",
              "flags");
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
      body = GenerateParametricBody(options);
    }
    ScanSimOptions sim;
    sim.seed = subject_seed;
    sim.transform = ScanTransform::kRandom;
    sim.floor = !no_floor;
    sim.stray_objects = stray;
    sim.misalign_deg = misalign_deg;
    sim.booth.width_px = width;
    sim.booth.height_px = height;
    const ScanSimResult scan = SimulateScan(sim, body.mesh);

    const auto start = std::chrono::steady_clock::now();
    const CleanResult result = CleanScan(CleanOptions{}, scan.cloud);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Eigen::Matrix3d truth = scan.scanner_from_body.linear().transpose();
    const Eigen::Matrix3d est = result.body_from_scanner.linear();
    const Eigen::Vector3d origin = result.body_from_scanner * scan.scanner_from_body.translation();
    const double face = AngleDeg(est.row(1), truth.row(1));
    std::string flags;
    for (const std::string& f : result.flags) flags += f + " ";
    std::printf("%4d %8lld %8.3f %8.3f %8.1f %8.1f %8.1f %8.3f %7s %7.1f %7.1f  %s\n", i,
                static_cast<long long>(scan.cloud.size()), AngleDeg(est.row(2), truth.row(2)), face,
                origin.x(), origin.y(), origin.z(), seconds, result.frame.front_source.c_str(),
                result.frame.foot_offset_mm, result.frame.nose_cue_mm, flags.c_str());
    std::fflush(stdout);
    up.push_back(AngleDeg(est.row(2), truth.row(2)));
    facing.push_back(face);
    front_wrong += face > 90;
    lateral.push_back(std::abs(origin.x()));
    along.push_back(std::abs(origin.y()));
    vertical.push_back(std::abs(origin.z()));
    times.push_back(seconds);
  }
  auto worst = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  std::printf(
      "\nmedian / worst: up %.3f / %.3f deg, facing %.3f / %.3f deg, |x| %.1f / %.1f mm, "
      "|y| %.1f / %.1f mm, |z| %.1f / %.1f mm, clean %.3f / %.3f s; front wrong %d of %d\n",
      Median(up), worst(up), Median(facing), worst(facing), Median(lateral), worst(lateral),
      Median(along), worst(along), Median(vertical), worst(vertical), Median(times), worst(times),
      front_wrong, subjects);
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("clean_eval", bespoke::Run, argc, argv);
}
