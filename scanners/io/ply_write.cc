// PLY writer: a cloud (and optionally triangles) in ascii, binary little or
// big endian. Positions and scalars as double (exact round trip), normals as
// float, colours as uchar, faces as "list uchar int vertex_indices".

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"
#include "scanners/io/ply_header.h"

namespace bespoke::io {
namespace {

// A PLY property name: no whitespace (the header is whitespace separated).
std::string SafeName(const std::string& name) {
  std::string out = name.empty() ? std::string("scalar") : name;
  for (char& c : out) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
  }
  return out;
}

std::string Comment(const std::string& text) {
  std::string out;
  LineCursor lines(text);
  std::string_view line;
  while (lines.Next(&line)) out += "comment " + std::string(line) + "\n";
  return out;
}

struct Column {
  const Eigen::MatrixX3d* matrix = nullptr;  // or
  const ColorMatrix* colors = nullptr;       // or
  const Eigen::VectorXd* scalar = nullptr;
  int col = 0;
  ScalarType type = ScalarType::kFloat64;
  double Value(Eigen::Index i) const {
    if (matrix) return (*matrix)(i, col);
    if (colors) return (*colors)(i, col);
    return (*scalar)[i];
  }
};

std::vector<std::pair<std::string, Column>> VertexColumns(const PointCloud& cloud) {
  std::vector<std::pair<std::string, Column>> columns;
  const char* xyz[] = {"x", "y", "z"};
  const char* nxyz[] = {"nx", "ny", "nz"};
  const char* rgb[] = {"red", "green", "blue"};
  NameSet used;
  for (int c = 0; c < 3; ++c) {
    columns.push_back({xyz[c], Column{&cloud.points, nullptr, nullptr, c, ScalarType::kFloat64}});
  }
  if (cloud.has_normals()) {
    for (int c = 0; c < 3; ++c) {
      columns.push_back(
          {nxyz[c], Column{&cloud.normals, nullptr, nullptr, c, ScalarType::kFloat32}});
    }
  }
  if (cloud.has_colors()) {
    for (int c = 0; c < 3; ++c) {
      columns.push_back({rgb[c], Column{nullptr, &cloud.colors, nullptr, c, ScalarType::kUint8}});
    }
  }
  for (const auto& column : columns) used.Unique(column.first);
  for (const auto& [name, values] : cloud.scalars) {
    if (values.size() != cloud.size()) continue;
    columns.push_back(
        {used.Unique(SafeName(name)), Column{nullptr, nullptr, &values, 0, ScalarType::kFloat64}});
  }
  return columns;
}

}  // namespace

std::string WritePly(const WriteOptions& options, const PointCloud& cloud,
                     const Eigen::MatrixX3i& faces) {
  cloud.CheckShapes();
  const auto columns = VertexColumns(cloud);
  std::string out = "ply\nformat " + ToString(options.ply_encoding) + " 1.0\n";
  if (!options.comment.empty()) out += Comment(options.comment);
  out += "element vertex " + std::to_string(cloud.size()) + "\n";
  for (const auto& [name, column] : columns) {
    out += std::string("property ") + PlyTypeName(column.type) + " " + name + "\n";
  }
  if (faces.rows() > 0) {
    out += "element face " + std::to_string(faces.rows()) + "\n";
    out += "property list uchar int vertex_indices\n";
  }
  out += "end_header\n";
  const bool ascii = options.ply_encoding == PlyEncoding::kAscii;
  const bool big = options.ply_encoding == PlyEncoding::kBinaryBigEndian;
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const Column& column = columns[k].second;
      const double v = column.Value(i);
      if (!ascii) {
        AppendScalar(&out, v, column.type, big);
        continue;
      }
      if (k > 0) out += ' ';
      if (column.type == ScalarType::kFloat32) {
        AppendNumber(&out, SafeFloat(v));
      } else if (column.type == ScalarType::kUint8) {
        AppendNumber(&out, static_cast<std::int64_t>(v));
      } else {
        AppendNumber(&out, v);
      }
    }
    if (ascii) out += '\n';
  }
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    if (ascii) {
      out += '3';
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        AppendNumber(&out, static_cast<std::int64_t>(faces(f, c)));
      }
      out += '\n';
    } else {
      AppendScalar(&out, 3, ScalarType::kUint8, big);
      for (int c = 0; c < 3; ++c) AppendScalar(&out, faces(f, c), ScalarType::kInt32, big);
    }
  }
  return out;
}

}  // namespace bespoke::io
