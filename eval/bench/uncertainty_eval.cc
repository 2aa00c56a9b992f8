// Evidence run: how well the measurements' 95 % intervals (uncertainty_mm)
// hold the truth, from the subjects of `bespoke accuracy --keep-subjects`
// reports, and the landmarks' typical errors the intervals start from.
//
//   build/eval/bench/uncertainty_eval REPORT_DIR [REPORT_DIR ...] [--scale S]
//
// For each REPORT_DIR/subjects/<s>.measurements.json with its
// <s>.truth.json (eval/accuracy/compare.h matches them): per measurement,
// the share of subjects whose |measured - truth| <= uncertainty_mm (the
// coverage; the target is >= 90 % overall), the median interval, and the
// factor that would make the overall coverage exactly 90 % (the 90th
// percentile of |error| / uncertainty_mm; > 1: the intervals are too
// narrow). `--scale S` judges the intervals times S instead: a
// calibration factor checked on reports it was not fitted on (the
// intervals are proportional to UncertaintyOptions::scale). Then the
// median 3-D error of every landmark kind (both sides pooled): the table
// uncertainty.cc starts from, when run on a calibration set. A report, not
// a test: exit code 0.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "eval/accuracy/compare.h"
#include "eval/bench/bench_main.h"
#include "measure/catalogue/catalogue.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

double Quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1,
                    static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5))];
}

int Run(int argc, char** argv) {
  CLI::App app{"Coverage of the measurements' 95 % intervals on accuracy reports"};
  std::vector<std::string> reports;
  app.add_option("reports", reports, "Report folders of bespoke accuracy --keep-subjects")
      ->required();
  double scale = 1;
  app.add_option("--scale", scale, "Judge the intervals times this factor")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  std::map<std::string, std::vector<double>> ratio, interval;  // per measurement
  std::map<std::string, std::vector<double>> landmark;         // per landmark kind
  std::vector<double> all;
  int subjects = 0;
  for (const std::string& report : reports) {
    const std::filesystem::path dir = std::filesystem::path(report) / "subjects";
    if (!std::filesystem::is_directory(dir))
      throw InputError(dir, "no subjects folder (run bespoke accuracy with --keep-subjects)");
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string file = entry.path().filename().string();
      const std::string suffix = ".measurements.json";
      if (file.size() <= suffix.size() || file.substr(file.size() - suffix.size()) != suffix)
        continue;
      const std::string subject = file.substr(0, file.size() - suffix.size());
      const nlohmann::json measured = ReadJsonFile(entry.path());
      const nlohmann::json truth = ReadJsonFile(dir / (subject + ".truth.json"));
      const SubjectComparison c = CompareDocuments(measured, truth, subject);
      std::map<std::string, double> u;
      for (const auto& m : measured.value("measurements", nlohmann::json::array()))
        if (m.contains("uncertainty_mm")) u[m["name"]] = m["uncertainty_mm"].get<double>();
      for (const MeasurementDifference& d : c.measurements) {
        if (d.missing || !u.count(d.name) || !(u[d.name] > 0)) continue;
        const double r = std::abs(d.difference_mm) / (scale * u[d.name]);
        ratio[d.name].push_back(r), interval[d.name].push_back(scale * u[d.name]);
        all.push_back(r);
      }
      for (const LandmarkError& e : c.landmarks)
        if (!e.missing) landmark[UnsidedLandmarkName(e.name)].push_back(e.error_mm);
      ++subjects;
    }
  }
  std::printf("%-22s %5s %9s %11s %9s\n", "measurement", "n", "coverage", "median_U_mm",
              "factor90");
  for (const auto& [name, r] : ratio) {
    const double inside =
        static_cast<double>(std::count_if(r.begin(), r.end(), [](double x) { return x <= 1; }));
    std::printf("%-22s %5zu %8.1f%% %11.1f %9.2f\n", name.c_str(), r.size(),
                100 * inside / static_cast<double>(r.size()), Quantile(interval[name], 0.5),
                Quantile(r, 0.9));
  }
  const double inside =
      static_cast<double>(std::count_if(all.begin(), all.end(), [](double x) { return x <= 1; }));
  std::printf(
      "\nall: %d subjects, %zu measurements, %.1f %% within their 95 %% interval; factor "
      "for 90 %%: %.2f\n",
      subjects, all.size(), all.empty() ? 0.0 : 100 * inside / static_cast<double>(all.size()),
      Quantile(all, 0.9));
  std::printf("\n%-20s %5s %9s\n", "landmark kind", "n", "median_mm");
  for (const auto& [kind, e] : landmark)
    std::printf("%-20s %5zu %9.1f\n", kind.c_str(), e.size(), Quantile(e, 0.5));
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("uncertainty_eval", bespoke::Run, argc, argv);
}
