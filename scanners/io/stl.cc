// STL reader (binary and ascii) and binary writer.
//
// STL stores every triangle with its own three corners; the reader merges
// corners with exactly equal coordinates (bitwise after -0 -> +0) into one
// vertex, so shared edges become shared vertices. Nothing is welded within a
// tolerance: nearly equal corners stay distinct vertices.
// Binary: 80-byte header, uint32 count, 50 bytes per triangle (normal, three
// float corners, uint16 attribute). A file is binary when its size is exactly
// 84 + 50 * count, else ascii when it starts with "solid", else binary with
// the count checked against the size. Ascii: "solid ... facet normal ...
// outer loop / vertex x y z (x3) / endloop / endfacet ... endsolid", several
// solids allowed. Write: binary, float corners, normals from the corners.
#include <array>
#include <cstring>
#include <unordered_map>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

struct KeyHash {
  std::size_t operator()(const std::array<double, 3>& k) const {
    std::size_t h = 0;
    for (const double v : k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &v, sizeof(bits));
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};
struct KeyEqual {  // bitwise, so that NaN corners compare equal to themselves
  bool operator()(const std::array<double, 3>& a, const std::array<double, 3>& b) const {
    return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
  }
};

class Merger {
 public:
  void Add(double x, double y, double z) {
    // -0 and +0 are the same position.
    std::array<double, 3> key = {x == 0.0 ? 0.0 : x, y == 0.0 ? 0.0 : y, z == 0.0 ? 0.0 : z};
    const auto [it, inserted] = index_.emplace(key, static_cast<int>(xyz_.size() / 3));
    if (inserted) xyz_.insert(xyz_.end(), key.begin(), key.end());
    corners_.push_back(it->second);
  }

  RawScan Finish(const std::filesystem::path& file, std::int64_t triangles,
                 const std::string& encoding) {
    RawScan raw;
    raw.encoding = encoding;
    raw.fields = {"x", "y", "z"};
    const auto n = static_cast<Eigen::Index>(xyz_.size() / 3);
    raw.cloud.points = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        xyz_.data(), n, 3);
    raw.faces = TrianglesToMatrix(file, corners_, n);
    raw.faces_in_file = triangles;
    return raw;
  }

 private:
  std::unordered_map<std::array<double, 3>, int, KeyHash, KeyEqual> index_;
  std::vector<double> xyz_;
  std::vector<int> corners_;
};

RawScan ReadBinary(const ReadOptions& options, const std::filesystem::path& file,
                   std::string_view bytes) {
  if (bytes.size() < 84) {
    Fail(file, "binary STL needs an 84-byte header, the file has " + std::to_string(bytes.size()) +
                   " bytes");
  }
  const std::int64_t count = LoadUint32Le(bytes.data() + 80);
  CheckCount(options, file, count, "number of triangles", "byte offset 80");
  if (count > static_cast<std::int64_t>(bytes.size() - 84) / 50) {
    Fail(file, "byte offset 80: binary STL declares " + std::to_string(count) + " triangles (" +
                   std::to_string(84 + 50 * count) + " bytes) but the file has " +
                   std::to_string(bytes.size()) + " bytes (truncated?)");
  }
  Merger merger;
  for (std::int64_t t = 0; t < count; ++t) {
    const char* p = bytes.data() + 84 + 50 * t + 12;  // skip the normal
    for (int c = 0; c < 9; c += 3) {
      merger.Add(LoadScalar(p + 4 * c, ScalarType::kFloat32, false),
                 LoadScalar(p + 4 * c + 4, ScalarType::kFloat32, false),
                 LoadScalar(p + 4 * c + 8, ScalarType::kFloat32, false));
    }
  }
  RawScan raw = merger.Finish(file, count, "binary");
  const auto extra = static_cast<std::int64_t>(bytes.size()) - 84 - 50 * count;
  if (extra > 0)
    raw.warnings.push_back(std::to_string(extra) + " bytes after the triangles ignored");
  return raw;
}

