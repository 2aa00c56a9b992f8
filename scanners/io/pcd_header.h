// Internal to scanners/io: the PCD v0.7 header and its validation.
//
// ParsePcdHeader reads the header lines (comments '#', VERSION, FIELDS, SIZE,
// TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA; DATA ends the header)
// and checks, before anything is allocated: every keyword at most once and
// known; FIELDS/SIZE/TYPE/COUNT of equal length; TYPE F with SIZE 4 or 8,
// I/U with 1, 2, 4 or 8; COUNT >= 1; WIDTH * HEIGHT == POINTS (POINTS
// defaults to WIDTH * HEIGHT, HEIGHT to 1); POINTS in [0, max_elements];
// scalar fields x, y, z; DATA ascii, binary or binary_compressed. The data
// sizes are checked by the reader (pcd.cc), which knows the encoding's layout.
#ifndef BESPOKE_SCANNERS_IO_PCD_HEADER_H_
#define BESPOKE_SCANNERS_IO_PCD_HEADER_H_

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scanners/io/byte_reader.h"
#include "scanners/io/scan_io.h"

namespace bespoke::io {

struct PcdField {
  std::string name;
  int size = 4;     // bytes of one value
  char type = 'F';  // 'F', 'I' or 'U'
  std::int64_t count = 1;
  bool readable = true;                      // false for 8-byte integers (skipped: no exact double)
  ScalarType scalar = ScalarType::kFloat32;  // when readable
  std::int64_t offset = 0;                   // byte offset of its first value inside a point
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::int64_t width = 0, height = 1, points = 0;
  std::int64_t point_bytes = 0;  // sum of size * count
  PcdEncoding encoding = PcdEncoding::kAscii;
  std::size_t data_offset = 0;                 // first byte after the DATA line
  std::int64_t data_line = 0;                  // line number of the first data line
  int FindField(std::string_view name) const;  // index, or -1
};

PcdHeader ParsePcdHeader(const ReadOptions& options, const std::filesystem::path& file,
                         std::string_view bytes);

std::string ToString(PcdEncoding encoding);  // "ascii", "binary", "binary_compressed"

}  // namespace bespoke::io

#endif  // BESPOKE_SCANNERS_IO_PCD_HEADER_H_
