// PCD v0.7 writer (ascii, binary, binary_compressed), laid out the way PCL
// writes its own point types so PCL tools read the files: every field is a
// 4-byte float (x y z, normal_x normal_y normal_z, scalars), colour is the
// packed "rgb" float (0x00RRGGBB bits; as the packed integer in ascii, as PCL
// does). Positions are therefore rounded to float (about 0.1 um at 2 m).
#include <lzf.h>

#include <cstring>
#include <functional>
#include <limits>

#include "scanners/core/errors.h"
#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"
#include "scanners/io/pcd_header.h"

namespace bespoke::io {
namespace {

struct OutField {
  std::string name;
  std::function<float(Eigen::Index)> value;  // unused for rgb
  bool rgb = false;
};

std::uint32_t Packed(const ColorMatrix& colors, Eigen::Index i) {
  return (std::uint32_t{colors(i, 0)} << 16) | (std::uint32_t{colors(i, 1)} << 8) |
         std::uint32_t{colors(i, 2)};
}

float PackedAsFloat(std::uint32_t packed) {
  float f = 0.0f;
  std::memcpy(&f, &packed, sizeof(f));
  return f;
}

std::vector<OutField> Fields(const PointCloud& cloud) {
  std::vector<OutField> fields;
  const char* xyz[] = {"x", "y", "z"};
  const char* nxyz[] = {"normal_x", "normal_y", "normal_z"};
  for (int c = 0; c < 3; ++c) {
    fields.push_back(
        {xyz[c], [&cloud, c](Eigen::Index i) { return SafeFloat(cloud.points(i, c)); }});
  }
  if (cloud.has_normals()) {
    for (int c = 0; c < 3; ++c) {
      fields.push_back(
          {nxyz[c], [&cloud, c](Eigen::Index i) { return SafeFloat(cloud.normals(i, c)); }});
    }
  }
  if (cloud.has_colors()) {
    fields.push_back(
        {"rgb", [&cloud](Eigen::Index i) { return PackedAsFloat(Packed(cloud.colors, i)); }, true});
  }
  NameSet used;
  for (const OutField& f : fields) used.Unique(f.name);
  for (const auto& [name, values] : cloud.scalars) {
    if (values.size() != cloud.size()) continue;
    std::string safe = name.empty() || name == "_" ? std::string("scalar") : name;  // '_' = padding
    for (char& ch : safe) {
      if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') ch = '_';
    }
    const Eigen::VectorXd* v = &values;
    fields.push_back({used.Unique(safe), [v](Eigen::Index i) { return SafeFloat((*v)[i]); }});
  }
  return fields;
}

std::string Header(const WriteOptions& options, const std::vector<OutField>& fields,
                   Eigen::Index n) {
  std::string out = "# .PCD v0.7 - Point Cloud Data file format\n";
  LineCursor lines(options.comment);
  std::string_view line;
  while (lines.Next(&line)) out += "# " + std::string(line) + "\n";
  out += "VERSION 0.7\nFIELDS";
  for (const OutField& f : fields) out += " " + f.name;
  out += "\nSIZE";
  for (std::size_t k = 0; k < fields.size(); ++k) out += " 4";
  out += "\nTYPE";
  for (std::size_t k = 0; k < fields.size(); ++k) out += " F";
  out += "\nCOUNT";
  for (std::size_t k = 0; k < fields.size(); ++k) out += " 1";
  out += "\nWIDTH " + std::to_string(n) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string(n) + "\nDATA " + ToString(options.pcd_encoding) + "\n";
  return out;
}

void AppendFloat(std::string* out, float value) {
  char b[4];
  std::memcpy(b, &value, 4);
  out->append(b, 4);
}

void AppendUint32(std::string* out, std::uint32_t value) {
  char b[4];
  std::memcpy(b, &value, 4);
  out->append(b, 4);
}

}  // namespace

std::string WritePcd(const WriteOptions& options, const PointCloud& cloud) {
  cloud.CheckShapes();
  const std::vector<OutField> fields = Fields(cloud);
  const Eigen::Index n = cloud.size();
  std::string out = Header(options, fields, n);
  if (options.pcd_encoding == PcdEncoding::kAscii) {
    for (Eigen::Index i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (k > 0) out += ' ';
        if (fields[k].rgb) {
          AppendNumber(&out, static_cast<std::int64_t>(Packed(cloud.colors, i)));
        } else {
          AppendNumber(&out, fields[k].value(i));
        }
      }
      out += '\n';
    }
    return out;
  }
  std::string data;
  data.reserve(static_cast<std::size_t>(n) * fields.size() * 4);
  if (options.pcd_encoding == PcdEncoding::kBinary) {
    for (Eigen::Index i = 0; i < n; ++i) {
      for (const OutField& f : fields) AppendFloat(&data, f.value(i));
    }
    return out + data;
  }
  for (const OutField& f : fields) {  // binary_compressed: one block per field
    for (Eigen::Index i = 0; i < n; ++i) AppendFloat(&data, f.value(i));
  }
  if (data.size() > std::numeric_limits<std::uint32_t>::max() / 2) {
    throw InputError("a cloud of " + std::to_string(n) +
                     " points is too large for PCD binary_compressed; write binary instead");
  }
  std::string packed(data.size() + data.size() / 16 + 64, '\0');
  unsigned packed_size = 0;
  if (!data.empty()) {
    packed_size = lzf_compress(data.data(), static_cast<unsigned>(data.size()), packed.data(),
                               static_cast<unsigned>(packed.size()));
    BESPOKE_CHECK(packed_size > 0, "LZF compression of the PCD data failed");
  }
  AppendUint32(&out, packed_size);
  AppendUint32(&out, static_cast<std::uint32_t>(data.size()));
  out.append(packed.data(), packed_size);
  return out;
}

}  // namespace bespoke::io
