#include "pipeline/cli/commands.h"

#include <CLI/CLI.hpp>

namespace bespoke {

// One declaration and one table row per subcommand (pipeline/cmd_<name>.cc).
CommandRunner SetupVersionCommand(CLI::App& app);
CommandRunner SetupInfoCommand(CLI::App& app);
CommandRunner SetupCleanCommand(CLI::App& app);
CommandRunner SetupMeasureCommand(CLI::App& app);
CommandRunner SetupRunCommand(CLI::App& app);
CommandRunner SetupBatchCommand(CLI::App& app);
CommandRunner SetupBatchMergeCommand(CLI::App& app);
CommandRunner SetupGeodesicCommand(CLI::App& app);
CommandRunner SetupMeshGeodesicCommand(CLI::App& app);
CommandRunner SetupValidateCommand(CLI::App& app);
CommandRunner SetupScanSimCommand(CLI::App& app);
CommandRunner SetupSynthBodyCommand(CLI::App& app);
CommandRunner SetupSynthSetCommand(CLI::App& app);
CommandRunner SetupResizeCommand(CLI::App& app);
CommandRunner SetupDraftCommand(CLI::App& app);
CommandRunner SetupAccuracyCommand(CLI::App& app);

const std::vector<Command>& AllCommands() {
  static const std::vector<Command> commands = {
      {"version", "Print the version and the libraries Bespoke was built with",
       &SetupVersionCommand},
      {"info", "Format, points, fields, bounds and length unit of a scan or mesh file",
       &SetupInfoCommand},
      {"clean", "Clean a scan and put it in the body frame (outliers, floor, clusters, normals)",
       &SetupCleanCommand},
      {"measure",
       "Measure a scan: datum points, girths and lengths to JSON/CSV/Valentina/FreeSewing (+ a "
       "render)",
       &SetupMeasureCommand},
      {"run", "The whole job for one scan (clean, measure, fit a pattern) into one folder",
       &SetupRunCommand},
      {"batch", "Run every scan of a folder or manifest, each in its own worker process",
       &SetupBatchCommand},
      {"batch-merge", "Merge the shards of a batch (e.g. a Slurm job array) into one report",
       &SetupBatchMergeCommand},
      {"geodesic", "Geodesic length between two points, or distance field, on a scan's points",
       &SetupGeodesicCommand},
      {"mesh-geodesic",
       "Geodesics on a triangle mesh from a vertex (thesis Algorithms 1-3, or CGAL exact)",
       &SetupMeshGeodesicCommand},
      {"validate", "Compare a scan's cloud geodesics with exact ones on a reconstructed mesh",
       &SetupValidateCommand},
      {"scan-sim",
       "Simulate a body-scanner booth: a realistic noisy scan of a body mesh (+ its truth)",
       &SetupScanSimCommand},
      {"synth-body",
       "A test subject's body from a seed (parametric or MakeHuman) + its exact truth",
       &SetupSynthBodyCommand},
      {"synth-set",
       "A reproducible set of test subjects: bodies, truths and simulated scans from seeds",
       &SetupSynthSetCommand},
      {"resize", "Fit a sewing pattern to a body's measurements (multi-objective GA, thesis ch. 4)",
       &SetupResizeCommand},
      {"draft", "Draft a built-in design (shirt, trousers) directly for a body's measurements",
       &SetupDraftCommand},
      {"accuracy",
       "ISO 20685-1 accuracy report: oracle subjects against their truth (--subjects), or real "
       "subjects' scans against a tape (--scans)",
       &SetupAccuracyCommand},
  };
  return commands;
}

}  // namespace bespoke
