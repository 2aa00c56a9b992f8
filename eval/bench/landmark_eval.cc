// Evidence run: the landmark detector on virtual scans against the truth.
//
//   build/eval/bench/landmark_eval [--subjects N] [--seed S] [--model parametric|makehuman]
//                               [--param name=value ...] [--noise MM]
//                               [--width W --height H] [--cache DIR] [--verbose]
//
// For each subject i: a body of the model drawn from seed S*1000+i+1 (the
// seeds of `bespoke accuracy` and `synth-set`; `--param` as there, e.g.
// arm_abduction_deg=15 or weight=1), scanned by the simulated booth in a
// random rigid pose (oracle/scan_sim; default the accuracy run's booth,
// 240 x 180 px per sensor), cleaned (scanners/clean), then DetectLandmarks.
// Prints per landmark the median, mean and max 3-D error, the median height
// error (mm) against the body's exact datum points mapped into the cleaned
// frame, how often it was placed or flagged, and the detection time.
// `--cache DIR` keeps each cleaned scan and its truth there (keyed by model,
// seed, parameters and booth) so reruns only detect. A report, not a test
// (exit code 0; the tests keep small versions beside the detector).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "measure/landmarks/body_structure.h"
#include "measure/landmarks/landmarks.h"
#include "oracle/scan_sim/scanned_body.h"
#include "oracle/synth/synth_body.h"
#include "scanners/core/errors.h"
#include "scanners/render/render.h"

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

// Raw little-endian dump of a cleaned scan (points, normals) and its truth.
void SaveScan(const std::filesystem::path& file, const testing::ScannedBody& scan) {
  std::ofstream out(file, std::ios::binary);
  const std::int64_t n = scan.cloud.size(), with_normals = scan.cloud.has_normals() ? 1 : 0;
  const std::int64_t landmarks = static_cast<std::int64_t>(scan.truth.size());
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(&with_normals), sizeof with_normals);
  out.write(reinterpret_cast<const char*>(&landmarks), sizeof landmarks);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p = scan.cloud.points;
  out.write(reinterpret_cast<const char*>(p.data()), static_cast<std::streamsize>(8 * 3 * n));
  if (with_normals) {
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> q = scan.cloud.normals;
    out.write(reinterpret_cast<const char*>(q.data()), static_cast<std::streamsize>(8 * 3 * n));
  }
  for (const auto& [name, x] : scan.truth) {
    const std::int64_t size = static_cast<std::int64_t>(name.size());
    out.write(reinterpret_cast<const char*>(&size), sizeof size);
    out.write(name.data(), static_cast<std::streamsize>(size));
    out.write(reinterpret_cast<const char*>(x.data()), 24);
  }
}

bool LoadScan(const std::filesystem::path& file, testing::ScannedBody* scan) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::int64_t n = 0, with_normals = 0, landmarks = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  in.read(reinterpret_cast<char*>(&with_normals), sizeof with_normals);
  in.read(reinterpret_cast<char*>(&landmarks), sizeof landmarks);
  if (!in || n <= 0 || n > 100000000 || landmarks < 0 || landmarks > 1000) return false;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p(n, 3);
  in.read(reinterpret_cast<char*>(p.data()), static_cast<std::streamsize>(8 * 3 * n));
  scan->cloud.points = p;
  if (with_normals) {
    in.read(reinterpret_cast<char*>(p.data()), static_cast<std::streamsize>(8 * 3 * n));
    scan->cloud.normals = p;
  }
  for (std::int64_t i = 0; i < landmarks; ++i) {
    std::int64_t size = 0;
    in.read(reinterpret_cast<char*>(&size), sizeof size);
    if (!in || size <= 0 || size > 200) return false;
    std::string name(static_cast<size_t>(size), ' ');
    in.read(name.data(), static_cast<std::streamsize>(size));
    Eigen::Vector3d x;
    in.read(reinterpret_cast<char*>(x.data()), 24);
    scan->truth[name] = x;
  }
  return static_cast<bool>(in);
}

struct Stats {
  std::map<std::string, std::vector<double>> err, dz;
  std::map<std::string, int> missing, flagged;
  std::vector<double> times, points, all;
};

