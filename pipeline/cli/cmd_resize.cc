// `bespoke resize --pattern PATTERN|--design shirt|trousers
//                 --measurements MEAS.json|--scan SCAN
//                 -o OUT_DIR [--sidecar SIDECAR.json] [--seed N] [--population 400]
//                 [--generations 200] [--threads 0] [--seam-allowance 10] [--no-polish]`
// Fits a base pattern to a body's measurements with the multi-objective GA
// of thesis chapter 4 (resize/ga/resize.h). With --scan the measurements
// are taken from the scan first, by the pipeline's single-scan job
// (pipeline/batch/scan_job.h: read, clean, measure, as `bespoke measure`
// and `bespoke run` do), in a scratch folder that is removed afterwards;
// its measurements.json is written into OUT_DIR beside the fit. Writes into
// OUT_DIR:
//   fitted.json (Bespoke pattern), fitted.svg (1:1 mm, printable),
//   fitted.dxf (DXF-ASTM D6673 layers), pareto_front.csv, report.json (with
//   the settings used), report.txt (readable summary), convergence.png and
//   overlay.png (base, graded start and fit over each other, per piece).
// PATTERN is a Bespoke pattern JSON, a GarmentCode JSON or a DXF-AAMA/ASTM
// file (the last two need --sidecar for landmarks, seams and bindings).
// Bad input (unknown or missing measurement names, missing bindings, seams of
// different point counts, self-intersecting outlines) is an InputError (exit 1).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <future>
#include <random>
#include <string>

#include "pipeline/batch/scan_job.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "resize/designs/designs.h"
#include "resize/ga/report.h"
#include "resize/ga/resize.h"
#include "resize/io/measurements_io.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_io.h"
#include "resize/io/pattern_json.h"
#include "resize/io/pattern_overlay.h"
#include "resize/io/pattern_svg.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/render/plot.h"

namespace bespoke {
namespace {

struct ResizeCommandOptions {
  std::filesystem::path pattern;            // base pattern file, or
  std::string design;                       // a built-in design
  std::filesystem::path sidecar;            // optional landmarks/seams/bindings
  std::filesystem::path measurements;       // MEAS.json / TRUTH.json / a Valentina .vit, or
  std::filesystem::path scan;               // a scan to measure first
  std::filesystem::path base_measurements;  // the body the base pattern was drafted for
  std::filesystem::path out_dir;
  ResizeOptions resize;
  double seam_allowance_mm = 10;  // SVG/DXF cut lines
  bool no_polish = false;

