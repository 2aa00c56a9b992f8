#include "measure/catalogue/catalogue.h"

#include <nlohmann/json.hpp>
#include <set>
#include <utility>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using nlohmann::json;

std::string RequiredString(const json& entry, const char* key, const std::string& where) {
  if (!entry.contains(key) || !entry[key].is_string() || entry[key].get<std::string>().empty())
    throw InputError(where + ": missing or empty string field '" + key + "'");
  return entry[key].get<std::string>();
}

std::string OptionalString(const json& entry, const char* key, const std::string& where) {
  if (!entry.contains(key)) return {};
  if (!entry[key].is_string()) throw InputError(where + ": field '" + key + "' is not a string");
  return entry[key].get<std::string>();
}

std::vector<std::string> StringList(const json& entry, const char* key, const std::string& where) {
  std::vector<std::string> out;
  if (!entry.contains(key)) return out;
  if (!entry[key].is_array()) throw InputError(where + ": field '" + key + "' is not a list");
  for (const json& item : entry[key]) {
    if (!item.is_string()) throw InputError(where + ": field '" + key + "' has a non-string item");
    out.push_back(item.get<std::string>());
  }
  return out;
}

template <typename Enum>
Enum ParseEnum(const std::string& text, const std::vector<std::pair<const char*, Enum>>& table,
               const std::string& where) {
  std::string known;
  for (const auto& [name, value] : table) {
    if (text == name) return value;
    known += (known.empty() ? "" : ", ") + std::string(name);
  }
  throw InputError(where + ": unknown value '" + text + "' (known: " + known + ")");
}

const std::vector<std::pair<const char*, MeasurementKind>> kKinds = {
    {"girth", MeasurementKind::kGirth},
    {"length", MeasurementKind::kLength},
    {"height", MeasurementKind::kHeight}};
const std::vector<std::pair<const char*, MeasurementMethod>> kMethods = {
    {"section_hull", MeasurementMethod::kSectionHull},
    {"geodesic", MeasurementMethod::kGeodesic},
    {"breadth", MeasurementMethod::kBreadth},
    {"point_to_line", MeasurementMethod::kPointToLine},
    {"height", MeasurementMethod::kHeight}};
const std::vector<std::pair<const char*, GirthPlane>> kPlanes = {
    {"horizontal", GirthPlane::kHorizontal},
    {"perpendicular_to_axis", GirthPlane::kPerpendicularToAxis},
    {"through_points", GirthPlane::kThroughPoints}};

template <typename Enum>
std::string NameOf(Enum value, const std::vector<std::pair<const char*, Enum>>& table) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "none";
}

LandmarkDef ParseLandmark(const json& entry, const std::string& where) {
  LandmarkDef def;
  def.name = RequiredString(entry, "name", where);
  def.region = RequiredString(entry, "region", where);
  def.definition = RequiredString(entry, "definition", where);
  def.standard = RequiredString(entry, "standard", where);
  def.aliases = StringList(entry, "aliases", where);
  if (entry.contains("level")) {
    if (!entry["level"].is_boolean()) throw InputError(where + ": 'level' is not a boolean");
    def.level = entry["level"].get<bool>();
  }
  return def;
}

// Checks the number of datum points (and axis points) each method needs.
void CheckArity(const MeasurementDef& m, const std::string& where) {
  const std::size_t n = m.datum.size();
  bool ok = n >= 1;
  switch (m.method) {
    case MeasurementMethod::kSectionHull:
      ok = ok && m.kind == MeasurementKind::kGirth && m.plane != GirthPlane::kNone;
      if (m.plane == GirthPlane::kPerpendicularToAxis) ok = ok && m.axis.size() == 2;
      if (m.plane == GirthPlane::kThroughPoints) ok = ok && n == 3;
      break;
    case MeasurementMethod::kGeodesic:
      // A girth over the skin is a closed chain: it ends where it starts.
      ok = ok && n >= 2 && m.kind != MeasurementKind::kHeight;
      if (m.kind == MeasurementKind::kGirth) ok = ok && n >= 4 && IsClosedChain(m);
      break;
    case MeasurementMethod::kBreadth:
      ok = ok && n == 2 && m.kind == MeasurementKind::kLength;
      break;
    case MeasurementMethod::kPointToLine:
      ok = ok && n == 3 && m.kind == MeasurementKind::kLength;
      break;
    case MeasurementMethod::kHeight:
      ok = ok && n <= 2 && m.kind == MeasurementKind::kHeight;
      break;
  }
  if (!ok)
    throw InputError(where + ": method '" + ToString(m.method) + "' does not fit kind '" +
                     ToString(m.kind) + "', its plane/axis or its " + std::to_string(n) +
                     " datum points");
}

