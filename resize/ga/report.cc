#include "resize/ga/report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "resize/pattern/design_points.h"
#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

using nlohmann::json;

double Wrap(double a) {
  while (a > M_PI) a -= 2 * M_PI;
  while (a < -M_PI) a += 2 * M_PI;
  return a;
}

std::string Fmt(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, v);
  return buffer;
}

}  // namespace

std::vector<PieceShapeChange> ShapeChanges(const Pattern& base, const Pattern& fitted) {
  std::vector<PieceShapeChange> changes;
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const Piece &a = base.pieces[p], &b = fitted.pieces[p];
    const Eigen::VectorXd ta = TurningAngles(a.outline), tb = TurningAngles(b.outline);
    PieceShapeChange c;
    c.piece = a.name;
    for (Eigen::Index v = 0; v < ta.size(); ++v) {
      const double d = std::abs(Wrap(tb[v] - ta[v])) * 180 / M_PI;
      c.mean_angle_change_deg += d / static_cast<double>(ta.size());
      c.max_angle_change_deg = std::max(c.max_angle_change_deg, d);
    }
    for (int v : a.critical)
      c.critical_angle_change_deg +=
          std::abs(Wrap(tb[v] - ta[v])) * 180 / M_PI / static_cast<double>(a.critical.size());
    c.area_ratio = SignedArea(b.outline) / SignedArea(a.outline);
    c.width_mm = b.outline.col(0).maxCoeff() - b.outline.col(0).minCoeff();
    c.height_mm = b.outline.col(1).maxCoeff() - b.outline.col(1).minCoeff();
    changes.push_back(c);
  }
  return changes;
}

namespace {

double DirectionDeg(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(Wrap(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()))) * 180 / M_PI;
}

// Sign changes of the turning angle along the curves (CurveVertices of the
// base), among vertices that turn by 1e-3 rad or more; any other vertex ends
// a curve.
int Inflections(const Eigen::VectorXd& turning, const std::vector<bool>& curve) {
  int count = 0, last = 0;
  constexpr double kMinRad = 1e-3;
  for (Eigen::Index v = 0; v < turning.size(); ++v) {
    if (!curve[v]) {
      last = 0;
      continue;
    }
    if (std::abs(turning[v]) < kMinRad) continue;
    const int sign = turning[v] > 0 ? 1 : -1;
    if (last != 0 && sign != last) ++count;
    last = sign;
  }
  return count;
}

}  // namespace

std::vector<StructureFigures> StructureChanges(const Pattern& base, const Pattern& fitted) {
  std::vector<StructureFigures> all;
  for (size_t p = 0; p < base.pieces.size(); ++p) {
    const Piece &a = base.pieces[p], &b = fitted.pieces[p];
    const int n = a.num_vertices();
    StructureFigures f;
    f.piece = a.name;
    std::vector<bool> on_run(n, false);
    for (const StraightRun& r : a.straight) {
      const Eigen::Vector2d p0 = b.outline.row(r.from),
                            d = Eigen::Vector2d(b.outline.row(r.to)) - p0;
      for (int v = r.from; v != r.to; v = (v + 1) % n) {
        on_run[v] = true;
        const Eigen::Vector2d q = Eigen::Vector2d(b.outline.row(v)) - p0;
        f.max_kink_mm = std::max(
            f.max_kink_mm, std::abs(d.x() * q.y() - d.y() * q.x()) / std::max(d.norm(), 1e-9));
      }
      on_run[r.to] = true;
      if (r.fold)
        f.max_fold_tilt_deg =
            std::max(f.max_fold_tilt_deg,
                     DirectionDeg(Eigen::Vector2d(a.outline.row(r.to) - a.outline.row(r.from)), d));
    }
    for (const LevelLine& l : a.level_lines) {
      const int i = a.FindLandmark(l.from), j = a.FindLandmark(l.to);
      f.max_level_tilt_deg = std::max(f.max_level_tilt_deg,
                                      DirectionDeg(a.LandmarkPosition(j) - a.LandmarkPosition(i),
                                                   b.LandmarkPosition(j) - b.LandmarkPosition(i)));
    }
    if (a.has_grain)
      f.max_grain_tilt_deg = DirectionDeg(a.grain_end - a.grain_start, b.grain_end - b.grain_start);
    const Eigen::VectorXd ta = TurningAngles(a.outline), tb = TurningAngles(b.outline);
    for (int v : a.right_angles)
      f.max_corner_change_deg =
          std::max(f.max_corner_change_deg, std::abs(Wrap(tb[v] - ta[v])) * 180 / M_PI);
    for (const Dart& d : a.darts)
      f.max_dart_mismatch_mm =
          std::max(f.max_dart_mismatch_mm,
                   std::abs((b.outline.row(d.leg_a) - b.outline.row(d.apex)).norm() -
                            (b.outline.row(d.leg_b) - b.outline.row(d.apex)).norm()));
    for (const NotchRun& run : NotchRuns(base, static_cast<int>(p)))
      f.max_notch_shift_mm = std::max(f.max_notch_shift_mm, std::abs(NotchShift(b.outline, run)));
    const std::vector<bool> curve = CurveVertices(a.outline, on_run);
    f.new_inflections = std::max(0, Inflections(tb, curve) - Inflections(ta, curve));
    all.push_back(f);
  }
  return all;
}