class AsciiStlParser {
 public:
  AsciiStlParser(const ReadOptions& options, const std::filesystem::path& file,
                 std::string_view bytes)
      : options_(options), file_(file), lines_(bytes) {}

  RawScan Parse() {
    std::int64_t triangles = 0;
    bool any_solid = false;
    while (Next(false)) {
      Expect("solid");
      any_solid = true;
      while (Next(true) && tokens_[0] != "endsolid") {
        Expect("facet");
        Expect("outer", "loop");
        for (int c = 0; c < 3; ++c) Vertex();
        Expect("endloop");
        Expect("endfacet");
        ++triangles;
        CheckCount(options_, file_, triangles, "number of triangles", Where());
      }
    }
    if (!any_solid) Fail(file_, "ascii STL has no 'solid' line");
    return merger_.Finish(file_, triangles, "ascii");
  }

 private:
  std::string Where() const { return "line " + std::to_string(lines_.line_number()); }

  // Advances to the next non-blank line; false at the end (an error when `required`).
  bool Next(bool required) {
    std::string_view line;
    while (lines_.Next(&line)) {
      if (Tokenize(line, &tokens_) > 0) {
        fresh_ = true;
        return true;
      }
    }
    if (required) Fail(file_, "file ends inside a solid (truncated; 'endsolid' missing)");
    return false;
  }

  // The current line (or the next one when the current was used) must start
  // with `key` [`second`].
  void Expect(const char* key, const char* second = nullptr) {
    if (!fresh_) Next(true);
    fresh_ = false;
    if (tokens_[0] != key || (second && (tokens_.size() < 2 || tokens_[1] != second))) {
      Fail(file_, Where() + ": expected '" + std::string(key) +
                      (second ? std::string(" ") + second : "") + "', found " + Quote(tokens_[0]));
    }
  }

  void Vertex() {
    Expect("vertex");
    if (tokens_.size() != 4) {
      Fail(file_,
           Where() + ": 'vertex' needs 3 numbers, found " + std::to_string(tokens_.size() - 1));
    }
    double xyz[3];
    for (int c = 0; c < 3; ++c) {
      if (!ParseDouble(tokens_[static_cast<std::size_t>(c) + 1], &xyz[c])) {
        Fail(file_,
             Where() + ": " + Quote(tokens_[static_cast<std::size_t>(c) + 1]) + " is not a number");
      }
    }
    merger_.Add(xyz[0], xyz[1], xyz[2]);
  }

  const ReadOptions& options_;
  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
  bool fresh_ = false;  // tokens_ holds a line no Expect() has consumed yet
  Merger merger_;
};

}  // namespace

bool LooksLikeBinaryStl(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  const std::uint64_t count = LoadUint32Le(bytes.data() + 80);
  return 84 + 50 * count == bytes.size();
}

RawScan ReadStl(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  if (LooksLikeBinaryStl(bytes)) return ReadBinary(options, file, bytes);
  std::string_view start = Trim(bytes.substr(0, 80));
  if (start.substr(0, 5) == "solid") return AsciiStlParser(options, file, bytes).Parse();
  return ReadBinary(options, file, bytes);
}

std::string WriteStl(const WriteOptions& options, const TriangleMesh& mesh) {
  std::string header = "binary STL written by Bespoke";
  if (!options.comment.empty()) header += "; " + options.comment;
  for (char& c : header) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  header.resize(80, ' ');  // never starts with "solid"
  std::string out = header;
  AppendScalar(&out, static_cast<double>(mesh.num_faces()), ScalarType::kUint32, false);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2));
    Eigen::Vector3d n = (b - a).cross(c - a);
    n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& v : {n, a, b, c}) {
      for (int k = 0; k < 3; ++k) AppendScalar(&out, v[k], ScalarType::kFloat32, false);
    }
    AppendScalar(&out, 0, ScalarType::kUint16, false);
  }
  return out;
}

}  // namespace bespoke::io
