// Internal to scanners/io: the PLY header (format, elements, properties) and
// its validation against the file's size.
//
// ParsePlyHeader reads from "ply" to "end_header" and checks, before anything
// is allocated: the magic line, one known format line, element counts in
// [0, max_elements], known property types (char/int8, uchar/uint8, short/int16,
// ushort/uint16, int/int32, uint/uint32, float/float32, double/float64),
// integer list-count types, no duplicate names, and that the elements'
// minimum sizes fit in the data that follows (binary: count * minimum item
// bytes; ascii: count * 2 bytes per value, since every value takes at least a
// digit and a separator). Throws InputError naming the file and the line.
#ifndef BESPOKE_SCANNERS_IO_PLY_HEADER_H_
#define BESPOKE_SCANNERS_IO_PLY_HEADER_H_

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scanners/io/byte_reader.h"
#include "scanners/io/scan_io.h"

namespace bespoke::io {

struct PlyProperty {
  std::string name;
  ScalarType type = ScalarType::kFloat32;  // the value type (lists: each item's)
  bool is_list = false;
  ScalarType count_type = ScalarType::kUint8;  // lists only
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::vector<PlyProperty> properties;
  std::int64_t header_line = 0;  // where it was declared

  // Bytes of one item when every list is empty (binary), i.e. its minimum size.
  std::int64_t MinBinaryBytes() const;
  bool HasLists() const;
  int FindProperty(std::string_view name) const;  // index, or -1
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // byte offset of the first data byte
  std::int64_t data_line = 0;   // line number of the first data line (ascii)
};

PlyHeader ParsePlyHeader(const ReadOptions& options, const std::filesystem::path& file,
                         std::string_view bytes);

// "ascii", "binary_little_endian", "binary_big_endian".
std::string ToString(PlyEncoding encoding);

// PLY's name for a scalar type: "uchar", "float", ...
const char* PlyTypeName(ScalarType type);

}  // namespace bespoke::io

#endif  // BESPOKE_SCANNERS_IO_PLY_HEADER_H_
