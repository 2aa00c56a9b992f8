// `bespoke info SCAN [--units mm|cm|dm|m] [--json]`: what Bespoke reads from
// a scan or mesh file: format and encoding, points (in the file, NaN/Inf
// dropped, kept), faces, per-point fields, bounds in file units and in mm, the
// file's length unit (given or guessed from the extent) and any warnings.
// The file is read exactly as every other command reads it (ReadScan), so a
// file `info` accepts is one the pipeline accepts; a malformed file, or one
// too small or too oddly sized to be a body without --units, is an InputError
// (exit 1) naming the file and the problem.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "pipeline/cli/commands.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct InfoOptions {
  std::filesystem::path scan;  // the file to inspect
  std::string units;           // "" (guess, default) or mm / cm / dm / m
  bool json = false;           // print JSON instead of text (default off)

  void Check() const {
    if (!units.empty() && !ParseLengthUnit(units)) {
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
    }
  }
};

nlohmann::json BoxJson(const Eigen::AlignedBox3d& box, double scale) {
  if (box.isEmpty()) return nullptr;
  return {{"min", ToJson(box.min() * scale)}, {"max", ToJson(box.max() * scale)}};
}

nlohmann::json InfoJson(const Scan& scan) {
  const ReadReport& r = scan.report;
  const double mm = MillimetresPer(r.unit);
  nlohmann::json j = {
      {"file", r.file.string()},
      {"format", ToString(r.format)},
      {"encoding", r.encoding},
      {"points_in_file", r.points_in_file},
      {"non_finite_dropped", r.non_finite_dropped},
      {"points", scan.cloud.size()},
      {"faces_in_file", r.faces_in_file},
      {"fields", r.fields},
      {"file_unit", ToString(r.unit)},
      {"unit_guessed", r.unit_guessed},
      {"bounds_file_units", BoxJson(r.bounds_file_units, 1.0)},
      {"bounds_mm", BoxJson(r.bounds_file_units, mm)},
      {"warnings", r.warnings},
  };
  if (!r.bounds_file_units.isEmpty()) j["size_mm"] = ToJson(r.bounds_file_units.sizes() * mm);
  return j;
}

std::string Triple(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out.precision(6);
  out << v.x() << ", " << v.y() << ", " << v.z();
  return out.str();
}

void PrintText(const Scan& scan) {
  const ReadReport& r = scan.report;
  const double mm = MillimetresPer(r.unit);
  std::cout << "file:      " << r.file.string() << "\n"
            << "format:    " << ToString(r.format) << " (" << r.encoding << ")\n"
            << "points:    " << scan.cloud.size() << " kept of " << r.points_in_file
            << " in the file (" << r.non_finite_dropped << " NaN/Inf dropped)\n"
            << "faces:     " << r.faces_in_file << "\n"
            << "fields:   ";
  for (const std::string& field : r.fields) std::cout << " " << field;
  std::cout << "\nunit:      " << ToString(r.unit)
            << (r.unit_guessed ? " (guessed from the extent; override with --units)" : " (given)")
            << "\n";
  if (!r.bounds_file_units.isEmpty()) {
    const Eigen::AlignedBox3d& b = r.bounds_file_units;
    std::cout << "bounds:    min (" << Triple(b.min()) << ") max (" << Triple(b.max()) << ") "
              << ToString(r.unit) << "\n"
              << "bounds mm: min (" << Triple(b.min() * mm) << ") max (" << Triple(b.max() * mm)
              << ")\n"
              << "size mm:   " << Triple(b.sizes() * mm) << "\n";
  }
  for (const std::string& warning : r.warnings) std::cout << "warning:   " << warning << "\n";
}

}  // namespace

CommandRunner SetupInfoCommand(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  app.add_option("SCAN", options->scan,
                 "Scan or mesh file (.ply .pcd .obj .xyz .csv .txt .off .stl)")
      ->required();
  app.add_option("--units", options->units,
                 "The file's length unit: mm, cm, dm or m (default: guessed from its size)");
  app.add_flag("--json", options->json, "Print JSON instead of text");
  return [options](const GlobalOptions&) {
    options->Check();
    ReadOptions read;
    if (!options->units.empty()) read.units = ParseLengthUnit(options->units);
    const Scan scan = ReadScan(read, options->scan);
    if (options->json) {
      std::cout << InfoJson(scan).dump(2) << "\n";
    } else {
      PrintText(scan);
    }
    return 0;
  };
}

}  // namespace bespoke