void Compare(const testing::ScannedBody& scan, const LandmarkSet& set, int subject, bool verbose,
             Stats* s) {
  for (const auto& [name, truth] : scan.truth) {
    if (!set.Has(name)) {
      ++s->missing[name];
      if (verbose)
        std::printf("subject %d %-22s missing: %s\n", subject, name.c_str(),
                    set.missing.count(name) ? set.missing.at(name).c_str() : "?");
      continue;
    }
    const Landmark& l = set.At(name);
    const Eigen::Vector3d d = l.position_mm - truth;
    s->err[name].push_back(d.norm());
    s->dz[name].push_back(std::abs(d.z()));
    s->all.push_back(d.norm());
    if (l.confidence < 0.5) ++s->flagged[name];
    if (verbose) {
      std::string flags;
      for (const std::string& f : l.flags) flags += " " + f;
      std::printf(
          "subject %d %-22s err %6.1f  d(%6.1f %6.1f %6.1f)  truth z %7.1f  conf %.2f %s%s\n",
          subject, name.c_str(), d.norm(), d.x(), d.y(), d.z(), truth.z(), l.confidence,
          l.method.c_str(), flags.c_str());
    }
  }
}

// The structure's proposals against the truth, and a picture of the parts.
void ReportStructure(const testing::ScannedBody& scan, int subject, const std::string& picture,
                     Stats* s) {
  const double h = scan.cloud.points.col(2).maxCoeff();
  const auto start = std::chrono::steady_clock::now();
  const landmarks::BodyStructure b = landmarks::FindBodyStructure(
      landmarks::BodyStructureOptions{}, scan.cloud.points, scan.cloud.normals, h);
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("subject %d structure %s %s (%.3f s)\n", subject, b.ok ? "ok" : "failed",
              b.why.c_str(), t);
  if (!b.ok) return;
  auto report = [&](const std::string& name, const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - scan.truth.at(name);
    std::printf("subject %d proposal %-14s err %6.1f d(%6.1f %6.1f %6.1f)\n", subject, name.c_str(),
                d.norm(), d.x(), d.y(), d.z());
    s->err["proposal_" + name].push_back(d.norm());
    s->dz["proposal_" + name].push_back(std::abs(d.z()));
  };
  report("crotch", b.crotch);
  for (int side : {0, 1})
    if (b.has_armpit[side]) report(side == 0 ? "armpit_right" : "armpit_left", b.armpit[side]);
  if (picture.empty()) return;
  RenderScene scene;
  const Rgb colour[6] = {{160, 160, 160}, {220, 30, 30}, {30, 30, 220},
                         {30, 160, 30},   {200, 150, 0}, {0, 220, 220}};
  for (Eigen::Index r = 0; r < scan.cloud.size(); r += 7)
    scene.points.push_back({"", scan.cloud.points.row(r).transpose(),
                            colour[static_cast<int>(b.part[static_cast<size_t>(r)])]});
  scene.points.push_back({"crotch", b.crotch, {0, 0, 0}});
  for (int side : {0, 1}) {
    if (b.has_armpit[side]) scene.points.push_back({"armpit", b.armpit[side], {0, 0, 0}});
    if (b.has_hand[side]) scene.points.push_back({"hand", b.hand[side], {0, 0, 0}});
    scene.points.push_back({"foot", b.foot[side], {0, 0, 0}});
  }
  scene.points.push_back({"head", b.head, {0, 0, 0}});
  RenderOptions options;
  options.views = {View::kFront, View::kRight};
  options.label_font_px = 11;
  WritePng(Render(options, scene), picture + "_" + std::to_string(subject) + ".png");
}

// The cloud with the found (red, labelled) and true (green) datum points.
void DrawLandmarks(const testing::ScannedBody& scan, const LandmarkSet& set,
                   const std::string& file) {
  RenderScene scene;
  scene.cloud = &scan.cloud;
  for (const auto& [name, truth] : scan.truth) {
    scene.points.push_back({"", truth, {20, 170, 20}});
    if (set.Has(name)) {
      scene.points.push_back({name, set.At(name).position_mm, {220, 30, 30}});
      scene.polylines.push_back(
          {(Eigen::MatrixX3d(2, 3) << truth.transpose(), set.At(name).position_mm.transpose())
               .finished(),
           {0, 0, 0},
           false,
           1});
    }
  }
  RenderOptions options;
  options.views = {View::kFront, View::kRight};
  options.height_px = 1400;
  options.label_font_px = 10;
  WritePng(Render(options, scene), file);
}

void Print(const Stats& s, const std::string& what, int subjects) {
  std::printf("\n%-22s %6s %8s %8s %8s %8s %7s %7s\n", "landmark", "found", "med_mm", "mean_mm",
              "max_mm", "med_dz", "missing", "flagged");
  for (const auto& [name, e] : s.err) {
    const int missing = s.missing.count(name) ? s.missing.at(name) : 0;
    const int flagged = s.flagged.count(name) ? s.flagged.at(name) : 0;
    std::printf("%-22s %6zu %8.1f %8.1f %8.1f %8.1f %7d %7d\n", name.c_str(), e.size(), Median(e),
                Mean(e), Max(e), Median(s.dz.at(name)), missing, flagged);
  }
  for (const auto& [name, count] : s.missing) {
    if (!s.err.count(name))
      std::printf("%-22s %6d %8s %8s %8s %8s %7d\n", name.c_str(), 0, "-", "-", "-", "-", count);
  }
  std::printf(
      "\nall landmarks: median %.1f mm, mean %.1f mm over %zu placements; %s, %d subjects\n",
      Median(s.all), Mean(s.all), s.all.size(), what.c_str(), subjects);
  std::printf("detection: median %.3f s, max %.3f s for median %.0f points\n", Median(s.times),
              Max(s.times), Median(s.points));
}

