// PLY reader: ascii, binary_little_endian and binary_big_endian. The header is
// parsed and size-checked by ply_header.cc; this file walks the data.
//
// Vertex properties: x y z (required) -> points; nx ny nz (or normal_x ..)
// -> normals; red green blue (or diffuse_*; integers 0-255 or floats 0-1) ->
// colours; any other scalar -> cloud.scalars. The face element's
// vertex_indices / vertex_index list -> triangles (polygons fanned). Other
// elements and list properties are skipped by their declared sizes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"
#include "scanners/io/ply_header.h"

namespace bespoke::io {
namespace {

// Reads one element item at a time: the scalar properties' values (in
// declaration order) and the items of one chosen list property; other lists
// are skipped.
class ItemReader {
 public:
  virtual ~ItemReader() = default;
  virtual void Read(const PlyElement& element, int wanted_list, std::vector<double>* values,
                    std::vector<std::int64_t>* list) = 0;
  virtual std::string Where() const = 0;  // for messages: "line N" / "byte offset N"
  // Binary only: the next `bytes` bytes as one block (bounds checked), or
  // nullptr when the encoding has no fixed layout (ascii).
  virtual const char* TakeBlock(std::int64_t bytes) = 0;
  // Throws when non-blank data follows the last element (ascii only).
  virtual void Finish(std::vector<std::string>* warnings) = 0;
};

class BinaryItemReader : public ItemReader {
 public:
  BinaryItemReader(const std::filesystem::path& file, std::string_view bytes, std::size_t offset,
                   bool big_endian)
      : file_(file), bytes_(bytes), pos_(offset), big_endian_(big_endian) {}

  void Read(const PlyElement& element, int wanted_list, std::vector<double>* values,
            std::vector<std::int64_t>* list) override {
    item_start_ = pos_;
    values->clear();
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      if (!p.is_list) {
        values->push_back(Take(p.type));
        continue;
      }
      const double n = Take(p.count_type);  // an integer type: exact in a double
      const std::int64_t item = SizeOf(p.type);
      const std::size_t left = bytes_.size() - pos_;  // Take() keeps pos_ <= size
      if (n < 0 || static_cast<double>(left) < n * static_cast<double>(item)) {
        Fail(file_, Where() + ": list '" + p.name + "' of element '" + element.name + "' has " +
                        std::to_string(static_cast<std::int64_t>(n)) +
                        " items, which do not fit in the " + std::to_string(left) +
                        " bytes left (bad list count or truncated file)");
      }
      const auto count = static_cast<std::int64_t>(n);
      if (static_cast<int>(i) == wanted_list) {
        list->clear();
        for (std::int64_t k = 0; k < count; ++k) {
          const double v = Take(p.type);
          list->push_back(static_cast<std::int64_t>(v));
        }
      } else {
        pos_ += static_cast<std::size_t>(count * item);
      }
    }
  }

  std::string Where() const override { return "byte offset " + std::to_string(item_start_); }

  const char* TakeBlock(std::int64_t bytes) override {
    item_start_ = pos_;
    if (bytes < 0 || static_cast<std::uint64_t>(bytes) > bytes_.size() - pos_) {
      Fail(file_, Where() + ": file ends in the middle of an element (truncated)");
    }
    const char* block = bytes_.data() + pos_;
    pos_ += static_cast<std::size_t>(bytes);
    return block;
  }

  void Finish(std::vector<std::string>* warnings) override {
    if (pos_ < bytes_.size()) {
      warnings->push_back(std::to_string(bytes_.size() - pos_) +
                          " bytes after the last PLY element were ignored");
    }
  }

 private:
  double Take(ScalarType type) {
    const auto size = static_cast<std::size_t>(SizeOf(type));
    if (pos_ > bytes_.size() || bytes_.size() - pos_ < size) {
      Fail(file_, Where() + ": file ends in the middle of an element (truncated)");
    }
    const double v = LoadScalar(bytes_.data() + pos_, type, big_endian_);
    pos_ += size;
    return v;
  }

  const std::filesystem::path& file_;
  std::string_view bytes_;
  std::size_t pos_;
  std::size_t item_start_ = 0;
  bool big_endian_;
};

class AsciiItemReader : public ItemReader {
 public:
  AsciiItemReader(const std::filesystem::path& file, std::string_view bytes, std::size_t offset,
                  std::int64_t first_line)
      : file_(file), lines_(bytes.substr(offset), offset, first_line) {}