std::vector<DesignDimensionFigures> DesignDimensionChanges(const Pattern& base,
                                                           const ResizeResult& r) {
  std::vector<DesignDimensionFigures> all;
  for (const DesignDimension& d : FindDesignDimensions(base))
    all.push_back({d.piece, DesignDimensionName(d.kind), MeasureDesignDimension(base, d),
                   MeasureDesignDimension(r.seed, d), MeasureDesignDimension(r.graded, d),
                   MeasureDesignDimension(r.fitted, d)});
  return all;
}

json ObjectivesJson(const Objectives& o) {
  return {{"measurement_mm", o.measurement_mm},
          {"seam", o.seam},
          {"shape_deg", o.shape_deg},
          {"max_measurement_error_mm", o.max_measurement_mm},
          {"critical_shape_deg", o.critical_shape_deg},
          {"max_seam_mismatch_mm", o.max_seam_length_mm},
          {"outlines_simple", o.simple}};
}

json ResizeReportJson(const Pattern& base, const MeasurementSet& body, const ResizeResult& r,
                      const json& settings) {
  json measurements = json::array();
  for (size_t b = 0; b < base.bindings.size(); ++b) {
    const MeasurementBinding& binding = base.bindings[b];
    const bool measured = !binding.fixed && binding.follows.empty();
    const double body_mm = measured ? body.at(binding.measurement) : 0.0;
    measurements.push_back(
        {{"binding", binding.id},
         {"measurement", binding.fixed              ? "(fixed)"
                         : !binding.follows.empty() ? "(follows " + binding.follows + ")"
                                                    : binding.measurement},
         {"body_mm", body_mm},
         {"ease_mm", r.targets_mm[b] - body_mm},
         {"ease_percent", binding.ease_percent},
         {"target_mm", r.targets_mm[b]},
         {"achieved_mm", r.achieved_mm[b]},
         {"error_mm", r.achieved_mm[b] - r.targets_mm[b]},
         {"base_pattern_mm", BindingValue(base, binding)},
         {"proportional_grading_mm", BindingValue(r.seed, binding)},
         {"graded_start_mm", BindingValue(r.graded, binding)}});
  }
  json seams = json::array();
  for (size_t s = 0; s < base.seams.size(); ++s) {
    const Seam& seam = base.seams[s];
    const Pattern& f = r.fitted;
    seams.push_back({{"seam", seam.name},
                     {"a", seam.a.piece},
                     {"b", seam.b.piece},
                     {"length_a_mm", SeamLength(f.pieces[f.FindPiece(seam.a.piece)], seam.a)},
                     {"length_b_mm", SeamLength(f.pieces[f.FindPiece(seam.b.piece)], seam.b)},
                     {"ease_mm", seam.ease_mm},
                     {"mismatch_mm", r.seam_mismatch_mm[s]}});
  }
  json pieces = json::array();
  for (const PieceShapeChange& c : ShapeChanges(base, r.fitted))
    pieces.push_back({{"piece", c.piece},
                      {"mean_angle_change_deg", c.mean_angle_change_deg},
                      {"max_angle_change_deg", c.max_angle_change_deg},
                      {"critical_angle_change_deg", c.critical_angle_change_deg},
                      {"area_ratio", c.area_ratio},
                      {"width_mm", c.width_mm},
                      {"height_mm", c.height_mm}});
  json structure = json::array();
  for (const StructureFigures& f : StructureChanges(base, r.fitted))
    structure.push_back({{"piece", f.piece},
                         {"max_kink_mm", f.max_kink_mm},
                         {"max_level_tilt_deg", f.max_level_tilt_deg},
                         {"max_fold_tilt_deg", f.max_fold_tilt_deg},
                         {"max_grain_tilt_deg", f.max_grain_tilt_deg},
                         {"max_corner_change_deg", f.max_corner_change_deg},
                         {"max_dart_mismatch_mm", f.max_dart_mismatch_mm},
                         {"max_notch_shift_mm", f.max_notch_shift_mm},
                         {"new_inflections", f.new_inflections}});
  json dimensions = json::array();
  for (const DesignDimensionFigures& d : DesignDimensionChanges(base, r))
    dimensions.push_back({{"piece", d.piece},
                          {"dimension", d.name},
                          {"base_pattern_mm", d.base_mm},
                          {"proportional_grading_mm", d.grading_mm},
                          {"graded_start_mm", d.graded_mm},
                          {"fitted_mm", d.fit_mm}});
  json history = json::array();
  for (const GenerationStats& g : r.history)
    history.push_back({{"generation", g.generation},
                       {"best_measurement_mm", g.best_measurement_mm},
                       {"best_seam", g.best_seam},
                       {"best_shape_deg", g.best_shape_deg}});
  return {{"format", "bespoke-resize-report"},
          {"version", 1},
          {"pattern", base.name},
          {"settings", settings},
          {"objectives",
           {{"final", ObjectivesJson(r.objectives)},
            {"ga_pick", ObjectivesJson(r.ga_objectives)},
            {"proportional_seed", ObjectivesJson(r.seed_objectives)},
            {"shape_reference", r.shape_reference}}},
          {"polish",
           {{"start", r.polish_start},
            {"iterations", r.polish.iterations},
            {"max_constraint_before_mm", r.polish.max_constraint_before_mm},
            {"max_constraint_after_mm", r.polish.max_constraint_after_mm},
            {"change", r.polish.change}}},
          {"pareto_front_size", r.front.size()},
          {"time_s", {{"ga", r.ga_time_s}, {"polish", r.polish_time_s}}},
          {"measurements", measurements},
          {"seams", seams},
          {"pieces", pieces},
          {"structure", structure},
          {"design_dimensions", dimensions},
          {"history", history}};
}

