// TRUTH.json: a generated body's exact datum points and reference
// measurements, in the measurement document schema of docs/contracts.md
// (so a truth file can stand in for measurements anywhere):
//   { "format": "bespoke-measurements", "version": 1, "units": "mm",
//     "frame": "body", "source": "truth",
//     "model": "makehuman", "seed": 7, "parameters": { "gender": 0.04, ... },
//     "landmarks": { "crown": [x, y, z], ... },                 // mm, body frame
//     "landmark_surface": { "crown": {"face": 12, "barycentric": [1, 0, 0]}, ... },
//     "mesh": { "vertices": 13380, "faces": 26756 },
//     "measurements": [ { "name": "bust_girth", "kind": "girth", "value_mm": 912.3,
//                         "flags": [], "method": "section_hull",
//                         "datum": ["bust_right", "bust_left"],
//                         "geometry": [[x, y, z], ...] }, ... ],   // geometry only if kept
//     "skipped": [ { "name": "...", "reason": "..." } ],
//     "settings": { "datum_tolerance_mm": 20 } }
// Writing is atomic (scanners/core/json_io.h).
#ifndef BESPOKE_ORACLE_TRUTH_TRUTH_FILE_H_
#define BESPOKE_ORACLE_TRUTH_TRUTH_FILE_H_

#include <filesystem>
#include <nlohmann/json.hpp>

#include "oracle/body/body.h"
#include "oracle/truth/reference_measurements.h"

namespace bespoke {

nlohmann::json TruthDocument(const Body& body, const Catalogue& catalogue,
                             const ReferenceOptions& options, const ReferenceMeasurements& truth);

void WriteTruthFile(const std::filesystem::path& file, const Body& body, const Catalogue& catalogue,
                    const ReferenceOptions& options, const ReferenceMeasurements& truth);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_TRUTH_FILE_H_
