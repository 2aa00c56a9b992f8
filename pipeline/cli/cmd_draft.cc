// `bespoke draft --design shirt|trousers [--measurements MEAS.json] -o OUT_DIR
//                [--seam-allowance 10]`
// Drafts a built-in design directly for a body's measurements (the
// drafting system's own made-to-measure answer; resize/designs/designs.h) and
// writes pattern.json, pattern.svg (1:1 mm), pattern.dxf (ASTM layers) and
// draft.json (the measurements used and every binding's value). Without
// --measurements the design's standard size is drafted.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>

#include "pipeline/cli/commands.h"
#include "resize/designs/designs.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_json.h"
#include "resize/io/pattern_svg.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

struct DraftCommandOptions {
  std::string design;
  std::filesystem::path measurements;  // optional
  std::filesystem::path out_dir;
  double seam_allowance_mm = 10;

  void Check() const {
    if (design.empty()) throw InputError("--design is required (shirt or trousers)");
    if (out_dir.empty()) throw InputError("-o OUT_DIR is required");
    if (!(seam_allowance_mm >= 0)) throw InputError("--seam-allowance must be >= 0 mm");
  }
};

int RunDraft(const DraftCommandOptions& o) {
  o.Check();
  const MeasurementSet base = BaseMeasurements(o.design);  // also rejects unknown designs
  MeasurementSet body = base;
  if (!o.measurements.empty()) {
    const MeasurementSet read = ReadMeasurements(o.measurements);
    for (auto& [name, value] : body) {
      const auto it = read.find(name);
      if (it == read.end())
        throw InputError(o.measurements,
                         "design " + o.design + " needs measurement '" + name + "'");
      value = it->second;
    }
  }
  const Pattern pattern = DraftDesign(o.design, body);
  CreateDirectories(o.out_dir);
  WritePatternJson(pattern, o.out_dir / "pattern.json");
  SvgOptions svg;
  svg.seam_allowance_mm = o.seam_allowance_mm;
  WritePatternSvg(svg, pattern, o.out_dir / "pattern.svg");
  DxfWriteOptions dxf;
  dxf.seam_allowance_mm = o.seam_allowance_mm;
  WritePatternDxf(dxf, pattern, o.out_dir / "pattern.dxf");
  nlohmann::json bindings = nlohmann::json::array();
  for (const MeasurementBinding& b : pattern.bindings)
    bindings.push_back({{"binding", b.id},
                        {"measurement", b.measurement},
                        {"body_mm", body.at(b.measurement)},
                        {"ease_mm", b.ease_mm},
                        {"pattern_mm", BindingValue(pattern, b)}});
  WriteJsonFile(o.out_dir / "draft.json", {{"design", o.design},
                                           {"source", pattern.source},
                                           {"measurements", o.measurements.string()},
                                           {"body", body},
                                           {"bindings", bindings},
                                           {"seam_allowance_mm", o.seam_allowance_mm}});
  spdlog::info("drafted {} ({} pieces) into {}", o.design, pattern.pieces.size(),
               o.out_dir.string());
  return 0;
}

}  // namespace

CommandRunner SetupDraftCommand(CLI::App& app) {
  auto o = std::make_shared<DraftCommandOptions>();
  app.add_option("--design", o->design, "shirt or trousers")->required();
  app.add_option("--measurements", o->measurements,
                 "MEAS.json or TRUTH.json (default: standard size)");
  app.add_option("-o,--out", o->out_dir, "Output folder")->required();
  app.add_option("--seam-allowance", o->seam_allowance_mm, "Cut-line allowance in SVG/DXF (mm)");
  return [o](const GlobalOptions&) { return RunDraft(*o); };
}

}  // namespace bespoke
