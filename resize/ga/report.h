// The resize report: per measurement target vs achieved, per seam the length
// mismatch, per piece the shape change, the objective values as thesis Table
// 4.2 lists them (GA pick, after the polish, proportional seed), timings; as
// JSON, as a readable text summary, and the Pareto front as CSV.
#ifndef BESPOKE_RESIZE_GA_REPORT_H_
#define BESPOKE_RESIZE_GA_REPORT_H_

#include <nlohmann/json.hpp>
#include <string>

#include "resize/ga/resize.h"

namespace bespoke {

// Per-piece shape change of `fitted` against `base` (same vertex counts).
struct PieceShapeChange {
  std::string piece;
  double mean_angle_change_deg = 0;  // over all outline vertices
  double max_angle_change_deg = 0;
  double critical_angle_change_deg = 0;  // mean over critical points
  double area_ratio = 1;                 // fitted area / base area
  double width_mm = 0, height_mm = 0;    // fitted bounding box
};
std::vector<PieceShapeChange> ShapeChanges(const Pattern& base, const Pattern& fitted);

// How well a piece's structure survived (fitted against base, same vertex
// counts), for a tailor's check: the largest kink on a straight run (an inner
// vertex's distance from its run's chord, mm), the largest tilt of a level
// line, fold or grain line (deg), the largest change of a square corner's
// angle (deg), the largest dart leg-length difference (mm), the largest
// shift of a notch along the outline from its base fraction between the
// structure points that bound it (design_points.h NotchShift, mm), and the
// number of new inflections on curved parts of the outline.
struct StructureFigures {
  std::string piece;
  double max_kink_mm = 0;
  double max_level_tilt_deg = 0;
  double max_fold_tilt_deg = 0;
  double max_grain_tilt_deg = 0;
  double max_corner_change_deg = 0;
  double max_dart_mismatch_mm = 0;
  double max_notch_shift_mm = 0;
  int new_inflections = 0;
};
std::vector<StructureFigures> StructureChanges(const Pattern& base, const Pattern& fitted);

// A design dimension (design_points.h: sleeve cap height, armhole depth) on
// the base, proportional grading, the graded start and the fit, mm.
struct DesignDimensionFigures {
  std::string piece, name;
  double base_mm = 0, grading_mm = 0, graded_mm = 0, fit_mm = 0;
};
std::vector<DesignDimensionFigures> DesignDimensionChanges(const Pattern& base,
                                                           const ResizeResult& result);

nlohmann::json ObjectivesJson(const Objectives& o);

// The full report. `settings` is stored as given (the options used).
nlohmann::json ResizeReportJson(const Pattern& base, const MeasurementSet& body,
                                const ResizeResult& result, const nlohmann::json& settings);
std::string ResizeReportText(const nlohmann::json& report);

// One row per first-front member: measurement_mm,seam,shape_deg,...
std::string ParetoFrontCsv(const ResizeResult& result);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_REPORT_H_
