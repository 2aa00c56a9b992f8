// Shared body of the libFuzzer targets: parse the input as a scan and as a
// mesh with the public readers. InputError is the expected outcome for
// malformed input; anything else escaping (InternalError, std::bad_alloc, a
// standard exception), a crash, a sanitizer report, a hang or a large
// allocation (-malloc_limit_mb in scripts/fuzz.sh) is a finding.
#ifndef BESPOKE_TESTS_FUZZ_FUZZ_COMMON_H_
#define BESPOKE_TESTS_FUZZ_FUZZ_COMMON_H_

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke::fuzz {

// Aborts (a finding) when a successful read returned inconsistent data.
inline void Require(bool condition) {
  if (!condition) __builtin_trap();
}

// `name`'s extension is the format fallback when the content says nothing.
inline void ReadEverything(const std::uint8_t* data, std::size_t size, const char* name) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  ReadOptions options;
  options.min_finite_points = 0;  // exercise the readers, not the body-size check
  if (size > 0 && (data[0] & 1)) options.units = LengthUnit::kMillimetre;  // both unit paths
  try {
    const Scan scan = ReadScanFromBytes(options, name, bytes);
    scan.cloud.CheckShapes();  // throws InternalError (a finding) when attributes disagree
    Require(scan.cloud.points.allFinite());
    Require(scan.report.points_in_file == scan.cloud.size() + scan.report.non_finite_dropped);
  } catch (const InputError&) {
  }
  try {
    const Mesh mesh = ReadMeshFromBytes(options, name, bytes);
    const auto& faces = mesh.mesh.faces;
    Require(faces.rows() > 0);
    Require(faces.minCoeff() >= 0 && faces.maxCoeff() < mesh.mesh.num_vertices());
    Require(mesh.face_group.empty() ||
            static_cast<Eigen::Index>(mesh.face_group.size()) == faces.rows());
    for (const int g : mesh.face_group) {
      Require(g >= 0 && g < static_cast<int>(mesh.group_names.size()));
    }
  } catch (const InputError&) {
  }
}

}  // namespace bespoke::fuzz

#endif  // BESPOKE_TESTS_FUZZ_FUZZ_COMMON_H_
