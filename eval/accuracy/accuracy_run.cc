#include "eval/accuracy/accuracy_run.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <exception>
#include <mutex>
#include <thread>

#include "eval/accuracy/accuracy_summary.h"
#include "eval/accuracy/compare.h"
#include "eval/accuracy/posture.h"
#include "measure/catalogue/catalogue.h"
#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_pose.h"
#include "oracle/scan_sim/scan_truth.h"
#include "oracle/synth/synth_body.h"
#include "oracle/truth/reference_measurements.h"
#include "oracle/truth/truth_file.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// "a,b,c" -> {a, b, c}; "" -> {}.
std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (!text.empty() && start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    out.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// InputError naming `option` when `model` cannot build `posture`: an
// unknown name, or for the parametric body a lean, twist or head turn, or
// arms or a stance its default body refuses (arms 15-90 deg).
void CheckPosture(const std::string& model, const std::string& posture, const std::string& what) {
  try {
    const MakeHumanPosture p = ParseMakeHumanPosture(posture);
    if (model != "parametric") return;
    if (p.lean_deg != 0 || p.twist_deg != 0 || p.head_turn_deg != 0)
      throw InputError(
          "the parametric body has no lean, twist or head turn; use --model makehuman");
    ParametricBodyOptions body;
    if (p.arm_abduction_deg) body.arm_abduction_deg = *p.arm_abduction_deg;
    if (p.stance_mm) body.stance_width_mm = *p.stance_mm;
    body.Check();
  } catch (const InputError& e) {
    throw InputError(what + ": " +
                     (model == "parametric" ? "the parametric body cannot make it: " : "") +
                     e.what());
  }
}

void CheckPostureTest(const AccuracyRunOptions& o) {
  if (o.posture_test.empty()) return;
  if (!o.posture.empty())
    throw InputError("--posture-test builds the subjects in --posture-reference; drop --posture");
  if (o.pose != "a") throw InputError("--posture-test needs --pose a (not the A/T pair)");
  CheckPosture(o.model, o.posture_reference, "--posture-reference " + o.posture_reference);
  std::vector<std::string> seen;
  for (const std::string& p : SplitList(o.posture_test)) {
    if (p == o.posture_reference)
      throw InputError("--posture-test " + p + " is the reference posture itself");
    if (std::find(seen.begin(), seen.end(), p) != seen.end())
      throw InputError("--posture-test lists " + p + " twice");
    seen.push_back(p);
    CheckPosture(o.model, o.posture_reference + "+" + p, "--posture-test " + p);
  }
}

}  // namespace

void AccuracyRunOptions::Check() const {
  if (subjects < 1 || subjects > 1000) throw InputError("--subjects must be 1-1000");
  if (model != "parametric" && model != "makehuman") {
    throw InputError("--model must be parametric or makehuman, not '" + model + "'");
  }
  if (population != "default" && population != "full")
    throw InputError("--population must be default or full, not '" + population + "'");
  for (const std::string& p : SplitList(posture)) {
    SynthBodyOptions body;
    body.model = model;
    body.population = population;
    body.posture = p;
    body.Check();  // InputError for an unknown posture
  }
  for (const BoothOptions& b : booths) b.Check();
  if (repeat_body && !reuse_set.empty())
    throw InputError("--repeat-body and --reuse-set cannot be combined");
  if (pose != "a" && pose != "t" && pose != "both")
    throw InputError("--pose must be a, t or both, not '" + pose + "'");
  if (pose == "t" && model != "parametric") {
    throw InputError("--pose t needs --model parametric (MakeHuman bodies come in one pose)");
  }
  if (!(a_pose_deg >= 15 && a_pose_deg <= 90) || !(t_pose_deg >= 15 && t_pose_deg <= 90)) {
    throw InputError("arm angles of the poses must be 15-90 degrees");
  }
  if (!(posture_tolerance_mm > 0)) throw InputError("the posture tolerance must be positive");
  CheckPostureTest(*this);
  if (jobs < 1 || jobs > 64) throw InputError("--jobs must be 1-64");
  if (!reuse_set.empty() && !fs::is_regular_file(reuse_set / "set.json")) {
    throw InputError(reuse_set, "--reuse-set needs a bespoke synth-set folder (no set.json)");
  }
  for (const std::string& p : params) {
    const auto [name, value] = ParseNamedValue(p);
    if (model == "parametric")
      ParametricBodyOptions().Set(name, value);  // InputError for unknown names
  }
  if (model == "makehuman") {
    const fs::path dir = makehuman_dir.empty() ? DefaultMakeHumanDir() : makehuman_dir;
    if (!fs::is_directory(dir)) {
      throw InputError(dir,
                       "MakeHuman data not found; give --makehuman-dir or set BESPOKE_SHARED_DIR");
    }
  }
  scanner.Check();
  clean.Check();
}

