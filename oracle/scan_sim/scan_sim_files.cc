#include "oracle/scan_sim/scan_sim_files.h"

#include "oracle/scan_sim/scan_truth.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "scanners/render/render.h"

namespace bespoke {
namespace {

// The preview: front, right side and back of the scan in the body frame,
// with the truth's datum points when known.
void WritePreview(const ScanSimResult& result, const nlohmann::json* truth,
                  const std::filesystem::path& file) {
  PointCloud cloud = result.cloud;
  TransformInPlace(result.scanner_from_body.inverse(), &cloud);
  RenderScene scene;
  scene.cloud = &cloud;
  if (truth && truth->contains("landmarks")) {
    for (const auto& [name, value] : (*truth)["landmarks"].items()) {
      scene.points.push_back({"", Vector3FromJson(value, "landmark " + name)});
    }
  }
  RenderOptions options;
  options.views = {View::kFront, View::kRight, View::kBack};
  options.height_px = 700;
  options.title = file.stem().string();
  WritePng(Render(options, scene), file);
}

}  // namespace

std::filesystem::path WithSuffix(const std::filesystem::path& path, const std::string& suffix) {
  std::filesystem::path out = path;
  out.replace_extension();
  return out.string() + suffix;
}

ScanSimResult SimulateScanToFiles(const ScanSimOptions& options, const ScanSimFiles& files,
                                  const TriangleMesh& body, Progress* progress) {
  options.Check();
  if (files.scan.extension() != ".ply")
    throw InputError(files.scan, "the scan must be a .ply file");
  nlohmann::json truth;
  if (!files.truth_in.empty()) truth = ReadJsonFile(files.truth_in);  // read before the slow part
  const ScanSimResult result = SimulateScan(options, body, progress);
  PointCloud cloud = result.cloud;
  const double per_unit = MillimetresPer(files.units);
  cloud.points /= per_unit;
  if (!files.labels) cloud.scalars.clear();
  WriteOptions write;
  write.comment = "bespoke scan-sim seed " + std::to_string(options.seed) + "; units " +
                  ToString(files.units) + "; frame scanner";
  WriteScan(write, cloud, files.scan);
  if (files.pcd) WriteScan(write, cloud, WithSuffix(files.scan, ".pcd"));
  nlohmann::json report = ScanSimReport(options, result);
  report["file"] = files.scan.filename().string();
  report["file_unit"] = ToString(files.units);
  report["scanner_from_body"] = ToJson(result.scanner_from_body);
  WriteJsonFile(files.report.empty() ? WithSuffix(files.scan, ".scan.json") : files.report, report);
  if (!files.truth_in.empty()) {
    const std::filesystem::path out =
        files.truth_out.empty() ? WithSuffix(files.scan, ".truth.json") : files.truth_out;
    WriteJsonFile(out, ScanTruthDocument(truth, options, result, files.units,
                                         files.scan.filename().string(), files.truth_in.string()));
  }
  if (!files.preview.empty())
    WritePreview(result, files.truth_in.empty() ? nullptr : &truth, files.preview);
  return result;
}

}  // namespace bespoke
