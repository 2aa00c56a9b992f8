// Two kinds of ISO 20685-1 accuracy report, one writer
// (eval/accuracy/accuracy_report.h: index.html, CSV tables, PNG plots,
// settings.json, report.json in REPORT_DIR), and the headline printed.
//
// Against the oracle: `bespoke accuracy --subjects N [--model
// parametric|makehuman] [--seed S] [--population default|full]
// [--posture P[,P...]] [--booth B[,B...]] [--repeat-body] [--noise-mm 1]
// [--pose a|t|both] [--posture-test P[,P...] [--posture-reference arms-30]]
// [--jobs N] [--param k=v ...] [--reuse-set SYNTH_SET_DIR]
// [--truth-landmarks] [--keep-subjects] -o REPORT_DIR` generates N subjects, scans them
// virtually, cleans, finds the landmarks, measures them in-process and
// compares with the exact truth (eval/accuracy/accuracy_run.h). --pose both
// (the default for parametric subjects without --posture-test) adds the A/T
// pair: the parametric body of seed S * 1000 + 1 in an A-pose and a T-pose.
// --posture-test builds the subjects in the reference posture and again in
// each listed one, and compares every subject with itself. --truth-landmarks
// measures at the true datum points (mapped into the cleaned frame),
// separating measuring errors from landmark errors.
//
// On real subjects: `bespoke accuracy --scans DIR --reference REF.csv
// [--names valentina|freesewing|MAP.csv] [--method M] [--jobs N]
// [--resume [--retry-failed]] [--units U] [--timeout-s S] [--memory-mb M]
// -o REPORT_DIR` measures the scans through the batch runner into
// REPORT_DIR/scans and compares them with the reference
// (eval/accuracy/scan_accuracy_run.h).
//
// Exit 0 when the report is written (targets missed or not: the report
// says), 1 for bad options or input (nothing is written), 2 when no subject
// could be measured at all, 128 + signal when the scans' batch was
// interrupted (--resume continues it).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>

#include "eval/accuracy/accuracy_run.h"
#include "eval/accuracy/scan_accuracy_run.h"
#include "measure/catalogue/catalogue.h"
#include "measure/landmarks/landmarks.h"
#include "measure/measurements/measure.h"
#include "measure/measurements/measurement_document.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "pipeline/cli/scan_sim_cli.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

struct AccuracyCommandOptions {
  AccuracyRunOptions run;
  std::string pose;    // "" = both for parametric (a with --posture-test), a for makehuman
  ScanSimCli scanner;  // the virtual scanner's options used here (pipeline/cli/scan_sim_cli.h)
  std::string booths = "default";  // --booth NAME[,NAME...]
  bool keep_subjects = false;
  ScanAccuracyOptions scans;  // with --scans: real subjects
  int jobs = -1;              // --jobs; -1 = the kind's default (1 thread; all CPUs for scans)
  std::filesystem::path output;
};

// Landmarks (found, or the given true ones) and measurements of one cleaned scan.
nlohmann::json MeasureCleaned(const CleanResult& cleaned,
                              const std::map<std::string, Eigen::Vector3d>* given) {
  LandmarkSet landmarks;
  if (given) {
    for (const auto& [name, position] : *given) {
      Landmark landmark;
      landmark.position_mm = position;
      landmark.method = "truth";
      landmarks.points[name] = landmark;
    }
  } else {
    landmarks = DetectLandmarks(LandmarkOptions{}, cleaned.cloud);
  }
  MeasureOptions options;
  options.keep_geometry = false;
  const MeasureResult result = Measure(options, Catalogue::Builtin(), cleaned.cloud, landmarks);
  const nlohmann::json extra = {
      {"body_from_scanner", ToJson(Eigen::Affine3d(cleaned.body_from_scanner.matrix()))}};
  return MeasurementDocument(result, landmarks, extra, false);
}

