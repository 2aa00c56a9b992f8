// PCD v0.7 reader: ascii, binary and binary_compressed (LZF, via Debian's
// liblzf). The header is parsed and checked by pcd_header.cc; this file
// checks the data sizes before allocating and maps the fields:
// x y z -> points; normal_x normal_y normal_z -> normals; rgb / rgba (4
// bytes, packed 0x00RRGGBB as float bits or uint) -> colours; any other
// one-value field -> cloud.scalars; multi-value fields (histograms), 8-byte
// integers and '_' padding are skipped. Organised clouds keep their NaN
// points here; scan_io.cc drops and counts them.
#include <lzf.h>

#include <algorithm>
#include <cstring>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"
#include "scanners/io/pcd_header.h"

namespace bespoke::io {
namespace {

// LZF cannot expand data more than ~88 times (a 3-byte back reference
// copies at most 264 bytes); anything claiming more is corrupt.
constexpr std::int64_t kMaxLzfRatio = 100;

enum class Target { kX, kY, kZ, kNx, kNy, kNz, kRgb, kScalar, kSkip };

struct Layout {
  std::vector<Target> targets;  // one per header field
  bool normals = false, colors = false;
};

// A field that exists and holds one readable value per point.
bool Usable(const PcdHeader& h, const char* name) {
  const int i = h.FindField(name);
  return i >= 0 && h.fields[static_cast<std::size_t>(i)].readable &&
         h.fields[static_cast<std::size_t>(i)].count == 1;
}

Layout MakeLayout(const PcdHeader& h, RawScan* raw) {
  Layout layout;
  layout.normals = Usable(h, "normal_x") && Usable(h, "normal_y") && Usable(h, "normal_z");
  for (const PcdField& f : h.fields) {
    Target t = Target::kScalar;
    if (f.name == "_") {
      t = Target::kSkip;
    } else if (!f.readable || f.count != 1) {
      t = Target::kSkip;
      raw->warnings.push_back("field '" + f.name + "' (" + std::to_string(f.count) + " x " +
                              std::to_string(f.size) + "-byte " + f.type + ") skipped");
    } else if (f.name == "x" || f.name == "y" || f.name == "z") {
      t = f.name == "x" ? Target::kX : f.name == "y" ? Target::kY : Target::kZ;
    } else if (layout.normals && f.name == "normal_x") {
      t = Target::kNx;
    } else if (layout.normals && f.name == "normal_y") {
      t = Target::kNy;
    } else if (layout.normals && f.name == "normal_z") {
      t = Target::kNz;
    } else if ((f.name == "rgb" || f.name == "rgba") && f.size == 4 && !layout.colors) {
      t = Target::kRgb;
      layout.colors = true;
    }
    layout.targets.push_back(t);
    if (f.name != "_") raw->fields.push_back(f.name);
  }
  return layout;
}

// Allocates the attributes of `n` points (the caller checked n against the
// data); returns each field's scalar vector (null when not a scalar).
std::vector<Eigen::VectorXd*> Allocate(const PcdHeader& h, const Layout& layout, RawScan* raw) {
  const Eigen::Index n = h.points;
  raw->cloud.points.resize(n, 3);
  if (layout.normals) raw->cloud.normals.resize(n, 3);
  if (layout.colors) raw->cloud.colors.resize(n, 3);
  std::vector<Eigen::VectorXd*> scalars(h.fields.size(), nullptr);
  for (std::size_t f = 0; f < h.fields.size(); ++f) {
    if (layout.targets[f] != Target::kScalar) continue;
    scalars[f] = &raw->cloud.scalars[h.fields[f].name];
    scalars[f]->resize(n);
  }
  return scalars;
}

void Store(Target target, Eigen::VectorXd* scalar, Eigen::Index i, double value,
           std::uint32_t packed, RawScan* raw) {
  PointCloud& c = raw->cloud;
  switch (target) {
    case Target::kX:
      c.points(i, 0) = value;
      break;
    case Target::kY:
      c.points(i, 1) = value;
      break;
    case Target::kZ:
      c.points(i, 2) = value;
      break;
    case Target::kNx:
      c.normals(i, 0) = value;
      break;
    case Target::kNy:
      c.normals(i, 1) = value;
      break;
    case Target::kNz:
      c.normals(i, 2) = value;
      break;
    case Target::kRgb:
      c.colors(i, 0) = static_cast<std::uint8_t>((packed >> 16) & 0xff);
      c.colors(i, 1) = static_cast<std::uint8_t>((packed >> 8) & 0xff);
      c.colors(i, 2) = static_cast<std::uint8_t>(packed & 0xff);
      break;
    case Target::kScalar:
      (*scalar)[i] = value;
      break;
    case Target::kSkip:
      break;
  }
}

// Binary data: point i's value of field f is at bases[f] + i * strides[f]
// (interleaved for "binary", one block per field for "binary_compressed").
void ReadColumns(const PcdHeader& h, const Layout& layout, const std::vector<const char*>& bases,
                 const std::vector<std::int64_t>& strides, RawScan* raw) {
  const std::vector<Eigen::VectorXd*> scalars = Allocate(h, layout, raw);
  PointCloud& c = raw->cloud;
  // Chunks of points, all fields per chunk, so the source bytes stay in cache.
  constexpr Eigen::Index kChunk = 4096;
  for (Eigen::Index first = 0; first < h.points; first += kChunk) {
    const Eigen::Index count = std::min(kChunk, h.points - first);
    for (std::size_t f = 0; f < h.fields.size(); ++f) {
      const Target target = layout.targets[f];
      const char* src = bases[f] + first * strides[f];
      double* column = nullptr;  // Eigen matrices are column-major: columns are contiguous
      switch (target) {
        case Target::kX:
        case Target::kY:
        case Target::kZ:
          column = c.points.col(static_cast<int>(target) - static_cast<int>(Target::kX)).data();
          break;
        case Target::kNx:
        case Target::kNy:
        case Target::kNz:
          column = c.normals.col(static_cast<int>(target) - static_cast<int>(Target::kNx)).data();
          break;
        case Target::kScalar:
          column = scalars[f]->data();
          break;
        case Target::kRgb:
          for (Eigen::Index i = 0; i < count; ++i) {
            Store(target, nullptr, first + i, 0.0, LoadUint32Le(src + i * strides[f]), raw);
          }
          break;
        case Target::kSkip:
          break;
      }
      if (column) ConvertColumn(src, strides[f], h.fields[f].scalar, false, count, column + first);
    }
  }
}

void ReadBinary(const std::filesystem::path& file, const PcdHeader& h, const Layout& layout,
                std::string_view data, RawScan* raw) {
  if (h.points > static_cast<std::int64_t>(data.size()) / h.point_bytes) {
    Fail(file, "byte offset " + std::to_string(h.data_offset) + ": " + std::to_string(h.points) +
                   " points of " + std::to_string(h.point_bytes) + " bytes need " +
                   std::to_string(h.points * h.point_bytes) + " bytes but only " +
                   std::to_string(data.size()) + " follow the header (truncated file?)");
  }
  std::vector<const char*> bases;
  std::vector<std::int64_t> strides;
  for (const PcdField& f : h.fields) {
    bases.push_back(data.data() + f.offset);
    strides.push_back(h.point_bytes);
  }
  ReadColumns(h, layout, bases, strides, raw);
  const std::int64_t extra = static_cast<std::int64_t>(data.size()) - h.points * h.point_bytes;
  if (extra > 0) raw->warnings.push_back(std::to_string(extra) + " bytes after the data ignored");
}

void ReadCompressed(const std::filesystem::path& file, const PcdHeader& h, const Layout& layout,
                    std::string_view data, RawScan* raw) {
  const std::string where = "byte offset " + std::to_string(h.data_offset);
  if (data.size() < 8) Fail(file, where + ": the compressed block's sizes are missing (truncated)");
  const std::uint32_t packed_size = LoadUint32Le(data.data());
  const std::uint32_t unpacked_size = LoadUint32Le(data.data() + 4);
  const std::int64_t expected = h.points * h.point_bytes;
  if (unpacked_size != expected) {
    Fail(file, where + ": the compressed block unpacks to " + std::to_string(unpacked_size) +
                   " bytes but " + std::to_string(h.points) + " points of " +
                   std::to_string(h.point_bytes) + " bytes need " + std::to_string(expected));
  }
  if (packed_size > data.size() - 8) {
    Fail(file, where + ": the compressed block claims " + std::to_string(packed_size) +
                   " bytes but only " + std::to_string(data.size() - 8) + " follow (truncated)");
  }
  if (expected > 0 && (packed_size == 0 || expected > kMaxLzfRatio * packed_size + 1024)) {
    Fail(file, where + ": " + std::to_string(packed_size) + " compressed bytes cannot unpack to " +
                   std::to_string(expected) + " bytes (corrupt sizes)");
  }
  std::vector<char> unpacked(static_cast<std::size_t>(expected));
  if (expected > 0) {
    const unsigned got = lzf_decompress(data.data() + 8, packed_size, unpacked.data(),
                                        static_cast<unsigned>(expected));
    if (got != expected) {
      Fail(file, where + ": the LZF-compressed data is corrupt (unpacked " + std::to_string(got) +
                     " of " + std::to_string(expected) + " bytes)");
    }
  }
  std::vector<const char*> bases;
  std::vector<std::int64_t> strides;
  for (const PcdField& f : h.fields) {
    bases.push_back(unpacked.data() + h.points * f.offset);  // one block per field
    strides.push_back(f.size * f.count);
  }
  ReadColumns(h, layout, bases, strides, raw);
}

// One token (ascii): rgb is the packed integer (PCL writes it so) or a float
// whose bits are the packed colour.
std::uint32_t PackedColour(std::string_view token, double value) {
  std::int64_t integer = 0;
  if (ParseInt64(token, &integer) && integer >= 0 && integer <= 0xffffffffLL) {
    return static_cast<std::uint32_t>(integer);
  }
  const float f = SafeFloat(value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof(bits));
  return bits;
}

void ReadAscii(const std::filesystem::path& file, const PcdHeader& h, const Layout& layout,
               std::string_view data, RawScan* raw) {
  std::int64_t values = 0;
  for (const PcdField& f : h.fields) values += f.count;
  if (h.points > (static_cast<std::int64_t>(data.size()) + 1) / (2 * values)) {
    Fail(file, "line " + std::to_string(h.data_line) + ": " + std::to_string(h.points) +
                   " points of " + std::to_string(values) + " values cannot fit in the " +
                   std::to_string(data.size()) + " bytes that follow (truncated file?)");
  }
  const std::vector<Eigen::VectorXd*> scalars = Allocate(h, layout, raw);
  LineCursor lines(data, h.data_offset, h.data_line);
  std::vector<std::string_view> tokens;
  std::string_view line;
  for (Eigen::Index i = 0; i < h.points; ++i) {
    do {
      if (!lines.Next(&line)) {
        Fail(file, "file ends after " + std::to_string(i) + " of " + std::to_string(h.points) +
                       " points (truncated)");
      }
    } while (Tokenize(line, &tokens) == 0);
    const std::string where = "line " + std::to_string(lines.line_number());
    if (static_cast<std::int64_t>(tokens.size()) != values) {
      Fail(file, where + ": expected " + std::to_string(values) + " values, found " +
                     std::to_string(tokens.size()));
    }
    std::size_t t = 0;
    for (std::size_t f = 0; f < h.fields.size(); ++f) {
      const PcdField& field = h.fields[f];
      const std::size_t first = t;
      t += static_cast<std::size_t>(field.count);
      if (layout.targets[f] == Target::kSkip) continue;
      double v = 0.0;
      if (!ParseDouble(tokens[first], &v)) {
        Fail(file, where + ": " + Quote(tokens[first]) + " is not a number");
      }
      if (field.scalar == ScalarType::kFloat32 && layout.targets[f] != Target::kRgb) {
        v = SafeFloat(v);
      }
      const std::uint32_t packed =
          layout.targets[f] == Target::kRgb ? PackedColour(tokens[first], v) : 0;
      Store(layout.targets[f], scalars[f], i, v, packed, raw);
    }
  }
  while (lines.Next(&line)) {
    if (!Trim(line).empty()) {
      Fail(file, "line " + std::to_string(lines.line_number()) +
                     ": data after the last point (POINTS is too small)");
    }
  }
}

}  // namespace

RawScan ReadPcd(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  const PcdHeader header = ParsePcdHeader(options, file, bytes);
  RawScan raw;
  raw.encoding = ToString(header.encoding);
  const Layout layout = MakeLayout(header, &raw);
  const std::string_view data = bytes.substr(header.data_offset);
  switch (header.encoding) {
    case PcdEncoding::kAscii:
      ReadAscii(file, header, layout, data, &raw);
      break;
    case PcdEncoding::kBinary:
      ReadBinary(file, header, layout, data, &raw);
      break;
    case PcdEncoding::kBinaryCompressed:
      ReadCompressed(file, header, layout, data, &raw);
      break;
  }
  return raw;
}

}  // namespace bespoke::io
