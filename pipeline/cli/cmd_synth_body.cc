// `bespoke synth-body [--model parametric|makehuman] --seed N [--population default|full]
//  [--param k=v ...]
//  -o BODY.obj [--truth TRUTH.json] [--skip-reference] [--makehuman-dir D]`
// One test subject's body (oracle/synth/synth_body.h): the mesh in the
// body frame (mm) and, with --truth, its datum points and exact reference
// measurements (oracle/truth/truth_file.h). The same seed and parameters
// give the same body as `bespoke synth-set` and `bespoke accuracy`.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "measure/catalogue/catalogue.h"
#include "oracle/synth/synth_body.h"
#include "oracle/truth/truth_file.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct SynthBodyCommandOptions {
  SynthBodyOptions body;
  std::filesystem::path output;  // -o BODY.obj|.ply|.off|.stl (required)
  std::filesystem::path truth;   // --truth TRUTH.json (optional)
  bool skip_reference = false;   // --skip-reference: datum points only in TRUTH.json
  void Check() const {
    body.Check();
    const std::string ext = output.extension().string();
    if (ext != ".obj" && ext != ".ply" && ext != ".off" && ext != ".stl") {
      throw InputError(output, "-o must be a mesh file (.obj, .ply, .off or .stl)");
    }
    if (!truth.empty() && truth.extension() != ".json")
      throw InputError(truth, "--truth must be a .json file");
    if (skip_reference && truth.empty()) throw InputError("--skip-reference needs --truth");
    for (const std::filesystem::path& file : {output, truth}) {
      const std::filesystem::path folder = file.parent_path();
      if (!file.empty() && !folder.empty() && !std::filesystem::is_directory(folder))
        throw InputError(file, "its folder does not exist");
    }
  }
};

}  // namespace

CommandRunner SetupSynthBodyCommand(CLI::App& app) {
  auto o = std::make_shared<SynthBodyCommandOptions>();
  app.add_option("--model", o->body.model,
                 "Body model: parametric (built in, default) or makehuman (needs ../shared)");
  app.add_option("--seed", o->body.seed, "Seed (parametric: 0 = the average body; default 1)");
  app.add_option("--population", o->body.population,
                 "Population of the seeded draw: default or full (the whole range, hard cases)");
  app.add_option("--posture", o->body.posture,
                 "Posture: rest, arms-5|15|30|45|90, feet-together, feet-40, lean-5, twist-5, "
                 "head-turn, joined with + (default: the model's own)");
  app.add_option("--param", o->body.params,
                 "A size or model value after the seeded draw, name=value (repeatable)");
  app.add_option("--makehuman-dir", o->body.makehuman_dir,
                 "MakeHuman data (default ../shared/data/bodies/makehuman)");
  app.add_option("-o,--output", o->output, "Body mesh to write (body frame, mm)")->required();
  app.add_option("--truth", o->truth,
                 "Write the datum points and exact reference measurements here");
  app.add_flag("--skip-reference", o->skip_reference,
               "TRUTH.json with datum points only (no exact geodesics)");
  return [o](const GlobalOptions& global) {
    o->Check();
    Body body = GenerateSynthBody(o->body);
    // Everything is computed before anything is written, so a failure leaves no half output.
    const Catalogue& catalogue = Catalogue::Builtin();
    const ReferenceOptions reference;
    ReferenceMeasurements truth;
    if (!o->truth.empty()) {
      if (o->skip_reference) {
        truth.skipped.push_back({"*", "reference measurements not computed (--skip-reference)"});
      } else {
        ProgressBar bar(global.quiet);
        truth = ComputeReferenceMeasurements(reference, catalogue, body, &bar);
      }
    }
    WriteOptions write;
    write.comment = "bespoke synth-body " + o->body.model + " seed " +
                    std::to_string(o->body.seed) + "; units mm; frame body";
    WriteMesh(write, body.mesh, o->output);
    spdlog::info("{}: {} body, {} vertices, {} faces, {} datum points", o->output.string(),
                 body.model, body.mesh.num_vertices(), body.mesh.num_faces(),
                 body.landmarks.size());
    if (!o->truth.empty()) {
      WriteTruthFile(o->truth, body, catalogue, reference, truth);
      spdlog::info("{}: {} reference measurements, {} skipped", o->truth.string(),
                   truth.measurements.size(), truth.skipped.size());
    }
    return 0;
  };
}

}  // namespace bespoke
