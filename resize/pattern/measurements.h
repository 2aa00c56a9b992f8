// Body measurements as the resize stage reads them: the measurement document
// of docs/contracts.md (MEAS.json from `bespoke measure`, TRUTH.json from the
// oracle; {"measurements": [{"name", "kind", "value_mm"}]}), and the core
// measurement names pattern bindings may use.
#ifndef BESPOKE_RESIZE_PATTERN_MEASUREMENTS_H_
#define BESPOKE_RESIZE_PATTERN_MEASUREMENTS_H_

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

using MeasurementSet = std::map<std::string, double>;  // name -> value (mm)

// The core measurement names of docs/contracts.md. They include the derived
// measurements below.
const std::vector<std::string>& CoreMeasurementNames();
bool IsCoreMeasurement(const std::string& name);

// True for every measurement a binding may use: any measurement of the
// catalogue (measure/catalogue/catalogue.json) and the derived ones.
bool IsBindableMeasurement(const std::string& name);

// The target of `binding` for `body` (mm): body x (1 + ease_percent / 100) +
// ease_mm, or the kept value of a fixed binding. The measurement must be in
// `body` (CheckBindingsAgainst). InputError for a binding that follows
// another (use BindingTargets).
double BindingTarget(const MeasurementBinding& binding, const MeasurementSet& body);

// Every binding's target, in order, those that follow another binding
// included (its base value in `pattern` x the followed binding's target /
// its base value).
std::vector<double> BindingTargets(const Pattern& pattern, const MeasurementSet& body);

// Resolves every binding that keeps the base pattern's own ease
// (MeasurementBinding::keep_ease) from `pattern.base_body`, the measurements
// the base was drafted for: ease_mm = value - body ("mm"), or ease_percent =
// 100 (value / body - 1) ("percent"); keep_ease is cleared. InputError
// naming `what` when a needed measurement is missing from base_body.
void ResolveKeptEase(const std::string& what, Pattern* pattern);

// Derived measurements: computed from other measurements, so a document need
// not give them. One so far:
//   body_rise = waist_height - inside_leg (mm), the rise the trouser draft
//   places its crotch line by. It is not the catalogue's crotch_depth (the
//   vertical side-waist-to-crotch distance): inside_leg runs from the crotch
//   to the inside ankle, so body_rise is about crotch_depth + ankle height.
bool IsDerivedMeasurement(const std::string& name);

// Adds to `values` every derived measurement whose inputs it has and that it
// lacks (only when the derived value is positive). A derived measurement
// that `values` already gives must agree with its derivation within 1 mm:
// InputError("<what>: measurement 'body_rise' (x mm) is not waist_height -
// inside_leg (y mm) ...") otherwise. ReadMeasurements, MeasurementsFromJson,
// DraftDesign and ResizePattern call it, so sets read or drafted from always
// carry body_rise when they have waist_height and inside_leg.
void AddDerivedMeasurements(MeasurementSet* values, const std::string& what);

// Reads a measurement document and adds the derived measurements
// (AddDerivedMeasurements). Throws InputError naming `file` when it is not a
// JSON object with a "measurements" array of {name, value_mm} entries with
// finite positive values, when a name repeats, or when a given derived
// measurement disagrees with its derivation.
MeasurementSet ReadMeasurements(const std::filesystem::path& file);
MeasurementSet MeasurementsFromJson(const nlohmann::json& document, const std::string& what);

// A measurement document (contracts.md schema) for `values`, kinds guessed
// from the names (…_girth -> girth, …_height/stature -> height, else length).
nlohmann::json MeasurementsToJson(const MeasurementSet& values);

// Checks every binding of `pattern` against the catalogue and `values`:
// InputError("<what>: binding 'x' uses unknown measurement 'y'") or
// ("<what>: measurement 'y' needed by binding 'x' is missing from <where>").
void CheckBindingsAgainst(const Pattern& pattern, const MeasurementSet& values,
                          const std::string& what, const std::string& where);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_MEASUREMENTS_H_
