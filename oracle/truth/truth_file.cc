#include "oracle/truth/truth_file.h"

#include "scanners/core/json_io.h"

namespace bespoke {

nlohmann::json TruthDocument(const Body& body, const Catalogue& catalogue,
                             const ReferenceOptions& options, const ReferenceMeasurements& truth) {
  using nlohmann::json;
  json doc = {{"format", "bespoke-measurements"},
              {"version", 1},
              {"units", "mm"},
              {"frame", "body"},
              {"source", "truth"},
              {"model", body.model}};
  // The subject's seed: a seeded parametric body reports seed 0 (the size
  // values are set) and the seed they were drawn from in drawn_from_seed.
  const auto seed = body.parameters.find("seed"), drawn = body.parameters.find("drawn_from_seed");
  if (drawn != body.parameters.end() && drawn->second > 0)
    doc["seed"] = static_cast<std::uint64_t>(drawn->second);
  else if (seed != body.parameters.end())
    doc["seed"] = static_cast<std::uint64_t>(seed->second);
  doc["parameters"] = json::object();
  for (const auto& [name, value] : body.parameters) doc["parameters"][name] = value;
  doc["landmarks"] = json::object();
  doc["landmark_surface"] = json::object();
  for (const auto& [name, point] : body.landmarks) {
    doc["landmarks"][name] = ToJson(PositionOf(body.mesh, point));
    doc["landmark_surface"][name] = {
        {"face", point.face},
        {"barycentric", {point.barycentric[0], point.barycentric[1], point.barycentric[2]}}};
  }
  doc["mesh"] = {{"vertices", body.mesh.num_vertices()}, {"faces", body.mesh.num_faces()}};
  doc["measurements"] = json::array();
  for (const ReferenceMeasurement& m : truth.measurements) {
    const MeasurementDef& def = catalogue.Measurement(m.name);
    json entry = {{"name", m.name},   {"kind", ToString(m.kind)},       {"value_mm", m.value_mm},
                  {"flags", m.flags}, {"method", ToString(def.method)}, {"datum", def.datum}};
    if (m.geometry.rows() > 0) {
      entry["geometry"] = json::array();
      for (Eigen::Index i = 0; i < m.geometry.rows(); ++i)
        entry["geometry"].push_back(ToJson(Eigen::Vector3d(m.geometry.row(i).transpose())));
    }
    doc["measurements"].push_back(entry);
  }
  doc["skipped"] = json::array();
  for (const auto& [name, reason] : truth.skipped)
    doc["skipped"].push_back({{"name", name}, {"reason", reason}});
  doc["settings"] = {{"datum_tolerance_mm", options.datum_tolerance_mm},
                     {"keep_geometry", options.keep_geometry}};
  return doc;
}

void WriteTruthFile(const std::filesystem::path& file, const Body& body, const Catalogue& catalogue,
                    const ReferenceOptions& options, const ReferenceMeasurements& truth) {
  WriteJsonFile(file, TruthDocument(body, catalogue, options, truth));
}

}  // namespace bespoke
