// The landmark (datum point) and measurement catalogue: names, definitions,
// methods and the names other tools use (Valentina, FreeSewing).
//
// The data is one readable file, measure/catalogue/catalogue.json, compiled
// into the library at build time (measure/catalogue/catalogue.cmake), so
// every binary carries the same catalogue. docs/measurements.md is generated
// from it (ToMarkdown; a test fails when the doc is stale).
//
// Landmarks marked "paired" in the file are expanded here into
// <name>_left and <name>_right. Lookups by an unknown name throw InputError.
#ifndef BESPOKE_MEASURE_CATALOGUE_CATALOGUE_H_
#define BESPOKE_MEASURE_CATALOGUE_CATALOGUE_H_

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace bespoke {

struct LandmarkDef {
  std::string name;                  // snake_case, e.g. "back_neck", "shoulder_right"
  std::string region;                // "head", "neck", "shoulder", "torso", "hip", "arm", "leg"
  std::string definition;            // in our words, after the standards cited
  std::string standard;              // e.g. "ISO 8559-1 (cervicale); EN 13402-1 (back neck point)"
  std::vector<std::string> aliases;  // "cervicale", "C7", ...
  // Defined by a level alone (the height of a girth, e.g. the calf's largest
  // girth; default false): its height is what places it, so its error is
  // the height's.
  bool level = false;
};

enum class MeasurementKind { kGirth, kLength, kHeight };
std::string ToString(MeasurementKind kind);  // "girth", "length", "height"

enum class MeasurementMethod {
  kSectionHull,  // girth: convex-hull perimeter of the plane section loop through datum[0]
  kGeodesic,     // length: geodesics along the datum chain (+ last point's height if to_floor)
  kBreadth,      // length: horizontal (xy) distance between datum[0] and datum[1]
  kPointToLine,  // length: distance from datum[0] to the line through datum[1], datum[2]
  kHeight,       // height: z of datum[0] above the floor, or minus z of datum[1]
};
std::string ToString(MeasurementMethod method);  // the catalogue file's spelling

// The cutting plane of a girth.
enum class GirthPlane {
  kNone,                 // not a girth
  kHorizontal,           // z = mean z of the datum points
  kPerpendicularToAxis,  // through datum[0], normal along axis[1] - axis[0]
  kThroughPoints,        // through datum[0], datum[1], datum[2]
};
std::string ToString(GirthPlane plane);

struct MeasurementDef {
  std::string name;
  MeasurementKind kind = MeasurementKind::kLength;
  MeasurementMethod method = MeasurementMethod::kGeodesic;
  GirthPlane plane = GirthPlane::kNone;
  std::vector<std::string> datum;  // landmark names, in the method's order
  std::vector<std::string> axis;   // two landmark names for kPerpendicularToAxis, else empty
  bool to_floor = false;           // kGeodesic: add the last datum point's height
  // Horizontal trunk girths whose datum points include the left and right
  // sides: "check" flags a section reaching > 30 mm beyond them (arms or
  // hands merged into it); "lower": the section just under them, free of the
  // arms (chest: "just under the armpits"; the reference moves the plane
  // down in 1 mm steps, up to 100, until the mesh's trunk loop is free of the
  // arm loops, the scan's measurement keeps the points between the datum
  // points' x); "" (default) neither.
  std::string arms;
  // Horizontal limb girths: the plane moves up from datum[0]'s height to this
  // landmark's height and the girth is the smallest section there (ankle:
  // the minimum girth above the malleoli, up to the calf); "" (default) the
  // plane stays at the datum points.
  std::string narrowest_up_to;
  std::string side;  // "right", "both" (uses both sides) or "centre"
  std::string definition, deviation, standard, thesis;  // deviation/thesis may be empty
  std::string valentina, freesewing;                    // empty where none exists
};

// The landmarks `m` is measured from: its datum points, its axis points and
// the top of a `narrowest_up_to` search, in that order (names may repeat).
std::vector<std::string> ReferencedLandmarks(const MeasurementDef& m);

// Whether `m` is a geodesic chain that ends where it starts (a girth over
// the skin: the neck).
inline bool IsClosedChain(const MeasurementDef& m) {
  return m.method == MeasurementMethod::kGeodesic && m.datum.size() > 2 &&
         m.datum.front() == m.datum.back();
}

// Whether `m` is a girth round the trunk: a horizontal section measured
// across the body (side "centre" or "both": bust, chest, under-bust, waist,
// middle hip, hip).
inline bool IsTrunkGirth(const MeasurementDef& m) {
  return m.kind == MeasurementKind::kGirth && m.plane == GirthPlane::kHorizontal &&
         (m.side == "centre" || m.side == "both");
}

class Catalogue {
 public:
  // The built-in catalogue (parsed once, on first use; thread-safe).
  static const Catalogue& Builtin();
  // Parses a catalogue document; `source` names it in errors. Throws
  // InputError for a missing field, an unknown kind/method/plane, duplicate
  // names, a measurement referring to an unknown landmark, or a method given
  // the wrong number of datum points.
  static Catalogue FromJson(const nlohmann::json& document, const std::string& source);

  const std::vector<LandmarkDef>& landmarks() const { return landmarks_; }
  const std::vector<MeasurementDef>& measurements() const { return measurements_; }
  const std::vector<std::string>& notes() const { return notes_; }

  bool HasLandmark(std::string_view name) const;
  bool HasMeasurement(std::string_view name) const;
  // InputError("unknown landmark 'foo' (known: ...)") for unknown names.
  const LandmarkDef& Landmark(std::string_view name) const;
  const MeasurementDef& Measurement(std::string_view name) const;

  // docs/measurements.md: the landmark and measurement tables.
  std::string ToMarkdown() const;

 private:
  std::vector<LandmarkDef> landmarks_;
  std::vector<MeasurementDef> measurements_;
  std::vector<std::string> notes_;
  std::map<std::string, std::size_t, std::less<>> landmark_index_, measurement_index_;
};

// The catalogue file's text as embedded at build time.
const char* BuiltinCatalogueJson();

// A landmark's name without its side: "shoulder_right" -> "shoulder"; a name
// without a "_left" or "_right" suffix comes back unchanged.
std::string UnsidedLandmarkName(const std::string& name);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CATALOGUE_CATALOGUE_H_
