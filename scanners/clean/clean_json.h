// JSON for the cleaning chain's settings and results (the `bespoke clean`
// report and batch reports). Units in the key names (docs/contracts.md).
//
// ToJson(CleanOptions): every setting, disabled stages included, e.g.
//   {"voxel_grid": {"enabled": true, "leaf_mm": 4.0}, ...}
// ToJson(CleanResult): everything but the cloud itself:
//   {"stages": [{"name", "enabled", "points_in", "points_out", "time_s"}],
//    "body_from_scanner": 4x4 row-major, "floor": {...} or null,
//    "body_frame": {...}, "normals": {...}, "clusters": [...], "flags": [...]}
#ifndef BESPOKE_SCANNERS_CLEAN_CLEAN_JSON_H_
#define BESPOKE_SCANNERS_CLEAN_CLEAN_JSON_H_

#include <nlohmann/json.hpp>

#include "scanners/clean/clean.h"

namespace bespoke {

nlohmann::json ToJson(const CleanOptions& options);
nlohmann::json ToJson(const CleanResult& result);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_CLEAN_JSON_H_