void PrintHeadline(const AccuracyReport& report, const std::filesystem::path& dir) {
  const AccuracySummary& s = report.summary;
  std::printf("subjects compared %d, failed %zu\n", s.subjects, report.failures.size());
  std::printf("ISO 20685-1: %d pass, %d fail, %d not judged (of %zu measurements)\n", s.passed,
              s.failed, s.not_judged, s.measurements.size());
  std::printf("MAE of large girths: %s mm (target <= %.0f)\n",
              FormatNumber(s.large_girth_mae_mm).c_str(), report.targets.large_girth_mae_mm);
  if (!s.landmarks.empty()) {
    std::printf("median landmark error: %s mm (target <= %.0f)\n",
                FormatNumber(s.median_landmark_error_mm).c_str(),
                report.targets.median_landmark_error_mm);
  }
  if (!report.repeatability.empty()) {
    std::printf("repeatability: %zu measurements from repeated scans (repeatability.csv)\n",
                report.repeatability.size());
  }
  if (!report.not_compared.empty()) {
    std::printf("not compared: %zu (not_compared.csv says why)\n", report.not_compared.size());
  }
  if (!report.posture_pairs.empty()) {
    std::printf("%s\n", SummarizePostures(report.posture_pairs).Headline().c_str());
    for (const PostureComparison& p : report.posture_pairs) {
      if (!p.error.empty())
        std::printf("posture pair failed: %s %s: %s\n", p.subject.c_str(), p.pose_b.c_str(),
                    p.error.c_str());
    }
  }
  if (report.posture) {
    const PostureComparison& p = *report.posture;
    if (p.error.empty()) {
      std::printf("posture: %d of %d lengths within %.0f mm (largest difference %s mm)\n", p.passed,
                  p.judged, p.tolerance_mm, FormatNumber(p.max_abs_difference_mm).c_str());
    } else {
      std::printf("posture: did not run: %s\n", p.error.c_str());
    }
  }
  for (const SubjectFailure& f : report.failures) {
    std::printf("failed: %s at %s: %s\n", f.subject.c_str(), f.stage.c_str(), f.error.c_str());
  }
  std::printf("report: %s\n", (dir / "index.html").string().c_str());
}

// Writes the report, prints the headline; exit 0, or InternalError when no
// subject could be compared at all.
int Finish(const AccuracyReport& report, const std::filesystem::path& output) {
  WriteAccuracyReport(report, output);
  PrintHeadline(report, output);
  if (report.summary.subjects == 0) {
    throw InternalError("no subject could be measured; see " + (output / "index.html").string());
  }
  return 0;
}

int RunOracle(const AccuracyCommandOptions& o, const GlobalOptions& global) {
  AccuracyRunOptions run = o.run;
  const bool pair = run.model == "parametric" && run.posture_test.empty();
  run.pose = !o.pose.empty() ? o.pose : pair ? "both" : "a";
  if (o.jobs >= 0) run.jobs = o.jobs;
  std::vector<std::string> names;
  for (std::size_t start = 0; start <= o.booths.size();) {
    const std::size_t comma = std::min(o.booths.find(',', start), o.booths.size());
    names.push_back(o.booths.substr(start, comma - start));
    start = comma + 1;
  }
  ScanSimCli scanner = o.scanner;
  scanner.booth = names.front();
  scanner.Check();
  run.scanner = scanner.ToOptions();
  if (names.size() > 1) {
    for (const std::string& name : names) {
      ScanSimCli one = scanner;
      one.booth = name;
      run.booths.push_back(one.ToOptions().booth);
    }
  }
  if (o.keep_subjects) run.subjects_dir = o.output / "subjects";
  run.Check();
  CreateDirectories(o.output);
  ProgressBar bar(global.quiet);
  AccuracyReport report = RunAccuracy(run, &MeasureCleaned, &bar);
  nlohmann::json settings = {{"command", "bespoke accuracy"},
                             {"subjects", run.subjects},
                             {"model", run.model},
                             {"population", run.population},
                             {"posture", run.posture},
                             {"posture_test", run.posture_test},
                             {"posture_reference", run.posture_reference},
                             {"seed", run.seed},
                             {"params", run.params},
                             {"pose", run.pose},
                             {"a_pose_deg", run.a_pose_deg},
                             {"t_pose_deg", run.t_pose_deg},
                             {"noise_mm", o.scanner.noise_mm},
                             {"outliers", o.scanner.outliers},
                             {"transform", o.scanner.transform},
                             {"booth", o.booths},
                             {"repeat_body", run.repeat_body},
                             {"sensors", o.scanner.sensors},
                             {"resolution", o.scanner.resolution},
                             {"jobs", run.jobs},
                             {"reuse_set", run.reuse_set.string()},
                             {"truth_landmarks", run.truth_landmarks},
                             {"created_utc", report.created_utc}};
  settings.update(report.settings);
  if (run.truth_landmarks) {
    report.title +=
        " (measured at the TRUE datum points: landmark errors are zero by construction)";
  }
  report.settings = settings;
  return Finish(report, o.output);
}

