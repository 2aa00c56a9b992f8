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

// The core measurement names of docs/contracts.md (bindings must use these).
const std::vector<std::string>& CoreMeasurementNames();
bool IsCoreMeasurement(const std::string& name);

// Reads a measurement document. Throws InputError naming `file` when it is not
// a JSON object with a "measurements" array of {name, value_mm} entries with
// finite positive values, or when a name repeats.
MeasurementSet ReadMeasurements(const std::filesystem::path& file);
MeasurementSet MeasurementsFromJson(const nlohmann::json& document, const std::string& what);

// A measurement document (contracts.md schema) for `values`, kinds guessed
// from the names (…_girth -> girth, …_height/stature -> height, else length).
nlohmann::json MeasurementsToJson(const MeasurementSet& values);

// Checks every binding of `pattern` against the core names and `values`:
// InputError("<what>: binding 'x' uses unknown measurement 'y'") or
// ("<what>: measurement 'y' needed by binding 'x' is missing from <where>").
void CheckBindingsAgainst(const Pattern& pattern, const MeasurementSet& values,
                          const std::string& what, const std::string& where);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_MEASUREMENTS_H_
