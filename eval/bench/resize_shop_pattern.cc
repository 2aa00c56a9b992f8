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
//                       [--overlay OVERLAY.png] [--overlay-pieces A,B,...] [--write DIR]
//
// Prints one row per piece (distances to the draft; structure figures of
// the fit against the base: largest kink on a straight run, level-line and
// fold tilt, square-corner change, dart legs, notch shift from its fraction
// of its run), then the sleeve cap heights and armhole depths (base,
// grading, graded start, fit; the draft's cap height found from its shape
// on the base cap's side, design_points.h InferredCapHeight), and exits 1
// when a piece is farther from the draft than grading (by more than 0.05
// mm, the measuring noise for pieces the draft leaves unchanged), a kink
// exceeds 1 mm, a level, fold or grain line tilts more than 0.5 deg, a notch
// shifts more than 1 mm or a curve gains an inflection.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "eval/bench/bench_main.h"
#include "eval/resize/evidence.h"
#include "resize/ga/report.h"
#include "resize/ga/resize.h"
#include "resize/io/measurements_io.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_io.h"
#include "resize/io/pattern_json.h"
#include "resize/io/pattern_overlay.h"
#include "resize/pattern/design_points.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace {

bespoke::OverlayLayer Layer(const char* label, const bespoke::Pattern* pattern,
                            std::array<double, 3> color, double line_px, bool dashed = false) {
  bespoke::OverlayLayer layer;
  layer.label = label;
  layer.pattern = pattern;
  layer.color = color;
  layer.line_px = line_px;
  layer.dashed = dashed;
  return layer;
}

std::string Format(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, v);
  return buffer;
}

int Run(int argc, char** argv) {
  using namespace bespoke;
  std::string pattern_file, sidecar, measurements, draft_file, overlay, write_dir;
  OverlayOptions overlay_options;
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
    else if (key == "--overlay")
      overlay = value;
    else if (key == "--write")
      write_dir = value;
    else if (key == "--overlay-pieces") {
      std::stringstream list(value);
      for (std::string piece; std::getline(list, piece, ',');)
        overlay_options.pieces.push_back(piece);
      overlay_options.px_per_mm = 1.2;
    } else
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
      "notch mm | new inflections |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  double fit_sum = 0, grading_sum = 0;
  OverlayLayer draft_layer = Layer("draft for the body (aligned)", &draft, {0.1, 0.6, 0.1}, 2.5);
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const int d = draft.FindPiece(base.pieces[p].name);
    if (d < 0) throw InputError(draft_file + " has no piece '" + base.pieces[p].name + "'");
    Eigen::Matrix<double, 2, 3> placement;
    CompareOutlineShapes(r.fitted.pieces[p].outline, draft.pieces[d].outline, 2, &placement);
    draft_layer.placement[base.pieces[p].name] = placement;
    const PatternDistance fit =
        CompareOutlineShapes(draft.pieces[d].outline, r.fitted.pieces[p].outline);
    const PatternDistance grading =
        CompareOutlineShapes(draft.pieces[d].outline, r.seed.pieces[p].outline);
    const PatternDistance graded =
        CompareOutlineShapes(draft.pieces[d].outline, r.graded.pieces[p].outline);
    const StructureFigures& s = structure[p];
    const bool ok =
        fit.mean_mm <= grading.mean_mm + 0.05 && s.max_kink_mm <= 1 &&
        std::max({s.max_level_tilt_deg, s.max_fold_tilt_deg, s.max_grain_tilt_deg}) <= 0.5 &&
        s.max_notch_shift_mm <= 1 && s.new_inflections == 0;
    failures += ok ? 0 : 1;
    fit_sum += fit.mean_mm;
    grading_sum += grading.mean_mm;
    std::printf(
        "| %s | %.1f / %.1f | %.1f / %.1f | %.1f | %.2f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f "
        "| %d |%s\n",
        base.pieces[p].name.c_str(), fit.mean_mm, fit.max_mm, grading.mean_mm, grading.max_mm,
        graded.mean_mm, fit.mean_mm / std::max(grading.mean_mm, 1e-9), s.max_kink_mm,
        s.max_level_tilt_deg, s.max_fold_tilt_deg, s.max_corner_change_deg, s.max_dart_mismatch_mm,
        s.max_notch_shift_mm, s.new_inflections, ok ? "" : " **miss**");
  }
  std::printf(
      "\n| piece | dimension | base mm | grading mm | graded start mm | fit mm | draft mm |\n"
      "|---|---|---|---|---|---|---|\n");
  const std::vector<DesignDimension> found = FindDesignDimensions(base);
  const std::vector<DesignDimensionFigures> figures = DesignDimensionChanges(base, r);
  for (size_t i = 0; i < figures.size(); ++i) {
    const DesignDimensionFigures& d = figures[i];
    // The draft has no landmarks: its cap is found from its shape, on the
    // side the base's cap is.
    const int k = draft.FindPiece(d.piece);
    const std::string drafted =
        found[i].kind == DesignDimension::Kind::kCapHeight && k >= 0
            ? Format("%.1f", InferredCapHeight(draft.pieces[k], CapDirection(base, found[i])))
            : std::string("-");
    std::printf("| %s | %s | %.1f | %.1f | %.1f | %.1f | %s |\n", d.piece.c_str(), d.name.c_str(),
                d.base_mm, d.grading_mm, d.graded_mm, d.fit_mm, drafted.c_str());
  }
  std::printf(
      "\nworst binding %.3f mm, worst seam %.3f mm, structure rules %.3f mm, time GA %.2f s + "
      "polish %.2f s\n",
      r.objectives.max_measurement_mm, r.objectives.max_seam_length_mm,
      r.objectives.max_structure_mm, r.ga_time_s, r.polish_time_s);
  if (!write_dir.empty()) {
    CreateDirectories(write_dir);
    WritePatternJson(base, std::filesystem::path(write_dir) / "base.json");
    WritePatternJson(r.graded, std::filesystem::path(write_dir) / "graded.json");
    WritePatternJson(r.seed, std::filesystem::path(write_dir) / "grading.json");
    WritePatternJson(r.fitted, std::filesystem::path(write_dir) / "fitted.json");
  }
  if (!overlay.empty())
    WritePatternOverlay(overlay_options,
                        {Layer("base", &base, {0.55, 0.55, 0.55}, 1.0),
                         Layer("proportional grading", &r.seed, {0.95, 0.6, 0.1}, 1.0, true),
                         Layer("graded start", &r.graded, {0.2, 0.4, 0.9}, 1.0, true), draft_layer,
                         Layer("fitted", &r.fitted, {0.85, 0.1, 0.1}, 1.2)},
                        overlay);
  std::printf(
      "graded start: worst binding or seam %.3f mm; GA pick: measurement %.3f mm, seam "
      "%.3f, shape %.3f deg\n",
      r.graded_constraint_mm, r.ga_objectives.measurement_mm, r.ga_objectives.seam,
      r.ga_objectives.shape_deg);
  std::printf("mean over pieces: fit %.2f mm, grading %.2f mm\n%zu passed, %d failed\n",
              fit_sum / base.pieces.size(), grading_sum / base.pieces.size(),
              base.pieces.size() - failures, failures);
  return failures == 0 ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("resize_shop_pattern", Run, argc, argv);
}