int RunScans(const AccuracyCommandOptions& o, const GlobalOptions& global) {
  ScanAccuracyOptions scans = o.scans;
  scans.report_dir = o.output;
  if (o.jobs >= 0) scans.jobs = o.jobs;
  ProgressBar bar(global.quiet);
  const ScanAccuracyOutcome outcome = RunScanAccuracy(scans, &bar);
  if (outcome.interrupted) {
    spdlog::warn("interrupted: no report written; --resume continues the measured scans");
    return 128 + outcome.signal;
  }
  return Finish(outcome.report, o.output);
}

void AddOracleOptions(CLI::App& app, AccuracyCommandOptions* o, CLI::Option* scans) {
  AccuracyRunOptions& r = o->run;
  const auto oracle = [scans](CLI::Option* option) { return option->excludes(scans); };
  oracle(app.add_option("--subjects", r.subjects, "Oracle: number of generated subjects (1-1000)"));
  oracle(app.add_option("--model", r.model,
                        "Body model: parametric (built in) or makehuman (needs ../shared)"));
  oracle(app.add_option("--seed", r.seed,
                        "Seed of the set (subject i uses seed * 1000 + i + 1, as synth-set)"));
  oracle(app.add_option("--population", r.population,
                        "Population of the subjects: default or full (the whole range, hard "
                        "cases)"));
  oracle(app.add_option("--posture", r.posture,
                        "Posture: rest, arms-5|15|30|45|90, feet-together, feet-40, lean-5, "
                        "twist-5, head-turn, joined with +; a comma list is cycled through by "
                        "the subjects (default: the model's own)"));
  oracle(app.add_option("--posture-test", r.posture_test,
                        "Posture test: every subject also built, scanned and measured in each of "
                        "these postures (comma list, names as --posture) and compared with itself "
                        "in --posture-reference: lengths within 5 mm, girths within their ISO "
                        "20685-1 limit"));
  oracle(app.add_option("--posture-reference", r.posture_reference,
                        "Posture test: the subjects' reference posture (default arms-30)"));
  oracle(app.add_flag("--repeat-body", r.repeat_body,
                      "Every subject is the same body (seed S * 1000 + 1), scanned with its own "
                      "seed (repeatability)"));
  oracle(app.add_option("--param", r.params,
                        "Body size or model value for every subject, name=value (repeatable)"));
  oracle(app.add_option("--makehuman-dir", r.makehuman_dir,
                        "MakeHuman data (default ../shared/data/bodies/makehuman)"));
  oracle(app.add_option("--noise-mm", o->scanner.noise_mm,
                        "Scanner range noise SD along each ray, mm (default 1)"));
  oracle(app.add_option("--outliers", o->scanner.outliers,
                        "Fraction of outlier points in each scan (default 0.02)"));
  oracle(app.add_option("--transform", o->scanner.transform,
                        "Scanner frame: none, random (rigid) or y-up (default none)"));
  oracle(app.add_option("--booth", o->booths,
                        "Named booth: default, sparse, sparse-3, 60k, 120k, 250k, 500k; a comma "
                        "list is cycled through by the subjects (default default)"));
  oracle(app.add_option("--sensors", o->scanner.sensors,
                        "DIRECTIONSxHEIGHTS sensors (default: the booth's, 6x7)"));
  oracle(app.add_option("--resolution", o->scanner.resolution,
                        "Depth image per sensor, WIDTHxHEIGHT px (default: the booth's, 240x180)"));
  oracle(app.add_option(
      "--pose", o->pose,
      "a (A-pose), t (T-pose, parametric) or both (A-pose subjects + the posture test); "
      "default both for parametric, a for makehuman"));
  oracle(app.add_option("--a-pose-deg", r.a_pose_deg,
                        "Arm abduction of the A-pose, degrees (default 30)"));
  oracle(app.add_option("--t-pose-deg", r.t_pose_deg,
                        "Arm abduction of the T-pose, degrees (default 90)"));
  oracle(app.add_option(
      "--reuse-set", r.reuse_set,
      "A synth-set folder (same model, seed, --param) whose truth.json files are reused"));
  oracle(
      app.add_flag("--truth-landmarks", r.truth_landmarks,
                   "Measure at the true datum points (isolates measuring from landmark finding)"));
  oracle(app.add_flag("--keep-subjects", o->keep_subjects,
                      "Also write each subject's truth and measurements"));
}

