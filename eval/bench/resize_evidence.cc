// Resize evidence: bodies far from the standard size, each resized
// from the standard-size design and compared with the design drafted directly
// for that body and with plain proportional grading (eval/resize/evidence.h).
// Prints a Markdown table and a summary line; exit code 1 when any body
// misses a check (binding or seam beyond 1 mm, a self-intersecting outline,
// or the GA not closer to the direct draft than grading is, by mean distance).
//
//   resize_evidence [--design shirt|trousers|both] [--bodies 20] [--population 400]
//                   [--generations 200] [--truth-dir DIR] [--write DIR]
//                   [--first 100]
// With --truth-dir, the bodies are DIR/subject_*/truth.json (from
// `bespoke synth-set`, measurements in the contracts.md schema); without it,
// generated measurement sets (resize/designs/body_variants.h). With --write,
// DIR/<design>-<body>/ gets measurements.json and the fitted, drafted and
// graded patterns (fitted.json, draft.json, grading.json) for inspection.
// --first: the first generated body's seed (gen-<first>...). --generations 0
// skips the GA (the graded start, polished): the run without the GA.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "eval/resize/evidence.h"
#include "resize/designs/body_variants.h"
#include "resize/designs/designs.h"
#include "resize/io/pattern_json.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace {
int Run(int argc, char** argv) {
  using namespace bespoke;
  ResizeOptions options;
  int count = 20, first = 100;
  std::string which = "both";
  std::filesystem::path truth_dir, write_dir;
  const char* usage =
      "usage: resize_evidence [--design shirt|trousers|both] [--bodies 20] [--population 400]\n"
      "                       [--generations 200] [--truth-dir DIR] [--write DIR]\n"
      "                       [--first 100]\n";
  for (int i = 1; i < argc; i += 2) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--population") && has_value)
      options.population = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--generations") && has_value)
      options.generations = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--bodies") && has_value)
      count = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--design") && has_value)
      which = argv[i + 1];
    else if (!std::strcmp(argv[i], "--truth-dir") && has_value)
      truth_dir = argv[i + 1];
    else if (!std::strcmp(argv[i], "--first") && has_value)
      first = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--write") && has_value)
      write_dir = argv[i + 1];
    else {
      std::fputs(usage, stderr);
      return std::strcmp(argv[i], "--help") && std::strcmp(argv[i], "-h") ? 1 : 0;
    }
  }
  std::vector<std::filesystem::path> truths;
  if (!truth_dir.empty()) {
    if (!std::filesystem::is_directory(truth_dir))
      throw InputError(truth_dir.string() +
                       ": --truth-dir is not a folder (a `bespoke synth-set` output)");
    for (const auto& entry : std::filesystem::directory_iterator(truth_dir))
      if (std::filesystem::exists(entry.path() / "truth.json"))
        truths.push_back(entry.path() / "truth.json");
    std::sort(truths.begin(), truths.end());
    if (static_cast<int>(truths.size()) > count) truths.resize(count);
    count = static_cast<int>(truths.size());
  }
  int failures = 0, rows = 0;
  double sum_fit = 0, sum_graded = 0, sum_grading = 0;
  std::printf(
      "| design | body | worst binding mm | worst seam mm | simple | shape deg (draft's) | "
      "fit-draft mean/max mm | graded-draft mean mm | grading-draft mean/max mm | "
      "grading worst binding mm | kink mm | tilt deg | notch mm | cap fit/graded/draft mm | "
      "new inflections | polish from | s |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& design : DesignNames()) {
    if (which != "both" && which != design) continue;
    for (int b = 0; b < count; ++b) {
      MeasurementSet body;
      std::string name;
      if (truths.empty()) {
        body = VariedMeasurements(design, first + b);
        name = "gen-" + std::to_string(first + b);
      } else {
        const MeasurementSet all = ReadMeasurements(truths[b]);
        for (const auto& [m, v] : BaseMeasurements(design)) {
          if (!all.count(m)) throw InputError(truths[b], "has no '" + m + "'");
          body[m] = all.at(m);
        }
        name = truths[b].parent_path().filename().string();
      }
      FitPatterns patterns;
      const FitEvidence e = EvaluateFit(options, design, body, &patterns);
      if (!write_dir.empty()) {
        const std::filesystem::path dir = write_dir / (design + "-" + name);
        std::filesystem::create_directories(dir);
        WriteJsonFile(dir / "measurements.json", MeasurementsToJson(body));
        WritePatternJson(patterns.fitted, dir / "fitted.json");
        WritePatternJson(patterns.direct, dir / "draft.json");
        WritePatternJson(patterns.grading, dir / "grading.json");
      }
      const bool ok = e.Passes();
      failures += ok ? 0 : 1;
      ++rows;
      sum_fit += e.ga_to_draft.mean_mm;
      sum_graded += e.graded_to_draft.mean_mm;
      sum_grading += e.grading_to_draft.mean_mm;
      std::printf(
          "| %s | %s | %.3f | %.3f | %s | %.3f (%.3f) | %.1f / %.1f | %.1f | %.1f / %.1f | %.1f | "
          "%.3f | %.3f | %.3f | %.1f / %.1f / %.1f | %d | %s | %.2f |%s\n",
          design.c_str(), name.c_str(), e.max_binding_error_mm, e.max_seam_mismatch_mm,
          e.outlines_simple ? "yes" : "NO", e.shape_deg, e.draft_shape_deg, e.ga_to_draft.mean_mm,
          e.ga_to_draft.max_mm, e.graded_to_draft.mean_mm, e.grading_to_draft.mean_mm,
          e.grading_to_draft.max_mm, e.grading_max_binding_error_mm, e.max_kink_mm, e.max_tilt_deg,
          e.max_notch_shift_mm, e.cap_fit_mm, e.cap_graded_mm, e.cap_draft_mm, e.new_inflections,
          e.polish_start.c_str(), e.time_s, ok ? "" : " **miss**");
      std::fflush(stdout);
    }
  }
  std::printf(
      "\nmean distance to the draft over the rows: fit %.2f mm, graded start %.2f mm, "
      "grading %.2f mm\n%d passed, %d failed\n",
      sum_fit / std::max(rows, 1), sum_graded / std::max(rows, 1), sum_grading / std::max(rows, 1),
      rows - failures, failures);
  return failures == 0 ? 0 : 1;
}
}  // namespace

// Errors end the run with a message and an exit code (1 bad input, 2 other).
int main(int argc, char** argv) {
  return bespoke::RunBenchMain("resize_evidence", Run, argc, argv);
}