int Run(int argc, char** argv) {
  CLI::App app{"The landmark detector on virtual scans of generated bodies, against their truth"};
  int subjects = 5, width = 240, height = 180;
  unsigned seed = 1;
  double noise = 1.0;
  bool verbose = false, structure = false;
  std::string picture, hole_at;
  double hole_mm = 40, squeeze_mm = 0;
  std::string model = "parametric", cache;
  std::vector<std::string> params;
  app.add_option("--subjects", subjects, "Number of subjects")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the set")->capture_default_str();
  app.add_option("--model", model, "Body model: parametric or makehuman")->capture_default_str();
  app.add_option("--param", params, "A body size or model value, name=value (repeatable)");
  app.add_option("--noise", noise, "Range noise SD (mm)")->capture_default_str();
  app.add_option("--width", width, "Depth image width per sensor")->capture_default_str();
  app.add_option("--height", height, "Depth image height per sensor")->capture_default_str();
  app.add_option("--cache", cache, "Folder keeping the cleaned scans between runs");
  app.add_flag("--verbose", verbose, "Print every landmark's error per subject");
  app.add_option("--hole-at", hole_at, "Cut a hole around this true landmark (a scan occlusion)");
  app.add_option("--hole-mm", hole_mm, "Radius of that hole (mm)")->capture_default_str();
  app.add_option("--squeeze-thighs-mm", squeeze_mm,
                 "Make the thighs touch: move them together by up to this (mm)");
  app.add_flag("--structure", structure, "Also compare the structure's proposals");
  app.add_option("--picture", picture, "With --structure: pictures of the parts, PREFIX_i.png");
  CLI11_PARSE(app, argc, argv);

  SynthBodyGenerator generator;
  Stats stats;
  std::string what = model;
  for (const std::string& p : params) what += " " + p;
  if (!cache.empty()) std::filesystem::create_directories(cache);
  for (int i = 0; i < subjects; ++i) {
    SynthBodyOptions body_options;
    body_options.model = model;
    body_options.seed = static_cast<std::uint64_t>(seed) * 1000 + static_cast<std::uint64_t>(i) + 1;
    body_options.params = params;
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = body_options.seed;
    scan_options.width_px = width;
    scan_options.height_px = height;
    scan_options.noise_sigma_mm = noise;
    std::string key = model + "_" + std::to_string(body_options.seed) + "_" +
                      std::to_string(width) + "x" + std::to_string(height) + "_" +
                      std::to_string(noise);
    for (const std::string& p : params) key += "_" + p;
    const std::filesystem::path file =
        cache.empty() ? std::filesystem::path()
                      : std::filesystem::path(cache) /
                            (std::to_string(std::hash<std::string>()(key)) + ".scan");
    testing::ScannedBody scan;
    if (cache.empty() || !LoadScan(file, &scan)) {
      scan = testing::ScanAndClean(scan_options, generator.Generate(body_options));
      if (!cache.empty()) SaveScan(file, scan);
    }
    if (!hole_at.empty()) {
      if (!scan.truth.count(hole_at)) throw InputError("--hole-at: no landmark " + hole_at);
      std::vector<Eigen::Index> keep;
      for (Eigen::Index r = 0; r < scan.cloud.size(); ++r)
        if ((scan.cloud.points.row(r).transpose() - scan.truth.at(hole_at)).norm() > hole_mm)
          keep.push_back(r);
      scan.cloud = scan.cloud.Select(keep);
    }
    if (squeeze_mm > 0) testing::SqueezeThighs(squeeze_mm, &scan);
    if (structure) ReportStructure(scan, i, picture, &stats);
    const auto start = std::chrono::steady_clock::now();
    LandmarkSet set;
    try {
      set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    } catch (const Error& e) {
      std::printf("subject %d: %s\n", i, e.what());
      continue;
    }
    if (!picture.empty())
      DrawLandmarks(scan, set, picture + "_landmarks_" + std::to_string(i) + ".png");
    stats.times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    stats.points.push_back(static_cast<double>(scan.cloud.size()));
    Compare(scan, set, i, verbose, &stats);
  }
  Print(stats, what, subjects);
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("landmark_eval", bespoke::Run, argc, argv);
}
