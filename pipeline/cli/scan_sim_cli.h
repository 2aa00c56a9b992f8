// The virtual scanner's command-line options, shared by `bespoke scan-sim`
// and `bespoke synth-set`: declared on a CLI11 app, checked, and turned into
// ScanSimOptions / ScanSimFiles settings.
#ifndef BESPOKE_PIPELINE_CLI_SCAN_SIM_CLI_H_
#define BESPOKE_PIPELINE_CLI_SCAN_SIM_CLI_H_

#include <cstdint>
#include <string>

#include "oracle/scan_sim/scan_sim.h"
#include "oracle/scan_sim/scan_sim_files.h"

namespace CLI {
class App;
}

namespace bespoke {

struct ScanSimCli {
  std::uint64_t seed = 1;          // --seed
  double noise_mm = 1.0;           // --noise-mm
  std::string booth = "default";   // --booth NAME (oracle/scan_sim/booth.h BoothPreset)
  std::string sensors;             // --sensors DIRECTIONSxHEIGHTS, or N (N x 1); "" = the booth's
  std::string resolution;          // --resolution WIDTHxHEIGHT pixels per sensor; "" = the booth's
  double outliers = 0.02;          // --outliers (fraction of the output)
  bool floor = true;               // --floor / --no-floor
  int stray_objects = 0;           // --stray-objects
  std::string transform = "none";  // --transform none|random|y-up
  std::string units = "m";         // --units m|mm (of the written scan)
  double misalign_mm = 0;          // --misalign-mm
  double misalign_deg = 0;         // --misalign-deg
  bool pcd = false;                // --pcd
  bool labels = false;             // --labels
  // Throws InputError naming the option when a value is malformed.
  void Check() const;
  ScanSimOptions ToOptions() const;
  // Units, PCD and labels into `files`.
  void Apply(ScanSimFiles* files) const;
};

// Declares the options above on `app`, bound to `cli` (--seed only when
// `seed_option`).
void AddScanSimOptions(CLI::App& app, ScanSimCli* cli, bool seed_option = true);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_CLI_SCAN_SIM_CLI_H_
