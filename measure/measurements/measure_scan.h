// The per-scan glue between cleaning and the measurement files, shared by
// `bespoke measure` and the batch job's measure step:
//
//   FindLandmarks        DetectLandmarks on the cleaned cloud, then the
//                        tailor's override file (if any) applied on top;
//                        with an override file, a detector that cannot run
//                        (InputError) leaves the overridden points only.
//   WriteMeasureOutputs  the measurement document (JSON, docs/contracts.md)
//                        and whichever of CSV, Valentina .vit, FreeSewing
//                        JSON and the PNG render are asked for; each atomic.
//
// Input: the cleaned cloud (body frame, mm) and body_from_scanner (the
// scan's own axes in mm -> body frame, from CleanScan). Failure: InputError
// for a bad override file or output path (checked before any work by
// CheckMeasureOutputs), as the called functions otherwise.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_MEASURE_SCAN_H_
#define BESPOKE_MEASURE_MEASUREMENTS_MEASURE_SCAN_H_

#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "measure/landmarks/landmarks.h"
#include "measure/measurements/measure.h"

namespace bespoke {

struct FoundLandmarks {
  LandmarkSet set;
  std::vector<std::string> warnings;  // e.g. the detector's error when overrides stand in
  MeasureStage stage{"landmarks"};    // detection + overrides, wall and CPU
};

FoundLandmarks FindLandmarks(const LandmarkOptions& options, const PointCloud& body_cloud,
                             const Eigen::Isometry3d& body_from_scanner,
                             const std::filesystem::path& overrides, Progress* progress = nullptr);

struct MeasureOutputs {
  std::filesystem::path json;        // required: the measurement document (.json)
  std::filesystem::path csv;         // "" = none; else .csv
  std::filesystem::path vit;         // "" = none; else .vit
  std::filesystem::path freesewing;  // "" = none; else .json
  std::filesystem::path render;      // "" = none; else .png
  bool geometry = false;             // hull loops and paths in the JSON document
};

// InputError naming the file for a wrong extension or a missing folder.
void CheckMeasureOutputs(const MeasureOutputs& outputs);

// Writes every requested output; `extra` goes into the JSON document
// (MeasurementDocument). Returns the files written, in order.
std::vector<std::filesystem::path> WriteMeasureOutputs(const MeasureOutputs& outputs,
                                                       const PointCloud& body_cloud,
                                                       const LandmarkSet& landmarks,
                                                       const MeasureResult& result,
                                                       const nlohmann::json& extra);

// The landmark options as written under "settings".
nlohmann::json ToJson(const LandmarkOptions& options);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_MEASURE_SCAN_H_