  void Check() const {
    if (pattern.empty() == design.empty())
      throw InputError("give exactly one of --pattern FILE and --design shirt|trousers");
    if (!sidecar.empty() && pattern.empty()) throw InputError("--sidecar needs --pattern");
    if (measurements.empty() == scan.empty())
      throw InputError("give exactly one of --measurements FILE and --scan SCAN");
    if (out_dir.empty()) throw InputError("-o OUT_DIR is required");
    if (!(seam_allowance_mm >= 0)) throw InputError("--seam-allowance must be >= 0 mm");
    resize.Check();
  }
};

// Base, graded start and fit drawn over each other, piece by piece.
void WriteOverlay(const Pattern& base, const ResizeResult& r, const std::filesystem::path& file) {
  auto layer = [](const char* label, const Pattern* p, std::array<double, 3> color, double px,
                  bool dashed) {
    OverlayLayer l;
    l.label = label;
    l.pattern = p;
    l.color = color;
    l.line_px = px;
    l.dashed = dashed;
    return l;
  };
  WritePatternOverlay(OverlayOptions{},
                      {layer("base", &base, {0.55, 0.55, 0.55}, 1.0, false),
                       layer("graded start", &r.graded, {0.2, 0.4, 0.9}, 1.0, true),
                       layer("fitted", &r.fitted, {0.85, 0.1, 0.1}, 1.5, false)},
                      file);
}

void WriteConvergence(const ResizeResult& r, const std::filesystem::path& file) {
  Chart chart;
  chart.title = "GA convergence (best of each generation)";
  chart.x_label = "generation";
  chart.y_label = "objective (mm, Eq 4.8, deg)";
  chart.log_y = true;
  // The proportional seed keeps shape change 0, so the best shape stays at 0:
  // values are floored at 1e-3 to keep the log axis readable.
  constexpr double kFloor = 1e-3;
  Series m{"measurement (mm)", {}, {}}, s{"seam", {}, {}}, h{"shape (deg)", {}, {}};
  double top = 1;
  for (const GenerationStats& g : r.history) {
    const double x = g.generation;
    m.x.push_back(x), m.y.push_back(std::max(g.best_measurement_mm, kFloor));
    s.x.push_back(x), s.y.push_back(std::max(g.best_seam, kFloor));
    h.x.push_back(x), h.y.push_back(std::max(g.best_shape_deg, kFloor));
    top = std::max({top, g.best_measurement_mm, g.best_seam, g.best_shape_deg});
  }
  chart.series = {m, s, h};
  chart.y_min = kFloor;
  chart.y_max = 2 * top;
  WriteChart(chart, file);
}

// A scratch folder for the scan job, removed with everything in it when
// this goes out of scope (on success and on error alike).
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device seed;
    const std::string name = fmt::format("bespoke-resize-scan-{:016x}",
                                         (std::uint64_t{seed()} << 32) ^ std::uint64_t{seed()});
    path_ = std::filesystem::temp_directory_path() / name;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The scan's measurement document, taken by the single-scan job
// without a design: read, clean, measure, with the defaults of `bespoke
// measure`.
nlohmann::json MeasureScan(const std::filesystem::path& scan, const ScratchDir& scratch,
                           Progress* progress) {
  ScanJobOptions job;
  job.write_cleaned_cloud = false;
  RunScanJob(job, scan, scratch.path(), progress);
  return ReadJsonFile(scratch.path() / "measurements.json");
}

// The body's measurements from --measurements, or from --scan (then
// `document` gets the scan's measurement document).
MeasurementSet LoadBody(const ResizeCommandOptions& o, const ScratchDir& scratch,
                        Progress* progress, nlohmann::json* document) {
  if (!o.scan.empty()) {
    *document = MeasureScan(o.scan, scratch, progress);
    return MeasurementsFromJson(*document, o.scan.string() + " (its measurements)");
  }
  std::vector<std::string> skipped;
  const MeasurementSet body = LoadMeasurements(o.measurements, &skipped);
  if (!skipped.empty())
    spdlog::info("{}: left out {} measurement(s) the catalogue does not know: {}",
                 o.measurements.string(), skipped.size(), fmt::join(skipped, ", "));
  return body;
}

int RunResize(const ResizeCommandOptions& o, const GlobalOptions& global) {
  o.Check();
  ProgressBar bar(global.quiet);
  // The pattern first: a bad pattern fails before the scan is measured.
  Pattern base = o.design.empty() ? LoadPattern(o.pattern, o.sidecar)
                                  : DraftDesign(o.design, BaseMeasurements(o.design));
  if (!o.base_measurements.empty()) {
    const MeasurementSet base_body = LoadMeasurements(o.base_measurements);
    for (const auto& [name, value] : base_body) base.base_body[name] = value;
    ResolveKeptEase(o.base_measurements.string(), &base);
  }
  for (const std::string& note : base.notes) spdlog::info("import: {}", note);
  const ScratchDir scratch;
  nlohmann::json scan_document;
  const MeasurementSet body = LoadBody(o, scratch, &bar, &scan_document);
  const std::string body_source = o.scan.empty() ? o.measurements.string() : o.scan.string();
  CheckBindingsAgainst(base, body, o.design.empty() ? o.pattern.string() : "design " + o.design,
                       body_source);
  CreateDirectories(o.out_dir);
  ResizeOptions options = o.resize;
  options.polish = !o.no_polish;
  const ResizeResult result = ResizePattern(options, base, body, &bar);

  const nlohmann::json settings = {{"pattern", o.pattern.string()},
                                   {"design", o.design},
                                   {"sidecar", o.sidecar.string()},
                                   {"measurements", o.measurements.string()},
                                   {"scan", o.scan.string()},
                                   {"base_measurements", o.base_measurements.string()},
                                   {"seed", options.seed},
                                   {"population", options.population},
                                   {"generations", options.generations},
                                   {"threads", options.threads},
                                   {"crossover_rate", options.crossover_rate},
                                   {"mutation_rate", options.mutation_rate},
                                   {"mutation_rate_step", options.mutation_rate_step},
                                   {"polish", options.polish},
                                   {"tolerance_mm", options.tolerance_mm},
                                   {"seam_allowance_mm", o.seam_allowance_mm}};
  const nlohmann::json report = ResizeReportJson(base, body, result, settings);
  // The two pictures (most of the writing time) are drawn on a second
  // thread while the pattern files are written (after them with --threads 1).
  const auto policy = options.threads == 1 ? std::launch::deferred : std::launch::async;
  std::future<void> pictures = std::async(policy, [&] {
    WriteConvergence(result, o.out_dir / "convergence.png");
    WriteOverlay(base, result, o.out_dir / "overlay.png");
  });
  if (!o.scan.empty()) WriteJsonFile(o.out_dir / "measurements.json", scan_document);
  WritePatternJson(result.fitted, o.out_dir / "fitted.json");
  SvgOptions svg;
  svg.seam_allowance_mm = o.seam_allowance_mm;
  WritePatternSvg(svg, result.fitted, o.out_dir / "fitted.svg");
  DxfWriteOptions dxf;
  dxf.seam_allowance_mm = o.seam_allowance_mm;
  WritePatternDxf(dxf, result.fitted, o.out_dir / "fitted.dxf");
  WriteFileAtomically(o.out_dir / "pareto_front.csv", ParetoFrontCsv(result));
  WriteJsonFile(o.out_dir / "report.json", report);
  WriteFileAtomically(o.out_dir / "report.txt", ResizeReportText(report));
  pictures.get();
  spdlog::info(
      "fitted '{}' in {:.2f} s: worst binding error {:.3f} mm, worst seam mismatch "
      "{:.3f} mm; wrote {}",
      base.name, result.ga_time_s + result.polish_time_s, result.objectives.max_measurement_mm,
      result.objectives.max_seam_length_mm, o.out_dir.string());
  if (result.objectives.max_measurement_mm > options.tolerance_mm ||
      result.objectives.max_seam_length_mm > options.tolerance_mm)
    spdlog::warn("the fit misses the {:.1f} mm tolerance; see {}", options.tolerance_mm,
                 (o.out_dir / "report.txt").string());
  return 0;
}

}  // namespace

CommandRunner SetupResizeCommand(CLI::App& app) {
  auto o = std::make_shared<ResizeCommandOptions>();
  app.add_option("--pattern", o->pattern,
                 "Base pattern: Bespoke JSON, GarmentCode JSON or DXF-AAMA/ASTM");
  app.add_option("--design", o->design, "A built-in design instead: shirt or trousers");
  app.add_option("--sidecar", o->sidecar,
                 "JSON adding landmarks, seams and bindings to a DXF/GarmentCode pattern");
  app.add_option("--measurements", o->measurements,
                 "MEAS.json or TRUTH.json (mm), or a Valentina .vit file");
  app.add_option("--scan", o->scan,
                 "A body scan instead: measured as `bespoke measure` does (measurements.json "
                 "is written beside the fit)");
  app.add_option("--base-measurements", o->base_measurements,
                 "The body the base pattern was drafted for (.json or .vit): bindings without "
                 "an ease of their own keep the base's ease at that body");
  app.add_option("-o,--out", o->out_dir, "Output folder")->required();
  app.add_option("--seed", o->resize.seed, "Random seed (same seed, same result)");
  app.add_option("--population", o->resize.population, "Individuals (thesis: 400)");
  app.add_option("--generations", o->resize.generations, "Generations (thesis: 200)");
  app.add_option("--threads", o->resize.threads, "Threads for the fit (0 = all CPUs)");
  app.add_option("--seam-allowance", o->seam_allowance_mm, "Cut-line allowance in SVG/DXF (mm)");
  app.add_flag("--no-polish", o->no_polish, "Stop at the GA's pick (no constrained polish)");
  return [o](const GlobalOptions& global) { return RunResize(*o, global); };
}

}  // namespace bespoke
