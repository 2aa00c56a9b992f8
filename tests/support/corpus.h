// Scan folders for the batch tests and the reliability script: good scans and
// malformed or hostile files.
//
// Good scans: WriteSyntheticBodyScan scans a parametric body (oracle/body,
// coarse mesh, girths scaled) with the virtual booth (oracle/scan_sim:
// noise, outliers, floor), rotated about z and written in metres as binary
// PLY: a person the whole job (clean, landmarks, measure) works on.
//
// Hostile files (WriteHostileFiles), each a different way a file can be bad:
//   truncated.ply      a good binary PLY cut at 60 % of its bytes
//   huge_count.ply     header claims 4,000,000,000 vertices, 24 bytes of data
//   all_nan.ply        5,000 points, every coordinate NaN
//   zero_points.ply    a valid header with 0 vertices
//   empty.xyz          0 bytes
//   garbage.pcd        4 kB of random bytes
//   folder.ply/        a folder named like a scan
//   fifo.ply           a FIFO: opening it would block forever; as root,
//                      permission bits do not stop reads, so a FIFO and a
//                      dangling symlink are the honest "unreadable" files
//   dangling.ply       a symbolic link to a file that does not exist
//   header_lies.ply    binary PLY whose header says double but data is float-sized
// Returns the names written (10).
#ifndef BESPOKE_TESTS_SUPPORT_CORPUS_H_
#define BESPOKE_TESTS_SUPPORT_CORPUS_H_

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bespoke::testing {

struct SyntheticScanOptions {
  int points = 60000;        // about this many body points (the booth adds floor and outliers)
  double stature_mm = 1750;  // crown height
  double girth_scale = 1.0;  // widths and depths x this
  double noise_mm = 1.0;     // Gaussian noise per coordinate, mm
  double yaw_deg = 0;        // rotation about z
  std::uint32_t seed = 1;
};

void WriteSyntheticBodyScan(const SyntheticScanOptions& options, const std::filesystem::path& file);

std::vector<std::string> WriteHostileFiles(const std::filesystem::path& dir, std::uint32_t seed);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_CORPUS_H_
