// The measurement document of docs/contracts.md (MEAS.json) and its CSV
// table, from the result of Measure (measure.h):
//   { "format": "bespoke-measurements", "version": 1, "units": "mm",
//     "frame": "body", "source": "scan",
//     "landmarks": { "crown": [x, y, z], ... },                    // body frame, mm
//     "landmark_details": { "crown": {"confidence": 1, "flags": [], "method": "..."} },
//     "landmarks_missing": { "crotch": "why" },
//     "measurements": [ { "name": "bust_girth", "kind": "girth", "value_mm": 912.3,
//                         "flags": [], "method": "section_hull",
//                         "datum": ["bust_right", "bust_left"],
//                         "uncertain_landmarks": [...],          // when any
//                         "largest_gap_mm": 12.1,                // girths
//                         "geometry": [[x, y, z], ...] }, ... ],  // with_geometry only
//     "skipped": [ { "name": "...", "reason": "..." } ],
//     "timings": [ { "name": "girths", "time_s": 0.1, "cpu_s": 0.1 }, ... ] }
// `extra` is merged in at the top level last (e.g. "input", "settings",
// more "timings" of the caller's stages: given as "timings", they are
// prepended). Values are rounded to 0.01 mm.
//
// CSV: header `name,kind,method,value_mm,flags,datum`, one row per
// measurement in catalogue order, flags and datum joined with ';', values
// with two decimals; skipped measurements are not rows.
// Writers are atomic (scanners/core/atomic_file.h); InputError naming the
// file when its folder does not exist.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_DOCUMENT_H_
#define BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_DOCUMENT_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "measure/landmarks/landmarks.h"
#include "measure/measurements/measure.h"

namespace bespoke {

nlohmann::json MeasurementDocument(const MeasureResult& result, const LandmarkSet& landmarks,
                                   const nlohmann::json& extra = nlohmann::json::object(),
                                   bool with_geometry = false);

// The options as written under "settings".
nlohmann::json ToJson(const MeasureOptions& options);

std::string MeasurementsCsv(const MeasureResult& result);

void WriteMeasurementDocument(const std::filesystem::path& file, const nlohmann::json& document);
void WriteMeasurementsCsv(const std::filesystem::path& file, const MeasureResult& result);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_DOCUMENT_H_
