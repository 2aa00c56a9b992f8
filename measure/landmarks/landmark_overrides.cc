// The tailor's landmark override file (measure/landmarks/landmarks.h) and the
// small LandmarkSet / LandmarkOptions members.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "measure/catalogue/catalogue.h"
#include "measure/landmarks/landmarks.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/core/units.h"

namespace bespoke {

const Landmark& LandmarkSet::At(const std::string& name) const {
  auto it = points.find(name);
  if (it != points.end()) return it->second;
  auto why = missing.find(name);
  if (why != missing.end()) {
    throw InputError("landmark '" + name + "' could not be placed: " + why->second);
  }
  throw InputError("landmark '" + name + "' was not detected");
}

void LandmarkOptions::Check() const {
  if (!(slice_step_mm >= 1.0 && slice_step_mm <= 50.0)) {
    throw InputError("landmarks: slice_step_mm must be in [1, 50], got " +
                     std::to_string(slice_step_mm));
  }
  if (!(slice_half_thickness_mm >= 0.5 && slice_half_thickness_mm <= 50.0)) {
    throw InputError("landmarks: slice_half_thickness_mm must be in [0.5, 50], got " +
                     std::to_string(slice_half_thickness_mm));
  }
  const Catalogue& catalogue = Catalogue::Builtin();
  for (const std::string& name : only) {
    if (!catalogue.HasLandmark(name)) {
      throw InputError("landmarks: unknown landmark '" + name + "' in the list to find");
    }
  }
}

namespace {

// "scan" / "scanner" -> "scan"; "body" -> "body"; else InputError.
std::string ParseFrame(const std::filesystem::path& file, const nlohmann::json& value) {
  if (!value.is_string())
    throw InputError(file, "\"frame\" must be a string (\"scan\" or \"body\")");
  const std::string frame = value.get<std::string>();
  if (frame == "scan" || frame == "scanner") return "scan";
  if (frame == "body") return "body";
  throw InputError(file, "unknown frame '" + frame + "' (expected \"scan\" or \"body\")");
}

std::string ParseUnits(const std::filesystem::path& file, const nlohmann::json& value) {
  if (!value.is_string()) throw InputError(file, "\"units\" must be a string (mm, cm, dm or m)");
  const std::string text = value.get<std::string>();
  std::optional<LengthUnit> unit = ParseLengthUnit(text);
  if (!unit) throw InputError(file, "unknown units '" + text + "' (expected mm, cm, dm or m)");
  return ToString(*unit);
}

}  // namespace

LandmarkOverrides ReadLandmarkOverrides(const std::filesystem::path& file) {
  const nlohmann::json document = ReadJsonFile(file);  // InputError naming the file
  if (!document.is_object()) throw InputError(file, "not a JSON object");
  LandmarkOverrides overrides;
  if (document.contains("frame")) overrides.frame = ParseFrame(file, document["frame"]);
  if (document.contains("units")) overrides.units = ParseUnits(file, document["units"]);
  if (!document.contains("landmarks") || !document["landmarks"].is_object()) {
    throw InputError(file, "no \"landmarks\" object (name -> [x, y, z])");
  }
  const Catalogue& catalogue = Catalogue::Builtin();
  for (const auto& [name, value] : document["landmarks"].items()) {
    if (!catalogue.HasLandmark(name)) {
      throw InputError(
          file, "unknown landmark '" + name + "' (names are the catalogue's, e.g. shoulder_right)");
    }
    try {
      overrides.points[name] = Vector3FromJson(value, "landmark " + name);
    } catch (const InputError& e) {
      throw InputError(file, e.what());
    }
  }
  return overrides;
}

void ApplyLandmarkOverrides(const LandmarkOverrides& overrides,
                            const Eigen::Isometry3d& body_from_scan, LandmarkSet* set) {
  BESPOKE_CHECK(set != nullptr, "ApplyLandmarkOverrides: null set");
  std::optional<LengthUnit> unit = ParseLengthUnit(overrides.units);
  if (!unit) throw InputError("landmark overrides: unknown units '" + overrides.units + "'");
  if (overrides.frame != "scan" && overrides.frame != "body") {
    throw InputError("landmark overrides: unknown frame '" + overrides.frame + "'");
  }
  const double mm_per_unit = MillimetresPer(*unit);
  for (const auto& [name, file_point] : overrides.points) {
    Eigen::Vector3d point_mm = file_point * mm_per_unit;
    if (overrides.frame == "scan") point_mm = body_from_scan * point_mm;
    Landmark landmark;
    landmark.position_mm = point_mm;
    landmark.confidence = 1.0;
    landmark.flags = {"override"};
    landmark.method = "override";
    set->points[name] = landmark;
    set->missing.erase(name);
  }
}

}  // namespace bespoke