void AddScanOptions(CLI::App& app, AccuracyCommandOptions* o, CLI::Option* scans) {
  ScanAccuracyOptions& s = o->scans;
  const auto real = [scans](CLI::Option* option) { return option->needs(scans); };
  real(app.add_option("--reference", s.reference,
                      "Real subjects: CSV of subject,measurement,value_mm[,method,unit] rows "
                      "taken another way (tape, another scanner)"));
  real(app.add_option(
      "--names", s.names,
      "Their names -> ours: valentina, freesewing or a CSV their_name,our_name,note"));
  real(app.add_option("--method", s.method,
                      "Compare only the reference rows of this method (e.g. tape)"));
  real(app.add_flag("--resume", s.resume,
                    "Continue measuring the scans of an interrupted run in REPORT_DIR/scans"));
  real(app.add_flag("--retry-failed", s.retry_failed,
                    "With --resume: measure the scans that failed again"));
  real(app.add_option("--units", s.units,
                      "Length unit of the scan files: mm, cm, dm, m (default: guess)"));
  real(app.add_option("--timeout-s", s.timeout_s, "Wall-time limit per scan, s (0 = none)")
           ->capture_default_str());
  real(app.add_option("--memory-mb", s.memory_mb, "Address-space limit per scan, MB (0 = none)")
           ->capture_default_str());
  real(app.add_option("--worker", s.worker, "Program run per scan instead of bespoke (tests)")
           ->group(""));
}

}  // namespace

CommandRunner SetupAccuracyCommand(CLI::App& app) {
  auto o = std::make_shared<AccuracyCommandOptions>();
  CLI::Option* scans =
      app.add_option("--scans", o->scans.scans_dir,
                     "Real subjects: folder of scans SUBJECT.ply or SUBJECT_1.ply, SUBJECT_2.ply "
                     "(repeated scans); needs --reference");
  AddOracleOptions(app, o.get(), scans);
  AddScanOptions(app, o.get(), scans);
  app.add_option("--jobs", o->jobs,
                 "Subjects at once (oracle: threads, default 1); scans at once (--scans: "
                 "worker processes, default all CPUs)");
  app.add_option("-o,--output", o->output, "Report folder (created if missing)")->required();
  return [o](const GlobalOptions& global) {
    if (!o->scans.scans_dir.empty()) return RunScans(*o, global);
    if (o->run.subjects == 0)
      throw InputError("give --subjects N (oracle) or --scans DIR --reference REF.csv");
    return RunOracle(*o, global);
  };
}

}  // namespace bespoke
