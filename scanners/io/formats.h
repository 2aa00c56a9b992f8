// Internal to scanners/io: what every format reader returns, and the
// per-format readers and writers behind scan_io.h.
//
// Readers parse `bytes` (the whole file; `file` only names it in messages)
// into a RawScan in the FILE's units, non-finite points still included; the
// shared code in scan_io.cc drops them, resolves the unit and builds the
// report. Every reader validates counts against the bytes left before
// allocating and throws InputError("<file>: <what>, line N / byte offset N").
// Faces are already triangulated (polygon fans) and their indices checked
// against the vertex count.
//
// Writers return the complete file contents; scan_io.cc writes them
// atomically. Clouds and meshes are written in whatever units they are in.
#ifndef BESPOKE_SCANNERS_IO_FORMATS_H_
#define BESPOKE_SCANNERS_IO_FORMATS_H_

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "scanners/core/types.h"
#include "scanners/io/scan_io.h"

namespace bespoke::io {

struct RawScan {
  PointCloud cloud;             // file units; may hold NaN/Inf points
  Eigen::MatrixX3i faces;       // #T x 3 triangles, 0 x 3 for point formats
  std::vector<int> face_group;  // OBJ: group of each triangle
  std::vector<std::string> group_names;
  std::string encoding;               // "ascii", "binary_little_endian", ...
  std::vector<std::string> fields;    // per-point properties as named in the file
  std::int64_t faces_in_file = 0;     // polygons in the file (before triangulation)
  std::vector<std::string> warnings;  // things skipped or repaired, for the report
};

RawScan ReadPly(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);
RawScan ReadPcd(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);
RawScan ReadObj(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);
RawScan ReadXyz(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);
RawScan ReadOff(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);
RawScan ReadStl(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes);

// True when `bytes` is a binary STL (its size matches the triangle count).
bool LooksLikeBinaryStl(std::string_view bytes);

// Writers. `faces` may be empty (0 x 3) where the format allows it.
std::string WritePly(const WriteOptions& options, const PointCloud& cloud,
                     const Eigen::MatrixX3i& faces);
std::string WritePcd(const WriteOptions& options, const PointCloud& cloud);
// Text with a header line of names: "//x y z nx ..." (CloudCompare style,
// space separated) or, with separator ',', a CSV header "x,y,z,...".
std::string WriteXyz(const WriteOptions& options, const PointCloud& cloud, char separator);
std::string WriteObj(const WriteOptions& options, const TriangleMesh& mesh);
std::string WriteOff(const WriteOptions& options, const TriangleMesh& mesh);
std::string WriteStl(const WriteOptions& options, const TriangleMesh& mesh);

// Shared checks used by several readers.
// Throws unless 0 <= count <= options.max_elements.
void CheckCount(const ReadOptions& options, const std::filesystem::path& file, std::int64_t count,
                const std::string& what, const std::string& where);
// Builds the #T x 3 face matrix from a flat triangle list and checks every
// index is in [0, num_vertices).
Eigen::MatrixX3i TrianglesToMatrix(const std::filesystem::path& file, const std::vector<int>& flat,
                                   Eigen::Index num_vertices);
// Hands out distinct names: `name` itself, else name_2, name_3, ... in
// amortised constant time (files may repeat a column name 100,000s of times).
class NameSet {
 public:
  std::string Unique(const std::string& name);

 private:
  std::unordered_set<std::string> used_;
  std::unordered_map<std::string, int> next_suffix_;
};

// Maps a colour value to 0-255: integers are clamped, floats (0-1) scaled.
std::uint8_t ColorByte(double value, bool is_float);

}  // namespace bespoke::io

#endif  // BESPOKE_SCANNERS_IO_FORMATS_H_
