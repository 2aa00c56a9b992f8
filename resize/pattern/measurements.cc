#include "resize/pattern/measurements.h"

#include <algorithm>
#include <cmath>

#include "measure/catalogue/catalogue.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {

const std::vector<std::string>& CoreMeasurementNames() {
  static const std::vector<std::string> names = {
      "stature",          "neck_girth",      "bust_girth",       "chest_girth",
      "under_bust_girth", "waist_girth",     "middle_hip_girth", "hip_girth",
      "upper_arm_girth",  "wrist_girth",     "thigh_girth",      "knee_girth",
      "calf_girth",       "ankle_girth",     "back_length",      "front_length",
      "shoulder_length",  "across_shoulder", "back_width",       "front_width",
      "armhole_length",   "arm_length",      "sleeve_length",    "waist_to_hip",
      "crotch_length",    "inside_leg",      "outseam",          "waist_to_knee",
      "waist_height",     "body_rise"};
  return names;
}

bool IsCoreMeasurement(const std::string& name) {
  const auto& names = CoreMeasurementNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool IsDerivedMeasurement(const std::string& name) { return name == "body_rise"; }

bool IsBindableMeasurement(const std::string& name) {
  return IsDerivedMeasurement(name) || IsCoreMeasurement(name) ||
         Catalogue::Builtin().HasMeasurement(name);
}

double BindingTarget(const MeasurementBinding& binding, const MeasurementSet& body) {
  if (!binding.follows.empty())
    throw InputError("binding '" + binding.id + "' follows another; its target needs the pattern");
  if (binding.fixed) return binding.fixed_mm;
  return body.at(binding.measurement) * (1 + binding.ease_percent / 100) + binding.ease_mm;
}

std::vector<double> BindingTargets(const Pattern& pattern, const MeasurementSet& body) {
  std::vector<double> targets;
  for (const MeasurementBinding& b : pattern.bindings) {
    if (b.follows.empty()) {
      targets.push_back(BindingTarget(b, body));
      continue;
    }
    const MeasurementBinding* leader = nullptr;
    for (const MeasurementBinding& other : pattern.bindings)
      if (other.id == b.follows) leader = &other;
    if (leader == nullptr || !leader->follows.empty())
      throw InputError("binding '" + b.id + "' follows '" + b.follows +
                       "', which is not a binding with a measurement or a fixed one");
    const double ratio =
        BindingTarget(*leader, body) / std::max(BindingValue(pattern, *leader), 1e-9);
    targets.push_back(BindingValue(pattern, b) * ratio);
  }
  return targets;
}

void ResolveKeptEase(const std::string& what, Pattern* pattern) {
  for (MeasurementBinding& b : pattern->bindings) {
    if (b.keep_ease.empty() || b.fixed || !b.follows.empty()) continue;
    const auto body = pattern->base_body.find(b.measurement);
    if (body == pattern->base_body.end())
      throw InputError(what + ": binding '" + b.id + "' keeps the base pattern's ease, but '" +
                       b.measurement +
                       "' is not among the base measurements (sidecar \"base_measurements\")");
    const double value = BindingValue(*pattern, b);
    if (b.keep_ease == "percent") {
      b.ease_percent = 100 * (value / body->second - 1);
      b.ease_mm = 0;
    } else {
      b.ease_mm = value - body->second;
      b.ease_percent = 0;
    }
    b.keep_ease.clear();
  }
}

void AddDerivedMeasurements(MeasurementSet* values, const std::string& what) {
  const auto height = values->find("waist_height"), leg = values->find("inside_leg");
  if (height == values->end() || leg == values->end()) return;
  const double rise = height->second - leg->second;
  const auto given = values->find("body_rise");
  if (given == values->end()) {
    if (rise > 0) values->emplace("body_rise", rise);
    return;
  }
  constexpr double kAgreementMm = 1;
  if (!(std::abs(given->second - rise) <= kAgreementMm))
    throw InputError(what + ": measurement 'body_rise' (" + std::to_string(given->second) +
                     " mm) is not waist_height - inside_leg (" + std::to_string(rise) +
                     " mm); it is derived from them, leave it out");
}

MeasurementSet MeasurementsFromJson(const nlohmann::json& document, const std::string& what) {
  if (!document.is_object() || !document.contains("measurements") ||
      !document["measurements"].is_array())
    throw InputError(what + ": not a measurement document (needs a \"measurements\" array)");
  MeasurementSet values;
  for (const auto& entry : document["measurements"]) {
    if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string() ||
        !entry.contains("value_mm") || !entry["value_mm"].is_number())
      throw InputError(what +
                       ": every measurement needs a string \"name\" and a number "
                       "\"value_mm\"");
    const std::string name = entry["name"].get<std::string>();
    const double value = entry["value_mm"].get<double>();
    if (!std::isfinite(value) || value <= 0)
      throw InputError(what + ": measurement '" + name + "' has value " + std::to_string(value) +
                       " mm (must be finite and positive)");
    if (!values.emplace(name, value).second)
      throw InputError(what + ": measurement '" + name + "' appears twice");
  }
  AddDerivedMeasurements(&values, what);
  return values;
}

MeasurementSet ReadMeasurements(const std::filesystem::path& file) {
  return MeasurementsFromJson(ReadJsonFile(file), file.string());
}

nlohmann::json MeasurementsToJson(const MeasurementSet& values) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, value] : values) {
    std::string kind = "length";
    if (name.size() > 6 && name.compare(name.size() - 6, 6, "_girth") == 0) kind = "girth";
    if (name == "stature" || name.find("_height") != std::string::npos) kind = "height";
    list.push_back({{"name", name}, {"kind", kind}, {"value_mm", value}, {"flags", {}}});
  }
  return {{"format", "bespoke-measurements"},
          {"version", 1},
          {"units", "mm"},
          {"frame", "body"},
          {"measurements", list}};
}

void CheckBindingsAgainst(const Pattern& pattern, const MeasurementSet& values,
                          const std::string& what, const std::string& where) {
  for (const MeasurementBinding& b : pattern.bindings) {
    if (b.fixed || !b.follows.empty()) continue;
    if (!IsBindableMeasurement(b.measurement))
      throw InputError(what + ": binding '" + b.id + "' uses unknown measurement '" +
                       b.measurement +
                       "' (bindings use the catalogue's names, docs/measurements.md)");
    if (!values.count(b.measurement))
      throw InputError(what + ": measurement '" + b.measurement + "' needed by binding '" + b.id +
                       "' is missing from " + where);
  }
}

}  // namespace bespoke
