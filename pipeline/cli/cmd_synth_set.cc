// `bespoke synth-set --count N --seed S -o DIR [--model parametric|makehuman]
//  [--population default|full]
//  [--makehuman-dir D] [--preview PNG] [--preview-count K] [--param k=v ...]
//  [--skip-reference]
//  + the scanner options (pipeline/cli/scan_sim_cli.h)`
// A reproducible set of test subjects: for subject i (0-based) the body seed
// is S * 1000 + i + 1 (the same seed drives its scan), and DIR/subject_<i>/
// gets body.obj (body frame, mm), truth.json (datum points and reference
// measurements), scan.ply (+ scan.scan.json, scan.truth.json). DIR/set.json
// lists the subjects, seeds, settings and counts. With --preview, the first
// K subjects' bodies and scans are drawn side by side into one PNG. With
// --skip-reference, truth.json holds the datum points but no reference
// measurements (exact geodesics and sections: seconds per body, docs/oracle.md).
// --param k=v sets body sizes or model values after the seeded draw, for
// every subject (oracle/synth/synth_body.h).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/parametric_body.h"
#include "oracle/synth/synth_body.h"
#include "oracle/truth/truth_file.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "pipeline/cli/scan_sim_cli.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "scanners/render/render.h"

namespace bespoke {
namespace {

struct SynthSetOptions {
  int count = 0;                       // --count (required, 1-10000)
  std::uint64_t seed = 1;              // --seed of the set
  std::string model = "parametric";    // --model parametric|makehuman
  std::string population = "default";  // --population default|full
  std::string posture;                 // --posture NAME ("" = the model's own)
  std::filesystem::path
      makehuman_dir;             // default $BESPOKE_SHARED_DIR or ../shared, /data/bodies/makehuman
  std::filesystem::path output;  // -o DIR (required)
  std::filesystem::path preview;    // --preview PNG
  int preview_count = 4;            // --preview-count
  std::vector<std::string> params;  // --param k=v (parametric)
  bool skip_reference = false;      // --skip-reference: truth.json with datum points only (fast)
  ScanSimCli scanner;
  void Check() const {
    if (count < 1 || count > 10000) throw InputError("--count must be 1-10000");
    if (model != "parametric" && model != "makehuman") {
      throw InputError("--model must be parametric or makehuman, not '" + model + "'");
    }
    if (!preview.empty() && preview.extension() != ".png")
      throw InputError(preview, "--preview must be a .png file");
    if (preview_count < 1 || preview_count > 16) throw InputError("--preview-count must be 1-16");
    scanner.Check();
  }
};

// Front view of the body with its datum points beside the front view of its
// scan (the scan in the body frame).
RgbImage SubjectPicture(const Body& body, const ScanSimResult& scan, const std::string& title) {
  RenderScene scene;
  scene.mesh = &body.mesh;
  for (const auto& [name, point] : body.landmarks)
    scene.points.push_back({"", PositionOf(body.mesh, point)});
  RenderOptions options;
  options.views = {View::kFront};
  options.height_px = 420;
  options.margin_mm = 30;
  options.label_font_px = 11;
  options.title = title;
  // One scale for every subject: a box 1.2 m wide and deep, floor to 2.1 m.
  options.bounds =
      Eigen::AlignedBox3d(Eigen::Vector3d(-600, -600, -20), Eigen::Vector3d(600, 600, 2100));
  const RgbImage left = Render(options, scene);
  PointCloud cloud = scan.cloud;
  TransformInPlace(scan.scanner_from_body.inverse(), &cloud);
  RenderScene scan_scene;
  scan_scene.cloud = &cloud;
  options.title = "scan";
  options.surface = {150, 170, 200};
  return SideBySide({left, Render(options, scan_scene)}, 0);
}

}  // namespace

CommandRunner SetupSynthSetCommand(CLI::App& app) {
  auto o = std::make_shared<SynthSetOptions>();
  app.add_option("--count", o->count, "Number of subjects")->required();
  app.add_option("--seed", o->seed, "Seed of the set (subject i uses seed * 1000 + i + 1)");
  app.add_option("--model", o->model,
                 "Body model: parametric (built in) or makehuman (needs ../shared)");
  app.add_option("--population", o->population,
                 "Population of the draws: default or full (the whole range, hard cases)");
  app.add_option("--posture", o->posture,
                 "Posture of every subject: rest, arms-5|15|30|45|90, feet-together, feet-40, "
                 "lean-5, twist-5, head-turn, joined with + (default: the model's own)");
  app.add_option("--makehuman-dir", o->makehuman_dir,
                 "MakeHuman data (default ../shared/data/bodies/makehuman)");
  app.add_option("-o,--output", o->output, "Folder to fill (created if missing)")->required();
  app.add_option("--preview", o->preview,
                 "Draw the first subjects' bodies and scans into this PNG");
  app.add_option("--preview-count", o->preview_count, "Subjects in the preview (default 4)");
  app.add_option("--param", o->params,
                 "Body size or model value after the seeded draw, name=value (repeatable)");
  app.add_flag("--skip-reference", o->skip_reference,
               "Write datum points only, no reference measurements (faster)");
  AddScanSimOptions(app, &o->scanner, /*seed_option=*/false);  // each scan takes its subject's seed
  return [o](const GlobalOptions& global) {
    o->Check();
    CreateDirectories(o->output);
    const Catalogue& catalogue = Catalogue::Builtin();
    SynthBodyGenerator generator;
    ProgressBar bar(global.quiet);
    nlohmann::json subjects = nlohmann::json::array();
    std::vector<RgbImage> pictures;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < o->count; ++i) {
      const std::uint64_t seed = o->seed * 1000 + static_cast<std::uint64_t>(i) + 1;
      char name[32];
      std::snprintf(name, sizeof(name), "subject_%03d", i);
      const std::filesystem::path dir = o->output / name;
      CreateDirectories(dir);
      SynthBodyOptions body_options;
      body_options.model = o->model;
      body_options.seed = seed;
      body_options.population = o->population;
      body_options.posture = o->posture;
      body_options.params = o->params;
      body_options.makehuman_dir = o->makehuman_dir;
      const Body body = generator.Generate(body_options);
      WriteOptions mesh_write;
      mesh_write.comment = "bespoke synth-set " + o->model + " seed " + std::to_string(seed) +
                           "; units mm; frame body";
      WriteMesh(mesh_write, body.mesh, dir / "body.obj");
      const ReferenceOptions reference;
      ReferenceMeasurements truth;
      if (o->skip_reference) {
        truth.skipped.push_back({"*", "reference measurements not computed (--skip-reference)"});
      } else {
        truth = ComputeReferenceMeasurements(reference, catalogue, body, &bar);
      }
      WriteTruthFile(dir / "truth.json", body, catalogue, reference, truth);
      ScanSimOptions scan_options = o->scanner.ToOptions();
      scan_options.seed = seed;
      ScanSimFiles files;
      files.scan = dir / "scan.ply";
      files.truth_in = dir / "truth.json";
      o->scanner.Apply(&files);
      const ScanSimResult scan = SimulateScanToFiles(scan_options, files, body.mesh, &bar);
      subjects.push_back({{"name", name},
                          {"seed", seed},
                          {"model", body.model},
                          {"vertices", body.mesh.num_vertices()},
                          {"scan_points", scan.cloud.size()},
                          {"measurements", truth.measurements.size()},
                          {"skipped", truth.skipped.size()}});
      if (!o->preview.empty() && static_cast<int>(pictures.size()) < o->preview_count) {
        pictures.push_back(SubjectPicture(body, scan, "seed " + std::to_string(seed)));
      }
      spdlog::info("{}: {} ({} vertices), scan {} points", name, body.model,
                   body.mesh.num_vertices(), scan.cloud.size());
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json scanner = {{"booth", o->scanner.booth},
                              {"sensors", o->scanner.sensors},
                              {"resolution", o->scanner.resolution},
                              {"noise_mm", o->scanner.noise_mm},
                              {"outliers", o->scanner.outliers},
                              {"floor", o->scanner.floor},
                              {"stray_objects", o->scanner.stray_objects},
                              {"transform", o->scanner.transform},
                              {"units", o->scanner.units},
                              {"misalign_mm", o->scanner.misalign_mm},
                              {"misalign_deg", o->scanner.misalign_deg}};
    WriteJsonFile(o->output / "set.json", {{"format", "bespoke-synth-set"},
                                           {"version", 1},
                                           {"model", o->model},
                                           {"population", o->population},
                                           {"posture", o->posture},
                                           {"seed", o->seed},
                                           {"count", o->count},
                                           {"params", o->params},
                                           {"reference_measurements", !o->skip_reference},
                                           {"scanner", scanner},
                                           {"subjects", subjects},
                                           {"time_s", seconds}});
    if (!pictures.empty()) WritePng(SideBySide(pictures, 12), o->preview);
    return 0;
  };
}

}  // namespace bespoke
