#include "oracle/scan_sim/scan_truth.h"

#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {

nlohmann::json ScanSimReport(const ScanSimOptions& o, const ScanSimResult& r) {
  const BoothOptions& b = o.booth;
  nlohmann::json settings = {
      {"seed", o.seed},
      {"sensors",
       {{"directions", b.directions}, {"heights", b.heights}, {"count", r.sensors.size()}}},
      {"booth_radius_mm", b.radius_mm},
      {"sensor_heights_mm", {b.lowest_mm, b.highest_mm}},
      {"resolution_px", {b.width_px, b.height_px}},
      {"fov_deg", {b.fov_horizontal_deg, b.fov_vertical_deg}},
      {"range_mm", {b.min_range_mm, b.max_range_mm}},
      {"noise_sigma_mm", o.noise_sigma_mm},
      {"outlier_fraction", o.outlier_fraction},
      {"min_incidence_cos", o.min_incidence_cos},
      {"floor", o.floor},
      {"floor_half_size_mm", o.floor_half_size_mm},
      {"stray_objects", o.stray_objects},
      {"misalign_mm", o.misalign_mm},
      {"misalign_deg", o.misalign_deg},
      {"transform", ToString(o.transform)},
  };
  return {{"points", r.cloud.size()},
          {"rays", r.rays},
          {"by_source",
           {{"body", r.counts[0]},
            {"floor", r.counts[1]},
            {"stray", r.counts[2]},
            {"outlier", r.counts[3]}}},
          {"dropped_grazing", r.dropped_grazing},
          {"dropped_out_of_range", r.dropped_range},
          {"stray_objects_placed", r.stray_objects_placed},
          {"settings", settings}};
}

nlohmann::json ScanTruthDocument(const nlohmann::json& truth, const ScanSimOptions& options,
                                 const ScanSimResult& result, LengthUnit file_unit,
                                 const std::string& scan_file, const std::string& what) {
  if (!truth.is_object() || !truth.contains("landmarks") || !truth["landmarks"].is_object()) {
    throw InputError(what + ": not a measurement document (no \"landmarks\" object)");
  }
  if (truth.value("frame", "body") != "body") {
    throw InputError(what + ": its frame is '" + truth.value("frame", "") + "', expected 'body'");
  }
  const Eigen::Affine3d& t = result.scanner_from_body;
  nlohmann::json out = truth;
  nlohmann::json landmarks = nlohmann::json::object();
  for (const auto& [name, value] : truth["landmarks"].items()) {
    landmarks[name] =
        ToJson(Eigen::Vector3d(t * Vector3FromJson(value, what + ": landmark " + name)));
  }
  out["frame"] = "scanner";
  out["landmarks_body"] = truth["landmarks"];
  out["landmarks"] = landmarks;
  if (out.contains("measurements") && out["measurements"].is_array()) {
    for (auto& m : out["measurements"]) {
      if (!m.is_object() || !m.contains("geometry") || !m["geometry"].is_array()) continue;
      for (auto& p : m["geometry"])
        p = ToJson(Eigen::Vector3d(t * Vector3FromJson(p, what + ": geometry")));
    }
  }
  out["scanner_from_body"] = ToJson(t);
  out["file_unit"] = ToString(file_unit);
  out["scan"] = ScanSimReport(options, result);
  out["scan"]["file"] = scan_file;
  return out;
}

}  // namespace bespoke