  void Read(const PlyElement& element, int wanted_list, std::vector<double>* values,
            std::vector<std::int64_t>* list) override {
    std::string_view line;
    do {
      if (!lines_.Next(&line)) {
        Fail(file_, "file ends before all " + std::to_string(element.count) + " '" + element.name +
                        "' items were read (truncated, line " +
                        std::to_string(lines_.line_number() + 1) + ")");
      }
    } while (Tokenize(line, &tokens_) == 0);
    values->clear();
    std::size_t t = 0;
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& p = element.properties[i];
      if (!p.is_list) {
        values->push_back(Number(t++, p.type, element));
        continue;
      }
      std::int64_t n = 0;
      if (t >= tokens_.size() || !ParseInt64(tokens_[t], &n) || n < 0) {
        Fail(file_, Where() + ": list '" + p.name + "' needs a count >= 0, found " +
                        (t < tokens_.size() ? Quote(tokens_[t]) : std::string("nothing")));
      }
      ++t;
      if (static_cast<std::int64_t>(tokens_.size() - t) < n) {
        Fail(file_, Where() + ": list '" + p.name + "' declares " + std::to_string(n) +
                        " items but only " + std::to_string(tokens_.size() - t) + " follow");
      }
      if (static_cast<int>(i) == wanted_list) {
        list->clear();
        for (std::int64_t k = 0; k < n; ++k, ++t) {
          std::int64_t v = 0;
          if (!ParseInt64(tokens_[t], &v)) {
            Fail(file_, Where() + ": list item " + Quote(tokens_[t]) + " is not an integer");
          }
          list->push_back(v);
        }
      } else {
        t += static_cast<std::size_t>(n);
      }
    }
    if (t != tokens_.size()) {
      Fail(file_, Where() + ": expected " + std::to_string(t) + " values for a '" + element.name +
                      "' item, found " + std::to_string(tokens_.size()));
    }
  }

  std::string Where() const override { return "line " + std::to_string(lines_.line_number()); }

  const char* TakeBlock(std::int64_t) override { return nullptr; }

  void Finish(std::vector<std::string>*) override {
    std::string_view line;
    while (lines_.Next(&line)) {
      if (!Trim(line).empty()) {
        Fail(file_, Where() + ": data after the last element (the header's counts are too small)");
      }
    }
  }

 private:
  // A float property's text is rounded to float, as a binary file would hold it.
  double Number(std::size_t t, ScalarType type, const PlyElement& element) {
    double v = 0.0;
    if (t >= tokens_.size()) {
      Fail(file_, Where() + ": too few values for a '" + element.name + "' item");
    }
    if (!ParseDouble(tokens_[t], &v)) {
      Fail(file_, Where() + ": " + Quote(tokens_[t]) + " is not a number");
    }
    return type == ScalarType::kFloat32 ? SafeFloat(v) : v;
  }

  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
};

enum class Slot { kX, kY, kZ, kNx, kNy, kNz, kRed, kGreen, kBlue, kScalar };

// Where each scalar vertex property goes.
struct VertexLayout {
  std::vector<Slot> slots;                // one per scalar property, in order
  std::vector<bool> is_float;             // its type is float/double
  std::vector<std::string> scalar_names;  // for kScalar slots, in order
  bool normals = false;
  bool colors = false;
};

int FindAny(const PlyElement& e, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const int i = e.FindProperty(name);
    if (i >= 0 && !e.properties[static_cast<std::size_t>(i)].is_list) return i;
  }
  return -1;
}

