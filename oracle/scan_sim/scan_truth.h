// The truth file of a simulated scan (docs/contracts.md, "The virtual
// scanner's truth file"): the body's truth document carried into the
// scanner frame. Landmarks (and any measurement geometry) are mapped by the
// rigid scanner_from_body and stay in mm; the body-frame landmarks are kept
// under "landmarks_body"; the transform, the scan file's unit and what the
// scanner did are recorded:
//   { ...every field of TRUTH.json..., "frame": "scanner",
//     "landmarks": { name: [x, y, z] (scanner frame, mm) },
//     "landmarks_body": { name: [x, y, z] (body frame, mm) },
//     "scanner_from_body": 4x4 row-major, "file_unit": "m",
//     "scan": { "file": ..., "points": ..., "by_source": {...}, "settings": {...} } }
// Measurement values need no change (a rigid motion keeps lengths).
#ifndef BESPOKE_ORACLE_SCAN_SIM_SCAN_TRUTH_H_
#define BESPOKE_ORACLE_SCAN_SIM_SCAN_TRUTH_H_

#include <nlohmann/json.hpp>
#include <string>

#include "oracle/scan_sim/scan_sim.h"
#include "scanners/core/units.h"

namespace bespoke {

// What the scanner did (settings and counts), for reports and truth files.
nlohmann::json ScanSimReport(const ScanSimOptions& options, const ScanSimResult& result);

// The scan's truth document. `truth` must be a measurement document in the
// body frame (InputError naming `what` otherwise, e.g. the file name).
nlohmann::json ScanTruthDocument(const nlohmann::json& truth, const ScanSimOptions& options,
                                 const ScanSimResult& result, LengthUnit file_unit,
                                 const std::string& scan_file, const std::string& what);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_SCAN_TRUTH_H_
