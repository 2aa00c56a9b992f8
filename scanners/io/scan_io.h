// Reading and writing scans (point clouds) and meshes: the formats' front door.
//
// Formats: PLY (ascii, binary_little_endian, binary_big_endian), PCD (ascii,
// binary, binary_compressed), OBJ, XYZ/CSV/TXT text, OFF, STL (ascii, binary).
// The format is chosen by content (magic bytes), falling back to the extension.
//
// Safety: every file is parsed by Bespoke's own readers, which check every
// header field, element count and byte count against the file's size before
// allocating; third-party readers (PCL's, which assert or crash on some
// malformed files) are never handed a file. A malformed, truncated, empty,
// huge-count or unreadable file throws InputError("<file>: <what is wrong>").
//
// Units: a cloud's points are returned in millimetres. The file's unit is
// ReadOptions::units when set, else guessed from the extent of the finite
// points (GuessLengthUnit); the report says which and whether it was guessed.
// NaN/Inf points are dropped and counted.
//
// Writers are atomic (temporary file, then rename; scanners/core/atomic_file.h).
#ifndef BESPOKE_SCANNERS_IO_SCAN_IO_H_
#define BESPOKE_SCANNERS_IO_SCAN_IO_H_

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scanners/core/types.h"
#include "scanners/core/units.h"

namespace bespoke {

enum class FileFormat { kPly, kPcd, kObj, kXyz, kOff, kStl };
std::string ToString(FileFormat format);

struct ReadOptions {
  // The file's length unit; nullopt (default) guesses it from the extent.
  std::optional<LengthUnit> units;
  // Files claiming more points/vertices/faces than this are rejected before
  // anything is allocated. Default 50 million; at most 2^31 - 1 (face
  // indices are int).
  std::int64_t max_elements = 50'000'000;
  // A cloud with fewer finite points than this is not a body scan: InputError.
  // Default 1000. Set to 0 for non-body data (tests, patches).
  std::int64_t min_finite_points = 1000;
  // Throws InputError when a value is out of range.
  void Check() const;
};

// What a reader found, for `bespoke info` and the clean report.
struct ReadReport {
  std::filesystem::path file;
  FileFormat format = FileFormat::kPly;
  std::string encoding;             // "ascii", "binary_little_endian", "binary_compressed", ...
  std::vector<std::string> fields;  // per-point properties in the file, e.g. x y z nx ny nz red
  std::int64_t points_in_file = 0;  // as declared / found
  std::int64_t non_finite_dropped = 0;
  std::int64_t faces_in_file = 0;
  LengthUnit unit = LengthUnit::kMillimetre;  // unit the file was read in
  bool unit_guessed = false;                  // true when guessed from the extent
  Eigen::AlignedBox3d bounds_file_units;      // of the finite points, in file units
  // Things skipped or repaired while reading (ignored trailing bytes, normals
  // dropped because some were NaN, a mesh whose unit could not be guessed, ...).
  std::vector<std::string> warnings;
};

struct Scan {
  PointCloud cloud;  // millimetres, scanner axes
  ReadReport report;
};

// Reads a point cloud from any supported format (for meshes: the vertices).
Scan ReadScan(const ReadOptions& options, const std::filesystem::path& file);

struct Mesh {
  TriangleMesh mesh;  // file units are NOT converted: see report.unit (guessed)
  ReadReport report;
  // OBJ only: per-face group index into group_names ("g"/"o" statements),
  // empty for other formats. Polygons are fan-triangulated; every triangle
  // keeps its polygon's group.
  std::vector<int> face_group;
  std::vector<std::string> group_names;
};

// Reads a triangle mesh (OBJ, OFF, PLY with a face element, STL). Positions
// stay in the file's units (meshes feed geometry tools that must not rescale
// silently); report.unit is options.units or the guess (when no unit gives a
// body-sized extent, e.g. the Stanford bunny, report.unit is mm, unit_guessed
// is false and report.warnings says so). Throws InputError for malformed
// files, files without faces and vertices with NaN/Inf coordinates.
// min_finite_points does not apply to meshes.
Mesh ReadMesh(const ReadOptions& options, const std::filesystem::path& file);

// The same, from bytes already in memory (`file` names them in messages and
// its extension is the fallback for the format). For fuzzing and streams.
Scan ReadScanFromBytes(const ReadOptions& options, const std::filesystem::path& file,
                       std::string_view bytes);
Mesh ReadMeshFromBytes(const ReadOptions& options, const std::filesystem::path& file,
                       std::string_view bytes);

enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class PcdEncoding { kAscii, kBinary, kBinaryCompressed };

struct WriteOptions {
  PlyEncoding ply_encoding = PlyEncoding::kBinaryLittleEndian;  // default binary
  PcdEncoding pcd_encoding = PcdEncoding::kBinary;              // default binary
  // Written as a comment in PLY/PCD/OBJ headers, e.g. "units mm; frame body".
  std::string comment;
};

// Writes a cloud; format from the extension (.ply, .pcd, .xyz/.txt, .csv).
// Normals, colours and scalars are written where the format can hold them.
// PLY keeps positions and scalars as doubles (exact round trip); PCD uses
// 4-byte floats, PCL's own layout, so PCL tools read it (about 0.1 um at
// 2 m); XYZ/CSV text is the shortest exact decimal, with a header line.
// Throws InputError for an unknown extension or a missing folder.
void WriteScan(const WriteOptions& options, const PointCloud& cloud,
               const std::filesystem::path& file);

// Writes a mesh; format from the extension (.obj, .ply, .off, .stl). STL is
// binary with float corners; the others keep doubles exactly. Throws
// InputError for face indices out of range or an unknown extension.
void WriteMesh(const WriteOptions& options, const TriangleMesh& mesh,
               const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_IO_SCAN_IO_H_