VertexLayout MakeLayout(const std::filesystem::path& file, const PlyElement& vertex) {
  std::vector<Slot> by_property(vertex.properties.size(), Slot::kScalar);
  const int x = FindAny(vertex, {"x"}), y = FindAny(vertex, {"y"}), z = FindAny(vertex, {"z"});
  if (x < 0 || y < 0 || z < 0) {
    Fail(file, "the 'vertex' element needs scalar properties x, y and z");
  }
  by_property[x] = Slot::kX, by_property[y] = Slot::kY, by_property[z] = Slot::kZ;
  VertexLayout layout;
  const int nx = FindAny(vertex, {"nx", "normal_x"}), ny = FindAny(vertex, {"ny", "normal_y"}),
            nz = FindAny(vertex, {"nz", "normal_z"});
  if (nx >= 0 && ny >= 0 && nz >= 0) {
    by_property[nx] = Slot::kNx, by_property[ny] = Slot::kNy, by_property[nz] = Slot::kNz;
    layout.normals = true;
  }
  const int r = FindAny(vertex, {"red", "diffuse_red"});
  const int g = FindAny(vertex, {"green", "diffuse_green"});
  const int b = FindAny(vertex, {"blue", "diffuse_blue"});
  if (r >= 0 && g >= 0 && b >= 0) {
    by_property[r] = Slot::kRed, by_property[g] = Slot::kGreen, by_property[b] = Slot::kBlue;
    layout.colors = true;
  }
  for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
    const PlyProperty& p = vertex.properties[i];
    if (p.is_list) continue;  // lists on vertices are skipped
    layout.slots.push_back(by_property[i]);
    layout.is_float.push_back(!IsInteger(p.type));
    if (by_property[i] == Slot::kScalar) layout.scalar_names.push_back(p.name);
  }
  return layout;
}

// Binary vertices without list properties: one fixed-size block, converted
// column by column (the common case, and the fast one).
void ReadVertexBlock(const PlyElement& element, const VertexLayout& layout, const char* block,
                     bool big_endian, const std::vector<Eigen::VectorXd*>& scalars, RawScan* raw) {
  PointCloud& cloud = raw->cloud;
  const Eigen::Index n = element.count;
  const std::int64_t stride = element.MinBinaryBytes();
  constexpr Eigen::Index kChunk = 4096;  // all properties per chunk: the bytes stay in cache
  std::vector<double> channel(kChunk);
  for (Eigen::Index first = 0; first < n; first += kChunk) {
    const Eigen::Index count = std::min(kChunk, n - first);
    const char* chunk = block + first * stride;
    std::int64_t offset = 0;
    std::size_t s = 0;
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
      const PlyProperty& p = element.properties[k];
      const Slot slot = layout.slots[k];
      double* column = nullptr;
      if (slot == Slot::kX || slot == Slot::kY || slot == Slot::kZ) {
        column = cloud.points.col(static_cast<int>(slot) - static_cast<int>(Slot::kX)).data();
      } else if (slot == Slot::kNx || slot == Slot::kNy || slot == Slot::kNz) {
        column = cloud.normals.col(static_cast<int>(slot) - static_cast<int>(Slot::kNx)).data();
      } else if (slot == Slot::kScalar) {
        column = scalars[s++]->data();
      } else {  // a colour channel
        ConvertColumn(chunk + offset, stride, p.type, big_endian, count, channel.data());
        const int c = static_cast<int>(slot) - static_cast<int>(Slot::kRed);
        for (Eigen::Index i = 0; i < count; ++i) {
          cloud.colors(first + i, c) =
              ColorByte(channel[static_cast<std::size_t>(i)], layout.is_float[k]);
        }
      }
      if (column) ConvertColumn(chunk + offset, stride, p.type, big_endian, count, column + first);
      offset += SizeOf(p.type);
    }
  }
}

void ReadVertices(const std::filesystem::path& file, const PlyElement& element, ItemReader* reader,
                  bool big_endian, RawScan* raw) {
  const VertexLayout layout = MakeLayout(file, element);
  const Eigen::Index n = element.count;
  PointCloud& cloud = raw->cloud;
  cloud.points.resize(n, 3);
  if (layout.normals) cloud.normals.resize(n, 3);
  if (layout.colors) cloud.colors.resize(n, 3);
  std::vector<Eigen::VectorXd*> scalars;
  for (const std::string& name : layout.scalar_names) {
    Eigen::VectorXd& v = cloud.scalars[name];
    v.resize(n);
    scalars.push_back(&v);
  }
  if (!element.HasLists()) {
    if (const char* block = reader->TakeBlock(n * element.MinBinaryBytes())) {
      return ReadVertexBlock(element, layout, block, big_endian, scalars, raw);
    }
  }
  std::vector<double> values;
  std::vector<std::int64_t> unused;
  for (Eigen::Index i = 0; i < n; ++i) {
    reader->Read(element, -1, &values, &unused);
    std::size_t s = 0;
    for (std::size_t k = 0; k < values.size(); ++k) {
      const double v = values[k];
      switch (layout.slots[k]) {
        case Slot::kX:
          cloud.points(i, 0) = v;
          break;
        case Slot::kY:
          cloud.points(i, 1) = v;
          break;
        case Slot::kZ:
          cloud.points(i, 2) = v;
          break;
        case Slot::kNx:
          cloud.normals(i, 0) = v;
          break;
        case Slot::kNy:
          cloud.normals(i, 1) = v;
          break;
        case Slot::kNz:
          cloud.normals(i, 2) = v;
          break;
        case Slot::kRed:
          cloud.colors(i, 0) = ColorByte(v, layout.is_float[k]);
          break;
        case Slot::kGreen:
          cloud.colors(i, 1) = ColorByte(v, layout.is_float[k]);
          break;
        case Slot::kBlue:
          cloud.colors(i, 2) = ColorByte(v, layout.is_float[k]);
          break;
        case Slot::kScalar:
          (*scalars[s++])[i] = v;
          break;
      }
    }
  }
}

