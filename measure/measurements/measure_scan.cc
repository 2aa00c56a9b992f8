#include "measure/measurements/measure_scan.h"

#include <chrono>
#include <ctime>

#include "measure/measurements/measure_render.h"
#include "measure/measurements/measurement_document.h"
#include "measure/measurements/measurement_exports.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

void CheckOne(const std::filesystem::path& file, const char* extension, const char* what) {
  if (file.empty()) return;
  if (file.extension() != extension)
    throw InputError(file, std::string("the ") + what + " must end in " + extension);
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
  if (!std::filesystem::is_directory(folder)) throw InputError(file, "its folder does not exist");
}

}  // namespace

FoundLandmarks FindLandmarks(const LandmarkOptions& options, const PointCloud& body_cloud,
                             const Eigen::Isometry3d& body_from_scanner,
                             const std::filesystem::path& overrides, Progress* progress) {
  const auto wall = std::chrono::steady_clock::now();
  const std::clock_t cpu = std::clock();
  FoundLandmarks found;
  LandmarkOverrides read;
  if (!overrides.empty())
    read = ReadLandmarkOverrides(overrides);  // bad file: fail before detecting
  try {
    found.set = DetectLandmarks(options, body_cloud, progress);
  } catch (const InputError& e) {
    if (overrides.empty()) throw;
    found.warnings.push_back(
        std::string("landmark detection failed, using the override file only: ") + e.what());
  }
  if (!overrides.empty()) ApplyLandmarkOverrides(read, body_from_scanner, &found.set);
  found.stage.time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  found.stage.cpu_s = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  return found;
}

void CheckMeasureOutputs(const MeasureOutputs& o) {
  if (o.json.empty()) throw InputError("an output measurement document (-o MEAS.json) is required");
  CheckOne(o.json, ".json", "measurement document");
  CheckOne(o.csv, ".csv", "CSV table");
  CheckOne(o.vit, ".vit", "Valentina file");
  CheckOne(o.freesewing, ".json", "FreeSewing file");
  CheckOne(o.render, ".png", "render");
}

std::vector<std::filesystem::path> WriteMeasureOutputs(const MeasureOutputs& o,
                                                       const PointCloud& body_cloud,
                                                       const LandmarkSet& landmarks,
                                                       const MeasureResult& result,
                                                       const nlohmann::json& extra) {
  CheckMeasureOutputs(o);
  std::vector<std::filesystem::path> written;
  const Catalogue& catalogue = Catalogue::Builtin();
  if (!o.csv.empty()) WriteMeasurementsCsv(o.csv, result), written.push_back(o.csv);
  if (!o.vit.empty()) WriteValentinaVit(o.vit, result, catalogue), written.push_back(o.vit);
  if (!o.freesewing.empty())
    WriteFreeSewingJson(o.freesewing, result, catalogue), written.push_back(o.freesewing);
  if (!o.render.empty())
    WriteMeasureRender(o.render, body_cloud, landmarks, result), written.push_back(o.render);
  // The document last: when it exists, everything it lists was written.
  WriteMeasurementDocument(o.json, MeasurementDocument(result, landmarks, extra, o.geometry));
  written.push_back(o.json);
  return written;
}

nlohmann::json ToJson(const LandmarkOptions& o) {
  return {{"slice_step_mm", o.slice_step_mm},
          {"slice_half_thickness_mm", o.slice_half_thickness_mm},
          {"only", o.only}};
}

}  // namespace bespoke
