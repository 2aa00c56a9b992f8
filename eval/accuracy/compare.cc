#include "eval/accuracy/compare.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>

#include "measure/catalogue/catalogue.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

using nlohmann::json;

void CheckDocument(const json& document, const std::string& what) {
  if (!document.is_object()) throw InputError(what + ": not a JSON object");
  if (document.contains("format") && document["format"] != "bespoke-measurements") {
    throw InputError(what + ": format is " + document["format"].dump() +
                     ", not \"bespoke-measurements\"");
  }
  if (document.contains("units") && document["units"] != "mm") {
    throw InputError(what + ": units must be \"mm\", not " + document["units"].dump());
  }
  if (!document.contains("measurements") || !document["measurements"].is_array()) {
    throw InputError(what + ": no \"measurements\" array");
  }
}

std::vector<std::string> Flags(const json& entry) {
  std::vector<std::string> flags;
  if (entry.contains("flags") && entry["flags"].is_array()) {
    for (const json& f : entry["flags"]) {
      if (f.is_string()) flags.push_back(f.get<std::string>());
    }
  }
  return flags;
}

std::map<std::string, Eigen::Vector3d> Points(const json& document, const char* key,
                                              const std::string& what) {
  std::map<std::string, Eigen::Vector3d> points;
  if (!document.contains(key)) return points;
  if (!document[key].is_object()) throw InputError(what + ": \"" + key + "\" is not an object");
  for (const auto& [name, value] : document[key].items()) {
    points[name] = Vector3FromJson(value, what + ": landmark " + name);
  }
  return points;
}

std::string Frame(const json& document) { return document.value("frame", std::string("body")); }

}  // namespace

SubjectComparison CompareDocuments(const json& measured, const json& truth,
                                   const std::string& subject) {
  const std::string measured_what = subject + " (measurements)";
  const std::string truth_what = subject + " (truth)";
  CheckDocument(measured, measured_what);
  CheckDocument(truth, truth_what);
  SubjectComparison result;
  result.subject = subject;

  std::map<std::string, const json*> measured_by_name;
  for (const json& m : measured["measurements"]) {
    if (m.is_object() && m.contains("name") && m["name"].is_string()) {
      measured_by_name[m["name"].get<std::string>()] = &m;
    }
  }
  for (const json& t : truth["measurements"]) {
    if (!t.is_object() || !t.contains("name") || !t["name"].is_string()) {
      throw InputError(truth_what + ": a measurement without a name");
    }
    if (!t.contains("value_mm") || !t["value_mm"].is_number() ||
        !std::isfinite(t["value_mm"].get<double>())) {
      continue;  // the truth has no value: nothing to judge against
    }
    MeasurementDifference d;
    d.name = t["name"].get<std::string>();
    d.kind = t.value("kind", std::string());
    d.truth_mm = t["value_mm"].get<double>();
    d.truth_flags = Flags(t);
    const auto it = measured_by_name.find(d.name);
    const json* m = it == measured_by_name.end() ? nullptr : it->second;
    if (m && m->contains("value_mm") && (*m)["value_mm"].is_number() &&
        std::isfinite((*m)["value_mm"].get<double>())) {
      d.measured_mm = (*m)["value_mm"].get<double>();
      d.difference_mm = d.measured_mm - d.truth_mm;
    } else {
      d.missing = true;
      d.measured_mm = d.difference_mm = kNaN;
    }
    if (m) d.flags = Flags(*m);
    if (d.kind.empty() && m) d.kind = m->value("kind", std::string());
    result.measurements.push_back(std::move(d));
  }

  // Landmarks, in one frame.
  const bool truth_in_scanner = Frame(truth) == "scanner";
  const bool measured_has_transform = measured.contains("body_from_scanner");
  std::map<std::string, Eigen::Vector3d> truth_points,
      measured_points = Points(measured, "landmarks", measured_what);
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // the body's up axis in the compared frame
  if (truth_in_scanner && Frame(measured) == "scanner") {
    result.landmark_frame = "scanner";
    truth_points = Points(truth, "landmarks", truth_what);
  } else if (truth_in_scanner && measured_has_transform) {
    result.landmark_frame = "scanner";
    truth_points = Points(truth, "landmarks", truth_what);
    const Eigen::Affine3d scanner_from_body =
        AffineFromJson(measured["body_from_scanner"], measured_what + ": body_from_scanner")
            .inverse();
    for (auto& [name, p] : measured_points) p = scanner_from_body * p;
    up = (scanner_from_body.linear() * Eigen::Vector3d::UnitZ()).normalized();
  } else {
    result.landmark_frame = "body";
    truth_points = Points(truth, truth_in_scanner ? "landmarks_body" : "landmarks", truth_what);
  }
  const Catalogue& catalogue = Catalogue::Builtin();
  for (const auto& [name, t] : truth_points) {
    LandmarkError e;
    e.name = name;
    e.truth_mm = t;
    const auto it = measured_points.find(name);
    if (it == measured_points.end()) {
      e.missing = true;
      e.error_mm = kNaN;
    } else {
      e.measured_mm = it->second;
      e.height_only = catalogue.HasLandmark(name) && catalogue.Landmark(name).level;
      e.error_mm = e.height_only ? std::abs((it->second - t).dot(up)) : (it->second - t).norm();
    }
    result.landmarks.push_back(e);
  }
  return result;
}

}  // namespace bespoke
