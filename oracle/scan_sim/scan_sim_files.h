// Runs the virtual scanner and writes its files: the scan (PLY, optionally
// PCD) in the scanner frame and the chosen unit, a report of what was done,
// the scan's truth file (when the body's truth is given) and a preview
// picture. Shared by `bespoke scan-sim` and `bespoke synth-set`.
//
// Every file is written atomically; on any error nothing half-written is
// left (files already completed stay). InputError for unreadable truth
// files or bad paths.
#ifndef BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_FILES_H_
#define BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_FILES_H_

#include <filesystem>

#include "oracle/scan_sim/scan_sim.h"
#include "scanners/core/units.h"

namespace bespoke {

struct ScanSimFiles {
  std::filesystem::path scan;  // SCAN.ply (required)
  bool pcd = false;            // also write SCAN.pcd (binary)
  bool labels = false;         // write per-point "source" and "sensor" fields (ground truth labels)
  LengthUnit units =
      LengthUnit::kMetre;        // unit of the written coordinates (default m, like most scanners)
  std::filesystem::path report;  // settings and counts; "" = SCAN.scan.json
  std::filesystem::path truth_in;   // the body's TRUTH.json; "" = none
  std::filesystem::path truth_out;  // the scan's truth; "" = SCAN.truth.json (only with truth_in)
  std::filesystem::path preview;    // PNG of the scan in the body frame; "" = none
};

// `path` with its extension replaced by `suffix` ("scan.ply", ".truth.json"
// -> "scan.truth.json").
std::filesystem::path WithSuffix(const std::filesystem::path& path, const std::string& suffix);

// Simulates (SimulateScan) and writes the files. `body`: body frame, mm.
ScanSimResult SimulateScanToFiles(const ScanSimOptions& options, const ScanSimFiles& files,
                                  const TriangleMesh& body, Progress* progress = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_FILES_H_