void ReadFaces(const std::filesystem::path& file, const PlyElement& element, int list,
               std::int64_t num_vertices, ItemReader* reader, std::vector<int>* triangles) {
  std::vector<double> values;
  std::vector<std::int64_t> indices;
  for (std::int64_t f = 0; f < element.count; ++f) {
    reader->Read(element, list, &values, &indices);
    if (indices.size() < 3) {
      Fail(file, reader->Where() + ": face " + std::to_string(f) + " has " +
                     std::to_string(indices.size()) + " vertices (at least 3 needed)");
    }
    for (const std::int64_t v : indices) {
      if (v < 0 || v >= num_vertices) {
        Fail(file, reader->Where() + ": face " + std::to_string(f) + " refers to vertex " +
                       std::to_string(v) + " but the file has " + std::to_string(num_vertices) +
                       " vertices");
      }
    }
    for (std::size_t k = 1; k + 1 < indices.size(); ++k) {
      triangles->push_back(static_cast<int>(indices[0]));
      triangles->push_back(static_cast<int>(indices[k]));
      triangles->push_back(static_cast<int>(indices[k + 1]));
    }
  }
}

}  // namespace

RawScan ReadPly(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  const PlyHeader header = ParsePlyHeader(options, file, bytes);
  RawScan raw;
  raw.encoding = ToString(header.encoding);
  const PlyElement* vertex = nullptr;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex") vertex = &e;
  }
  if (!vertex) Fail(file, "PLY header declares no 'vertex' element");
  MakeLayout(file, *vertex);  // validates x, y, z before reading anything
  for (const PlyProperty& p : vertex->properties) raw.fields.push_back(p.name);

  std::unique_ptr<ItemReader> reader;
  if (header.encoding == PlyEncoding::kAscii) {
    reader = std::make_unique<AsciiItemReader>(file, bytes, header.data_offset, header.data_line);
  } else {
    reader = std::make_unique<BinaryItemReader>(file, bytes, header.data_offset,
                                                header.encoding == PlyEncoding::kBinaryBigEndian);
  }
  std::vector<int> triangles;
  std::vector<double> values;
  std::vector<std::int64_t> unused;
  for (const PlyElement& e : header.elements) {
    if (&e == vertex) {
      ReadVertices(file, e, reader.get(), header.encoding == PlyEncoding::kBinaryBigEndian, &raw);
      continue;
    }
    int list = -1;
    if (e.name == "face") {
      list = e.FindProperty("vertex_indices");
      if (list < 0) list = e.FindProperty("vertex_index");
      if (list >= 0 && !e.properties[static_cast<std::size_t>(list)].is_list) list = -1;
      if (list >= 0 && !IsInteger(e.properties[static_cast<std::size_t>(list)].type)) {
        Fail(file, "line " + std::to_string(e.header_line) +
                       ": face vertex indices must have an integer type");
      }
      if (list < 0 && e.count > 0) {
        raw.warnings.push_back("face element without a vertex_indices list was skipped");
      }
    }
    if (list >= 0) {
      raw.faces_in_file = e.count;
      ReadFaces(file, e, list, vertex->count, reader.get(), &triangles);
    } else {
      for (std::int64_t i = 0; i < e.count; ++i) reader->Read(e, -1, &values, &unused);
    }
  }
  reader->Finish(&raw.warnings);
  raw.faces = TrianglesToMatrix(file, triangles, raw.cloud.size());
  return raw;
}

}  // namespace bespoke::io