MeasurementDef ParseMeasurement(const json& entry, const std::string& where) {
  MeasurementDef m;
  m.name = RequiredString(entry, "name", where);
  const std::string at = where + " ('" + m.name + "')";
  m.kind = ParseEnum(RequiredString(entry, "kind", at), kKinds, at + " kind");
  m.method = ParseEnum(RequiredString(entry, "method", at), kMethods, at + " method");
  if (entry.contains("plane"))
    m.plane = ParseEnum(RequiredString(entry, "plane", at), kPlanes, at + " plane");
  m.datum = StringList(entry, "datum", at);
  m.axis = StringList(entry, "axis", at);
  if (entry.contains("to_floor")) {
    if (!entry["to_floor"].is_boolean()) throw InputError(at + ": 'to_floor' is not a boolean");
    m.to_floor = entry["to_floor"].get<bool>();
  }
  m.arms = OptionalString(entry, "arms", at);
  if (m.arms != "" && m.arms != "check" && m.arms != "lower")
    throw InputError(at + ": 'arms' must be check or lower, not '" + m.arms + "'");
  if (!m.arms.empty() && m.plane != GirthPlane::kHorizontal)
    throw InputError(at + ": 'arms' needs a horizontal girth");
  m.side = RequiredString(entry, "side", at);
  if (m.side != "right" && m.side != "both" && m.side != "centre")
    throw InputError(at + ": side must be right, both or centre, not '" + m.side + "'");
  m.narrowest_up_to = OptionalString(entry, "narrowest_up_to", at);
  if (!m.narrowest_up_to.empty() && (m.plane != GirthPlane::kHorizontal || m.side != "right"))
    throw InputError(at + ": 'narrowest_up_to' needs a horizontal girth of a right-side limb");
  m.definition = RequiredString(entry, "definition", at);
  m.standard = RequiredString(entry, "standard", at);
  m.deviation = OptionalString(entry, "deviation", at);
  m.thesis = OptionalString(entry, "thesis", at);
  m.valentina = OptionalString(entry, "valentina", at);
  m.freesewing = OptionalString(entry, "freesewing", at);
  CheckArity(m, at);
  return m;
}

}  // namespace

std::string ToString(MeasurementKind kind) { return NameOf(kind, kKinds); }
std::string ToString(MeasurementMethod method) { return NameOf(method, kMethods); }
std::string ToString(GirthPlane plane) { return NameOf(plane, kPlanes); }

Catalogue Catalogue::FromJson(const json& document, const std::string& source) {
  if (!document.is_object() || !document.contains("landmarks") ||
      !document["landmarks"].is_array() || !document.contains("measurements") ||
      !document["measurements"].is_array())
    throw InputError(source + ": not a catalogue (needs 'landmarks' and 'measurements' lists)");
  Catalogue c;
  c.notes_ = StringList(document, "notes", source);
  for (std::size_t i = 0; i < document["landmarks"].size(); ++i) {
    const json& entry = document["landmarks"][i];
    const std::string where = source + ": landmark " + std::to_string(i + 1);
    LandmarkDef def = ParseLandmark(entry, where);
    bool paired = false;
    if (entry.contains("paired")) {
      if (!entry["paired"].is_boolean()) throw InputError(where + ": 'paired' is not a boolean");
      paired = entry["paired"].get<bool>();
    }
    std::vector<LandmarkDef> expanded;
    if (paired) {
      for (const char* side : {"_left", "_right"}) {
        LandmarkDef d = def;
        d.name += side;
        expanded.push_back(d);
      }
    } else {
      expanded.push_back(def);
    }
    for (LandmarkDef& d : expanded) {
      if (!c.landmark_index_.emplace(d.name, c.landmarks_.size()).second)
        throw InputError(where + ": duplicate landmark name '" + d.name + "'");
      c.landmarks_.push_back(std::move(d));
    }
  }
  for (std::size_t i = 0; i < document["measurements"].size(); ++i) {
    const std::string where = source + ": measurement " + std::to_string(i + 1);
    MeasurementDef m = ParseMeasurement(document["measurements"][i], where);
    for (const std::string& name : ReferencedLandmarks(m))
      if (!c.HasLandmark(name))
        throw InputError(where + " ('" + m.name + "'): unknown landmark '" + name + "'");
    if (!c.measurement_index_.emplace(m.name, c.measurements_.size()).second)
      throw InputError(where + ": duplicate measurement name '" + m.name + "'");
    c.measurements_.push_back(std::move(m));
  }
  return c;
}

std::vector<std::string> ReferencedLandmarks(const MeasurementDef& m) {
  std::vector<std::string> out = m.datum;
  out.insert(out.end(), m.axis.begin(), m.axis.end());
  if (!m.narrowest_up_to.empty()) out.push_back(m.narrowest_up_to);
  return out;
}

const Catalogue& Catalogue::Builtin() {
  static const Catalogue catalogue = [] {
    json document;
    try {
      document = json::parse(BuiltinCatalogueJson());
    } catch (const json::exception& e) {
      throw InternalError(std::string("built-in catalogue.json does not parse: ") + e.what());
    }
    return FromJson(document, "catalogue.json");
  }();
  return catalogue;
}

bool Catalogue::HasLandmark(std::string_view name) const {
  return landmark_index_.find(name) != landmark_index_.end();
}

bool Catalogue::HasMeasurement(std::string_view name) const {
  return measurement_index_.find(name) != measurement_index_.end();
}

const LandmarkDef& Catalogue::Landmark(std::string_view name) const {
  const auto it = landmark_index_.find(name);
  if (it == landmark_index_.end())
    throw InputError("unknown landmark '" + std::string(name) +
                     "' (see docs/measurements.md for the names)");
  return landmarks_[it->second];
}

const MeasurementDef& Catalogue::Measurement(std::string_view name) const {
  const auto it = measurement_index_.find(name);
  if (it == measurement_index_.end())
    throw InputError("unknown measurement '" + std::string(name) +
                     "' (see docs/measurements.md for the names)");
  return measurements_[it->second];
}

std::string UnsidedLandmarkName(const std::string& name) {
  for (const std::string side : {"_right", "_left"})
    if (name.size() > side.size() &&
        name.compare(name.size() - side.size(), side.size(), side) == 0)
      return name.substr(0, name.size() - side.size());
  return name;
}

}  // namespace bespoke
