// Evidence for resizing a shop's own pattern: a pattern drafted by another
// system at its standard size (a DXF with a sidecar) is resized to a second
// body, and every piece is compared with the same system's own draft for
// that body (a second DXF, pieces matched by name), against plain
// proportional grading (Algorithm 6) and the graded start. Outlines need not
// correspond vertex by vertex: CompareOutlineShapes aligns them rigidly and
// measures the mean distance between them (eval/resize/evidence.h).
//
//   resize_shop_pattern --pattern STD.dxf --sidecar SIDECAR.json
//                       --measurements BIG.vit --draft BIG.dxf
//                       [--population 400] [--generations 200] [--seed 1]
//
// Prints one row per piece (distances to the draft; structure figures of
// the fit against the base: largest kink on a straight run, level-line and
// fold tilt, square-corner change, dart legs) and exits 1 when a piece is
// farther from the draft than grading (by more than 0.05 mm, the measuring
// noise for pieces the draft leaves unchanged), a kink exceeds 1 mm or a level
// line tilts more than 0.5 deg.
#include <cstdio>
#include <cstring>
#include <string>

#include "eval/bench/bench_main.h"
#include "eval/resize/evidence.h"
#include "resize/ga/report.h"
#include "resize/ga/resize.h"
#include "resize/io/measurements_io.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_io.h"
#include "scanners/core/errors.h"

namespace {
int Run(int argc, char** argv) {
  using namespace bespoke;
  std::string pattern_file, sidecar, measurements, draft_file;
  ResizeOptions options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--pattern")
      pattern_file = value;
    else if (key == "--sidecar")
      sidecar = value;
    else if (key == "--measurements")
      measurements = value;
    else if (key == "--draft")
      draft_file = value;
    else if (key == "--population")
      options.population = std::stoi(value);
    else if (key == "--generations")
      options.generations = std::stoi(value);
    else if (key == "--seed")
      options.seed = std::stoull(value);
    else
      throw InputError("unknown option " + key);
  }
  if (pattern_file.empty() || measurements.empty() || draft_file.empty())
    throw InputError(
        "usage: resize_shop_pattern --pattern STD.dxf --sidecar S.json "
        "--measurements BIG.vit --draft BIG.dxf");
  const Pattern base = LoadPattern(pattern_file, sidecar);
  const MeasurementSet body = LoadMeasurements(measurements);
  const Pattern draft = ReadPatternDxf(draft_file);
  const ResizeResult r = ResizePattern(options, base, body, nullptr);
  const std::vector<StructureFigures> structure = StructureChanges(base, r.fitted);
  std::printf(
      "| piece | fit-draft mean/max mm | grading-draft mean/max mm | graded start-draft mean mm | "
      "fit / grading | kink mm | level tilt deg | fold tilt deg | corner deg | dart mm | "
      "new inflections |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  double fit_sum = 0, grading_sum = 0;
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const int d = draft.FindPiece(base.pieces[p].name);
    if (d < 0) throw InputError(draft_file + " has no piece '" + base.pieces[p].name + "'");
    const PatternDistance fit =
        CompareOutlineShapes(draft.pieces[d].outline, r.fitted.pieces[p].outline);
    const PatternDistance grading =
        CompareOutlineShapes(draft.pieces[d].outline, r.seed.pieces[p].outline);
    const PatternDistance graded =
        CompareOutlineShapes(draft.pieces[d].outline, r.graded.pieces[p].outline);
    const StructureFigures& s = structure[p];
    const bool ok =
        fit.mean_mm <= grading.mean_mm + 0.05 && s.max_kink_mm <= 1 && s.max_level_tilt_deg <= 0.5;
    failures += ok ? 0 : 1;
    fit_sum += fit.mean_mm;
    grading_sum += grading.mean_mm;
    std::printf(
        "| %s | %.1f / %.1f | %.1f / %.1f | %.1f | %.2f | %.3f | %.3f | %.3f | %.3f | %.3f | %d "
        "|%s\n",
        base.pieces[p].name.c_str(), fit.mean_mm, fit.max_mm, grading.mean_mm, grading.max_mm,
        graded.mean_mm, fit.mean_mm / std::max(grading.mean_mm, 1e-9), s.max_kink_mm,
        s.max_level_tilt_deg, s.max_fold_tilt_deg, s.max_corner_change_deg, s.max_dart_mismatch_mm,
        s.new_inflections, ok ? "" : " **miss**");
  }
  std::printf(
      "\nworst binding %.3f mm, worst seam %.3f mm, structure rules %.3f mm, time GA %.2f s + "
      "polish %.2f s\n",
      r.objectives.max_measurement_mm, r.objectives.max_seam_length_mm,
      r.objectives.max_structure_mm, r.ga_time_s, r.polish_time_s);
  std::printf("mean over pieces: fit %.2f mm, grading %.2f mm\n%zu passed, %d failed\n",
              fit_sum / base.pieces.size(), grading_sum / base.pieces.size(),
              base.pieces.size() - failures, failures);
  return failures == 0 ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("resize_shop_pattern", Run, argc, argv);
}
