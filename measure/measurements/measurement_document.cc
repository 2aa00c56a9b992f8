#include "measure/measurements/measurement_document.h"

#include <cmath>
#include <cstdio>

#include "scanners/core/atomic_file.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

double Round2(double x) { return std::round(x * 100.0) / 100.0; }

nlohmann::json Point(const Eigen::Vector3d& p) {
  return {Round2(p.x()), Round2(p.y()), Round2(p.z())};
}

nlohmann::json MeasurementJson(const Measurement& m, bool with_geometry) {
  nlohmann::json j = {
      {"name", m.name},   {"kind", ToString(m.kind)},     {"value_mm", Round2(m.value_mm)},
      {"flags", m.flags}, {"method", ToString(m.method)}, {"datum", m.datum}};
  if (!m.uncertain_landmarks.empty()) j["uncertain_landmarks"] = m.uncertain_landmarks;
  j["uncertainty_mm"] = Round2(m.uncertainty_mm);
  if (m.method == MeasurementMethod::kGeodesic) j["bridged_mm"] = Round2(m.bridged_mm);
  if (m.kind == MeasurementKind::kGirth) {
    j["largest_gap_mm"] = Round2(m.largest_gap_mm);
    j["plane"] = {{"point", Point(m.plane_point)}, {"normal", ToJson(m.plane_normal)}};
  }
  if (with_geometry) {
    nlohmann::json g = nlohmann::json::array();
    for (Eigen::Index i = 0; i < m.geometry.rows(); ++i)
      g.push_back(Point(m.geometry.row(i).transpose()));
    j["geometry"] = std::move(g);
  }
  return j;
}

std::string Joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ";") + s;
  return out;
}

// RFC 4180 quoting where needed.
std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

nlohmann::json MeasurementDocument(const MeasureResult& result, const LandmarkSet& landmarks,
                                   const nlohmann::json& extra, bool with_geometry) {
  nlohmann::json doc = {{"format", "bespoke-measurements"},
                        {"version", 1},
                        {"units", "mm"},
                        {"frame", "body"},
                        {"source", "scan"}};
  nlohmann::json points = nlohmann::json::object(), details = nlohmann::json::object();
  for (const auto& [name, l] : landmarks.points) {
    points[name] = Point(l.position_mm);
    details[name] = {{"confidence", l.confidence}, {"flags", l.flags}, {"method", l.method}};
  }
  doc["landmarks"] = std::move(points);
  doc["landmark_details"] = std::move(details);
  doc["landmarks_missing"] = landmarks.missing;
  nlohmann::json measurements = nlohmann::json::array();
  for (const Measurement& m : result.measurements)
    measurements.push_back(MeasurementJson(m, with_geometry));
  doc["measurements"] = std::move(measurements);
  nlohmann::json skipped = nlohmann::json::array();
  for (const auto& [name, reason] : result.skipped)
    skipped.push_back({{"name", name}, {"reason", reason}});
  doc["skipped"] = std::move(skipped);
  const ScanSampling& q = result.sampling;
  doc["scan_sampling"] = {{"noise_mm", q.noise_mm},
                          {"spacing_mm", q.spacing_mm},
                          {"surface_spacing_mm", q.surface_spacing_mm},
                          {"slab_half_thickness_mm", q.slab_half_thickness_mm},
                          {"piece_gap_mm", q.piece_gap_mm}};
  nlohmann::json timings = nlohmann::json::array();
  if (extra.contains("timings") && extra["timings"].is_array()) timings = extra["timings"];
  for (const MeasureStage& s : result.stages)
    timings.push_back({{"name", s.name}, {"time_s", s.time_s}, {"cpu_s", s.cpu_s}});
  for (const auto& [key, value] : extra.items())
    if (key != "timings") doc[key] = value;
  doc["timings"] = std::move(timings);
  return doc;
}

nlohmann::json ToJson(const MeasureOptions& o) {
  const CloudGridOptions& g = o.geodesics.grid;
  return {{"section",
           {{"half_thickness_mm", o.section.half_thickness_mm},
            {"piece_gap_mm", o.section.piece_gap_mm},
            {"bridge_gap_mm", o.section.bridge_gap_mm},
            {"radius_tolerance", o.section.radius_tolerance},
            {"open_gap_mm", o.section.open_gap_mm},
            {"smooth_arc_mm", o.section.smooth_arc_mm},
            {"min_piece_points", o.section.min_piece_points},
            {"max_slide_mm", o.section.max_slide_mm},
            {"points_per_gap", o.section.points_per_gap},
            {"gap_per_spacing", o.section.gap_per_spacing},
            {"max_half_thickness_mm", o.section.max_half_thickness_mm}}},
          {"geodesics",
           {{"cell_size_mm", g.cell_size_mm},
            {"neighbours", g.neighbours},
            {"sheet_gap_mm", g.sheet_gap_mm},
            {"max_snap_distance_mm", o.geodesics.max_snap_distance_mm},
            {"polish", o.geodesics.polish}}},
          {"datum_tolerance_mm", o.datum_tolerance_mm},
          {"arms_margin_mm", o.arms_margin_mm},
          {"narrowest_step_mm", o.narrowest_step_mm},
          {"narrowest_window", o.narrowest_window},
          {"uncertain_confidence", o.uncertain_confidence},
          {"only", o.only}};
}

std::string MeasurementsCsv(const MeasureResult& result) {
  std::string out = "name,kind,method,value_mm,flags,datum\n";
  char value[64];
  for (const Measurement& m : result.measurements) {
    std::snprintf(value, sizeof(value), "%.2f", m.value_mm);
    out += CsvField(m.name) + "," + ToString(m.kind) + "," + ToString(m.method) + "," + value +
           "," + CsvField(Joined(m.flags)) + "," + CsvField(Joined(m.datum)) + "\n";
  }
  return out;
}

void WriteMeasurementDocument(const std::filesystem::path& file, const nlohmann::json& document) {
  WriteJsonFile(file, document);
}

void WriteMeasurementsCsv(const std::filesystem::path& file, const MeasureResult& result) {
  WriteFileAtomically(file, MeasurementsCsv(result));
}

}  // namespace bespoke