std::string ResizeReportText(const json& report) {
  std::ostringstream s;
  s << "Bespoke resize report: pattern '" << report["pattern"].get<std::string>() << "'\n\n";
  s << "Measurements (mm)      body     ease    target  achieved    error  prop.grading"
       "  graded start\n";
  for (const json& m : report["measurements"]) {
    char line[240];
    std::snprintf(line, sizeof(line), "  %-18s %8.1f %8.1f %9.1f %9.1f %8.2f %12.1f %13.1f\n",
                  m["binding"].get<std::string>().c_str(), m["body_mm"].get<double>(),
                  m["ease_mm"].get<double>(), m["target_mm"].get<double>(),
                  m["achieved_mm"].get<double>(), m["error_mm"].get<double>(),
                  m["proportional_grading_mm"].get<double>(), m["graded_start_mm"].get<double>());
    s << line;
  }
  s << "\nSeams (mm)             side a   side b     ease  mismatch\n";
  for (const json& m : report["seams"]) {
    char line[200];
    std::snprintf(line, sizeof(line), "  %-18s %8.1f %8.1f %8.1f %9.2f\n",
                  m["seam"].get<std::string>().c_str(), m["length_a_mm"].get<double>(),
                  m["length_b_mm"].get<double>(), m["ease_mm"].get<double>(),
                  m["mismatch_mm"].get<double>());
    s << line;
  }
  s << "\nShape change per piece  mean deg  max deg  critical deg  area ratio  width x height mm\n";
  for (const json& m : report["pieces"]) {
    char line[200];
    std::snprintf(line, sizeof(line), "  %-18s %9.3f %8.3f %13.3f %11.3f  %6.0f x %.0f\n",
                  m["piece"].get<std::string>().c_str(), m["mean_angle_change_deg"].get<double>(),
                  m["max_angle_change_deg"].get<double>(),
                  m["critical_angle_change_deg"].get<double>(), m["area_ratio"].get<double>(),
                  m["width_mm"].get<double>(), m["height_mm"].get<double>());
    s << line;
  }
  s << "\nStructure vs base       kink mm  level deg  fold deg  grain deg  corner deg  dart mm"
       "  notch mm  new inflections\n";
  for (const json& m : report["structure"]) {
    char line[240];
    std::snprintf(line, sizeof(line), "  %-18s %9.3f %10.3f %9.3f %10.3f %11.3f %8.3f %9.3f %16d\n",
                  m["piece"].get<std::string>().c_str(), m["max_kink_mm"].get<double>(),
                  m["max_level_tilt_deg"].get<double>(), m["max_fold_tilt_deg"].get<double>(),
                  m["max_grain_tilt_deg"].get<double>(), m["max_corner_change_deg"].get<double>(),
                  m["max_dart_mismatch_mm"].get<double>(), m["max_notch_shift_mm"].get<double>(),
                  m["new_inflections"].get<int>());
    s << line;
  }
  if (report.contains("design_dimensions") && !report["design_dimensions"].empty()) {
    s << "\nDesign dimensions (mm)          base  prop.grading  graded start    fitted\n";
    for (const json& m : report["design_dimensions"]) {
      char line[240];
      std::snprintf(line, sizeof(line), "  %-14s %-14s %7.1f %13.1f %13.1f %9.1f\n",
                    m["piece"].get<std::string>().c_str(),
                    m["dimension"].get<std::string>().c_str(), m["base_pattern_mm"].get<double>(),
                    m["proportional_grading_mm"].get<double>(), m["graded_start_mm"].get<double>(),
                    m["fitted_mm"].get<double>());
      s << line;
    }
  }
  s << "\nObjectives (as thesis Table 4.2: measurement Eq 4.5 mm, seam Eq 4.8, shape deg from the "
    << report["objectives"]["shape_reference"].get<std::string>() << ")\n";
  for (const char* which : {"proportional_seed", "ga_pick", "final"}) {
    const json& o = report["objectives"][which];
    s << "  " << which << ": measurement " << Fmt("%.3f", o["measurement_mm"].get<double>())
      << ", seam " << Fmt("%.3f", o["seam"].get<double>()) << ", shape "
      << Fmt("%.3f", o["shape_deg"].get<double>()) << " (worst binding "
      << Fmt("%.3f", o["max_measurement_error_mm"].get<double>()) << " mm, worst seam "
      << Fmt("%.3f", o["max_seam_mismatch_mm"].get<double>()) << " mm)\n";
  }
  s << "\nPolish started from the " << report["polish"]["start"].get<std::string>() << "; time: GA "
    << Fmt("%.2f", report["time_s"]["ga"].get<double>()) << " s, polish "
    << Fmt("%.2f", report["time_s"]["polish"].get<double>()) << " s\n";
  return s.str();
}

std::string ParetoFrontCsv(const ResizeResult& r) {
  std::ostringstream s;
  s << "measurement_mm,seam,shape_deg,max_measurement_error_mm,critical_shape_deg,"
       "max_seam_mismatch_mm\n";
  for (const Objectives& o : r.front)
    s << o.measurement_mm << "," << o.seam << "," << o.shape_deg << "," << o.max_measurement_mm
      << "," << o.critical_shape_deg << "," << o.max_seam_length_mm << "\n";
  return s.str();
}

}  // namespace bespoke