namespace {

struct SubjectSpec {
  std::string name;
  std::uint64_t seed = 0;       // of the scan (and of the body unless body_seed is set)
  std::uint64_t body_seed = 0;  // 0: seed
  std::string posture;
  const BoothOptions* booth = nullptr;  // null: the run's scanner booth
  std::vector<std::string> params;
  const json* reuse_truth = nullptr;  // a body-frame truth document to reuse, or null
};

struct SubjectOutcome {
  std::string name;
  std::string stage;  // where it failed; empty when ok
  std::string error;
  json truth;  // the scan's truth (scanner frame)
  json measured;
  double time_s = 0;
};

std::string SubjectName(int i) {
  char name[32];
  std::snprintf(name, sizeof(name), "subject_%03d", i);
  return name;
}

// The true datum points in the cleaned body frame: scanner-frame truth
// mapped with the body_from_scanner the cleaning found.
std::map<std::string, Eigen::Vector3d> GivenLandmarks(const json& scan_truth,
                                                      const CleanResult& cleaned) {
  std::map<std::string, Eigen::Vector3d> given;
  for (const auto& [name, value] : scan_truth.at("landmarks").items()) {
    given[name] = cleaned.body_from_scanner * Vector3FromJson(value, "truth landmark " + name);
  }
  return given;
}

SubjectOutcome RunSubject(const AccuracyRunOptions& options, const SubjectSpec& spec,
                          SynthBodyGenerator& generator, const SubjectMeasurer& measurer) {
  SubjectOutcome out;
  out.name = spec.name;
  const auto start = std::chrono::steady_clock::now();
  std::string stage = "body";
  try {
    SynthBodyOptions body_options;
    body_options.model = options.model;
    body_options.seed = spec.body_seed != 0 ? spec.body_seed : spec.seed;
    body_options.population = options.population;
    body_options.posture = spec.posture;
    body_options.params = spec.params;
    body_options.makehuman_dir = options.makehuman_dir;
    const Body body = generator.Generate(body_options);
    stage = "truth";
    json truth;
    if (spec.reuse_truth) {
      truth = *spec.reuse_truth;
      if (truth.value("/mesh/vertices"_json_pointer, -1) != body.mesh.num_vertices()) {
        throw InputError("the reused truth.json was made for another body (vertex count differs)");
      }
    } else {
      const Catalogue& catalogue = Catalogue::Builtin();
      const ReferenceOptions reference;
      truth = TruthDocument(body, catalogue, reference,
                            ComputeReferenceMeasurements(reference, catalogue, body));
    }
    stage = "scan";
    ScanSimOptions scan_options = options.scanner;
    scan_options.seed = spec.seed;
    if (spec.booth) scan_options.booth = *spec.booth;
    ScanSimResult scan = SimulateScan(scan_options, body.mesh);
    out.truth = ScanTruthDocument(truth, scan_options, scan, LengthUnit::kMillimetre, "(in memory)",
                                  spec.name);
    stage = "clean";
    const CleanResult cleaned = CleanScan(options.clean, std::move(scan.cloud));
    stage = "measure";
    std::map<std::string, Eigen::Vector3d> given;
    if (options.truth_landmarks) given = GivenLandmarks(out.truth, cleaned);
    out.measured = measurer(cleaned, options.truth_landmarks ? &given : nullptr);
    if (!out.measured.is_object()) throw InternalError("the measurer returned no document");
    if (!out.measured.contains("body_from_scanner")) {
      out.measured["body_from_scanner"] =
          ToJson(Eigen::Affine3d(cleaned.body_from_scanner.matrix()));
    }
    out.measured["clean_flags"] = cleaned.flags;
  } catch (const std::exception& e) {
    out.stage = stage;
    out.error = e.what();
  }
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// Runs `specs` on `jobs` threads (each with its own body generator).
std::vector<SubjectOutcome> RunSubjects(const AccuracyRunOptions& options,
                                        const std::vector<SubjectSpec>& specs,
                                        const SubjectMeasurer& measurer, Progress* progress) {
  std::vector<SubjectOutcome> outcomes(specs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::int64_t> done{0};
  std::mutex progress_mutex;
  ProgressBegin(progress, "subjects", static_cast<std::int64_t>(specs.size()));
  const auto work = [&]() {
    SynthBodyGenerator generator;
    for (std::size_t i = next++; i < specs.size(); i = next++) {
      outcomes[i] = RunSubject(options, specs[i], generator, measurer);
      const std::lock_guard<std::mutex> lock(progress_mutex);
      ProgressUpdate(progress, ++done);
    }
  };
  const int threads = std::min<int>(options.jobs, static_cast<int>(specs.size()));
  if (threads <= 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }
  ProgressEnd(progress);
  return outcomes;
}

// Truth documents of a synth-set folder made with the same model, seed and
// parameters, by subject index; InputError when the set does not match.
std::vector<json> ReusableTruths(const AccuracyRunOptions& options) {
  std::vector<json> truths(options.subjects);
  if (options.reuse_set.empty()) return truths;
  const json set = ReadJsonFile(options.reuse_set / "set.json");
  if (set.value("model", "") != options.model ||
      set.value("seed", std::uint64_t{0}) != options.seed ||
      set.value("population", std::string("default")) != options.population ||
      set.value("posture", std::string()) != options.posture ||
      set.value("params", std::vector<std::string>{}) != options.params) {
    throw InputError(options.reuse_set / "set.json",
                     "made with another model, seed, population or --param than this run");
  }
  if (!set.value("reference_measurements", false)) {
    throw InputError(options.reuse_set / "set.json",
                     "made with --skip-reference: no reference measurements");
  }
  for (int i = 0; i < options.subjects; ++i) {
    const fs::path file = options.reuse_set / SubjectName(i) / "truth.json";
    if (fs::is_regular_file(file)) truths[i] = ReadJsonFile(file);
  }
  return truths;
}

std::string NowUtc() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

void WriteSubjectDocuments(const fs::path& dir, const SubjectOutcome& o) {
  if (dir.empty()) return;
  CreateDirectories(dir);
  if (!o.truth.is_null()) WriteJsonFile(dir / (o.name + ".truth.json"), o.truth);
  if (!o.measured.is_null()) WriteJsonFile(dir / (o.name + ".measurements.json"), o.measured);
}

// The subjects' specs, in the run's posture (the reference with the posture test).
std::vector<SubjectSpec> SubjectSpecs(const AccuracyRunOptions& options,
                                      const std::vector<json>& reuse) {
  std::vector<SubjectSpec> specs;
  const std::vector<std::string> postures = SplitList(options.posture);
  for (int i = 0; i < options.subjects; ++i) {
    SubjectSpec spec;
    spec.name = SubjectName(i);
    spec.seed = options.seed * 1000 + static_cast<std::uint64_t>(i) + 1;
    if (options.repeat_body) spec.body_seed = options.seed * 1000 + 1;
    if (!postures.empty()) spec.posture = postures[static_cast<std::size_t>(i) % postures.size()];
    if (!options.booths.empty())
      spec.booth = &options.booths[static_cast<std::size_t>(i) % options.booths.size()];
    spec.params = options.params;
    if (options.model == "parametric") {
      const double arms = options.pose == "t" ? options.t_pose_deg : options.a_pose_deg;
      spec.params.push_back("arm_abduction_deg=" + std::to_string(arms));
    }
    if (!reuse[i].is_null()) spec.reuse_truth = &reuse[i];
    specs.push_back(spec);
  }
  return specs;
}

// The posture test's runs, subject-major: each subject's spec (same body
// and scan seeds, same booth) in the reference posture + each listed one.
std::vector<SubjectSpec> PostureTestSpecs(const AccuracyRunOptions& options,
                                          const std::vector<SubjectSpec>& subjects) {
  std::vector<SubjectSpec> specs;
  for (const SubjectSpec& subject : subjects) {
    for (const std::string& p : SplitList(options.posture_test)) {
      SubjectSpec spec = subject;
      spec.name = subject.name + "." + p;
      spec.posture = options.posture_reference + "+" + p;
      spec.reuse_truth = nullptr;
      specs.push_back(spec);
    }
  }
  return specs;
}

// Each subject's listed postures against its reference run; a run that
// failed (or a comparison that threw) fails its pair only.
std::vector<PostureComparison> PostureTestPairs(const AccuracyRunOptions& options,
                                                const std::vector<SubjectOutcome>& subjects,
                                                const std::vector<SubjectOutcome>& postured) {
  const std::vector<std::string> names = SplitList(options.posture_test);
  std::vector<PostureComparison> pairs;
  for (std::size_t i = 0; i < subjects.size(); ++i) {
    const SubjectOutcome& reference = subjects[i];
    for (std::size_t j = 0; j < names.size(); ++j) {
      const SubjectOutcome& o = postured[i * names.size() + j];
      PostureComparison pair;
      if (!reference.error.empty()) {
        pair.error = options.posture_reference + " (" + reference.stage + "): " + reference.error;
      } else if (!o.error.empty()) {
        pair.error = names[j] + " (" + o.stage + "): " + o.error;
      } else {
        try {
          pair = ComparePostures(reference.measured, o.measured, reference.truth, o.truth,
                                 options.posture_tolerance_mm, PostureRule::kLengthsAndGirths);
        } catch (const std::exception& e) {
          pair.error = std::string("compare: ") + e.what();
        }
      }
      pair.subject = reference.name;
      pair.pose_a = options.posture_reference;
      pair.pose_b = names[j];
      pair.tolerance_mm = options.posture_tolerance_mm;
      pair.rule = PostureRule::kLengthsAndGirths;
      pairs.push_back(pair);
    }
  }
  return pairs;
}

// The parametric A/T pair (pose "both"): one body, both arm poses.
PostureComparison RunPosePair(const AccuracyRunOptions& options, const SubjectMeasurer& measurer,
                              Progress* progress) {
  std::vector<SubjectSpec> pair;
  for (double arms : {options.a_pose_deg, options.t_pose_deg}) {
    SubjectSpec spec;
    spec.name = arms == options.a_pose_deg ? "posture_a" : "posture_t";
    spec.seed = options.seed * 1000 + 1;
    if (options.model == "parametric") spec.params = options.params;
    spec.params.push_back("arm_abduction_deg=" + std::to_string(arms));
    pair.push_back(spec);
  }
  AccuracyRunOptions parametric = options;
  parametric.model = "parametric";
  parametric.reuse_set.clear();
  const std::vector<SubjectOutcome> poses = RunSubjects(parametric, pair, measurer, progress);
  PostureComparison posture;
  for (const SubjectOutcome& o : poses) {
    WriteSubjectDocuments(options.subjects_dir, o);
    if (!o.error.empty() && posture.error.empty())
      posture.error = o.name + " (" + o.stage + "): " + o.error;
  }
  if (posture.error.empty()) {
    posture = ComparePostures(poses[0].measured, poses[1].measured, poses[0].truth, poses[1].truth,
                              options.posture_tolerance_mm);
  }
  posture.pose_a = "A-pose";
  posture.pose_b = "T-pose";
  posture.arm_a_deg = options.a_pose_deg;
  posture.arm_b_deg = options.t_pose_deg;
  return posture;
}

// The subjects' comparisons with their truth (failures listed) into `report`.
void CompareSubjects(const std::vector<SubjectOutcome>& outcomes, AccuracyReport* report) {
  for (const SubjectOutcome& o : outcomes) {
    if (!o.error.empty()) {
      report->failures.push_back({o.name, o.stage, o.error});
      continue;
    }
    try {
      report->subjects.push_back(CompareDocuments(o.measured, o.truth, o.name));
    } catch (const std::exception& e) {
      report->failures.push_back({o.name, "compare", e.what()});
    }
  }
  report->summary = SummarizeAccuracy(report->subjects, Catalogue::Builtin());
}

}  // namespace

AccuracyReport RunAccuracy(const AccuracyRunOptions& given, const SubjectMeasurer& measurer,
                           Progress* progress) {
  given.Check();
  AccuracyRunOptions options = given;
  if (!options.posture_test.empty()) options.posture = options.posture_reference;
  AccuracyReport report;
  report.created_utc = NowUtc();
  const std::vector<json> reuse = ReusableTruths(options);
  const std::vector<SubjectSpec> specs = SubjectSpecs(options, reuse);
  // The subjects and their postures run together, so --jobs spans both.
  std::vector<SubjectSpec> all = specs;
  const std::vector<SubjectSpec> postured = PostureTestSpecs(options, specs);
  all.insert(all.end(), postured.begin(), postured.end());
  const std::vector<SubjectOutcome> outcomes = RunSubjects(options, all, measurer, progress);
  for (const SubjectOutcome& o : outcomes) WriteSubjectDocuments(options.subjects_dir, o);
  const std::vector<SubjectOutcome> subjects(outcomes.begin(), outcomes.begin() + specs.size());
  CompareSubjects(subjects, &report);
  if (!postured.empty()) {
    report.posture_pairs = PostureTestPairs(
        options, subjects,
        std::vector<SubjectOutcome>(outcomes.begin() + specs.size(), outcomes.end()));
  }
  if (options.pose == "both") report.posture = RunPosePair(options, measurer, progress);
  json times = json::object();
  for (const SubjectOutcome& o : outcomes) times[o.name] = o.time_s;
  report.settings["subject_time_s"] = times;
  report.title = "Bespoke accuracy report: " + std::to_string(options.subjects) + " " +
                 options.model + " subjects";
  if (!postured.empty())
    report.title += " x " + std::to_string(postured.size() / specs.size()) + " postures";
  return report;
}

}  // namespace bespoke
