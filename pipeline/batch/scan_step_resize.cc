#include "pipeline/batch/scan_step_resize.h"

#include <spdlog/spdlog.h>

#include "resize/designs/designs.h"
#include "resize/ga/report.h"
#include "resize/ga/resize.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_json.h"
#include "resize/io/pattern_svg.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/json_io.h"

namespace bespoke {

void ResizeStep(JobState& s) {
  const std::string& design = s.options->design;
  const MeasurementSet body = MeasurementsFromJson(*s.measurements, "measurements.json");
  const Pattern base = DraftDesign(design, BaseMeasurements(design));
  CheckBindingsAgainst(base, body, "design " + design, "measurements.json");
  const ResizeOptions options;
  const ResizeResult result = ResizePattern(options, base, body, s.progress);
  WritePatternJson(result.fitted, s.out_dir / "fitted.json");
  WritePatternSvg(SvgOptions(), result.fitted, s.out_dir / "fitted.svg");
  WritePatternDxf(DxfWriteOptions(), result.fitted, s.out_dir / "fitted.dxf");
  const nlohmann::json settings = {{"design", design},
                                   {"seed", options.seed},
                                   {"population", options.population},
                                   {"generations", options.generations},
                                   {"tolerance_mm", options.tolerance_mm}};
  WriteJsonFile(s.out_dir / "resize_report.json", ResizeReportJson(base, body, result, settings));
  for (const char* f : {"fitted.json", "fitted.svg", "fitted.dxf", "resize_report.json"})
    s.AddOutput(f);
  s.SetResult("fit_max_measurement_error_mm", result.objectives.max_measurement_mm);
  s.SetResult("fit_max_seam_mismatch_mm", result.objectives.max_seam_length_mm);
  spdlog::info("resize: {} fitted, worst binding error {:.3f} mm", design,
               result.objectives.max_measurement_mm);
}

}  // namespace bespoke
