// `bespoke scan-sim BODY.obj -o SCAN.ply [--truth TRUTH.json [--truth-out F]]
//  [--preview PNG] [--body-units U] + the scanner options (pipeline/cli/scan_sim_cli.h:
//  --seed --noise-mm --booth --sensors --resolution --outliers --floor/--no-floor
//  --stray-objects --transform --units --misalign-mm --misalign-deg --pcd --labels)`
// Simulates a body-scanner booth looking at BODY (a closed mesh in the body
// frame; its unit guessed from its size unless --body-units) and writes the
// scan in the scanner frame and the chosen unit (PLY with normals; PCD too
// with --pcd), SCAN.scan.json (settings and counts) and, with --truth, the
// truth carried into the scanner frame (default SCAN.truth.json).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "pipeline/cli/scan_sim_cli.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct ScanSimCommandOptions {
  std::filesystem::path body;       // input mesh (required)
  std::filesystem::path output;     // SCAN.ply (required)
  std::filesystem::path truth;      // the body's TRUTH.json (optional)
  std::filesystem::path truth_out;  // default SCAN.truth.json
  std::filesystem::path preview;    // PNG (optional)
  std::string body_units;           // "" = guess from the size
  ScanSimCli scanner;
  void Check() const {
    if (output.extension() != ".ply")
      throw InputError(output, "the scan must be a .ply file (add --pcd for PCD)");
    if (!body_units.empty() && !ParseLengthUnit(body_units)) {
      throw InputError("--body-units must be mm, cm, dm or m, not '" + body_units + "'");
    }
    if (!truth_out.empty() && truth.empty()) throw InputError("--truth-out needs --truth");
    if (!preview.empty() && preview.extension() != ".png")
      throw InputError(preview, "--preview must be a .png file");
    scanner.Check();
  }
};

}  // namespace

CommandRunner SetupScanSimCommand(CLI::App& app) {
  auto o = std::make_shared<ScanSimCommandOptions>();
  app.add_option("BODY", o->body, "Body mesh in the body frame (.obj .ply .off .stl)")->required();
  app.add_option("-o,--output", o->output, "Scan to write (.ply)")->required();
  app.add_option("--truth", o->truth, "The body's TRUTH.json, carried over into the scanner frame");
  app.add_option("--truth-out", o->truth_out,
                 "Where to write the scan's truth (default SCAN.truth.json)");
  app.add_option("--body-units", o->body_units,
                 "BODY's length unit: mm, cm, dm or m (default: guessed)");
  app.add_option("--preview", o->preview, "Also draw the scan (front, side, back) into this PNG");
  AddScanSimOptions(app, &o->scanner);
  return [o](const GlobalOptions& global) {
    o->Check();
    ReadOptions read;
    if (!o->body_units.empty()) read.units = ParseLengthUnit(o->body_units);
    Mesh mesh = ReadMesh(read, o->body);
    mesh.mesh.vertices *= MillimetresPer(mesh.report.unit);
    ScanSimFiles files;
    files.scan = o->output;
    files.truth_in = o->truth;
    files.truth_out = o->truth_out;
    files.preview = o->preview;
    o->scanner.Apply(&files);
    ProgressBar bar(global.quiet);
    const ScanSimResult r = SimulateScanToFiles(o->scanner.ToOptions(), files, mesh.mesh, &bar);
    spdlog::info("{}: {} points ({} body, {} floor, {} stray, {} outliers) from {} rays, in {}",
                 o->output.string(), r.cloud.size(), r.counts[0], r.counts[1], r.counts[2],
                 r.counts[3], r.rays, o->scanner.units);
    return 0;
  };
}

}  // namespace bespoke
