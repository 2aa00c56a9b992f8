// Wavefront OBJ reader and writer.
//
// Read: `v x y z [w]` or `v x y z r g b` (vertex colours 0-1), `vn`, `vt`
// (checked, not kept), `f` with `a`, `a/b`, `a//c`, `a/b/c` corners (1-based;
// negative = relative to the vertices defined so far), `g`/`o` (groups: every
// triangle keeps the group current at its `f` line; faces before any group
// go to "default"), comments after '#'. Other statements (usemtl, mtllib, s,
// l, p, ...) are ignored. A face must refer to vertices defined above it.
// Write: `v` and 1-based `f` lines, shortest round-trip number text.
#include <unordered_map>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

bool IsKeyword(std::string_view token) {
  for (const char c : token) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    if (!ok) return false;
  }
  return !token.empty();
}

class ObjParser {
 public:
  ObjParser(const ReadOptions& options, const std::filesystem::path& file, std::string_view bytes)
      : options_(options), file_(file), lines_(StripBom(bytes)) {}

  RawScan Parse() {
    std::string_view line;
    while (lines_.Next(&line)) {
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
      if (Tokenize(line, &tokens_) == 0) continue;
      const std::string_view key = tokens_[0];
      if (key == "v") {
        Vertex();
      } else if (key == "vn") {
        Numbers(3, 3, "a normal");
      } else if (key == "vt") {
        Numbers(1, 3, "a texture coordinate");
      } else if (key == "f") {
        Face();
      } else if (key == "g" || key == "o") {
        Group(line);
      } else if (!IsKeyword(key)) {
        Fail(file_, Where() + ": " + Quote(key) + " is not an OBJ statement");
      }
    }
    return Finish();
  }

 private:
  std::string Where() const { return "line " + std::to_string(lines_.line_number()); }

  double Number(std::size_t t) {
    double v = 0.0;
    if (!ParseDouble(tokens_[t], &v)) {
      Fail(file_, Where() + ": " + Quote(tokens_[t]) + " is not a number");
    }
    return v;
  }

  void Numbers(std::size_t min, std::size_t max, const char* what) {
    const std::size_t n = tokens_.size() - 1;
    if (n < min || n > max) {
      Fail(file_, Where() + ": " + what + " needs " + std::to_string(min) +
                      (min == max ? "" : "-" + std::to_string(max)) + " numbers, found " +
                      std::to_string(n));
    }
    for (std::size_t t = 1; t < tokens_.size(); ++t) Number(t);
  }

  void Vertex() {
    const std::size_t n = tokens_.size() - 1;
    if (n != 3 && n != 4 && n != 6) {
      Fail(file_, Where() + ": a vertex needs 3 numbers (or x y z w, or x y z r g b), found " +
                      std::to_string(n));
    }
    if (static_cast<std::int64_t>(xyz_.size() / 3) >= options_.max_elements) {
      CheckCount(options_, file_, static_cast<std::int64_t>(xyz_.size() / 3) + 1,
                 "number of vertices", Where());
    }
    for (std::size_t t = 1; t <= 3; ++t) xyz_.push_back(Number(t));
    if (n == 6) {
      for (std::size_t t = 4; t <= 6; ++t) rgb_.push_back(ColorByte(Number(t), true));
    } else {
      if (n == 4) Number(4);  // w: checked, not kept
      all_colored_ = false;
    }
  }

  // The vertex index of a corner token "a", "a/b", "a//c" or "a/b/c".
  int Corner(std::string_view token) {
    const std::size_t slash = token.find('/');
    const std::string_view first = token.substr(0, slash);
    std::int64_t index = 0;
    if (!ParseInt64(first, &index) || index == 0) {
      Fail(file_, Where() + ": face corner " + Quote(token) + " needs a vertex index (1-based)");
    }
    if (slash != std::string_view::npos) CheckRefs(token.substr(slash + 1));
    const auto defined = static_cast<std::int64_t>(xyz_.size() / 3);
    const std::int64_t resolved = index > 0 ? index - 1 : defined + index;
    if (resolved < 0 || resolved >= defined) {
      Fail(file_, Where() + ": face refers to vertex " + std::to_string(index) + " but " +
                      std::to_string(defined) + " vertices are defined above this line");
    }
    return static_cast<int>(resolved);
  }

  // "b", "b/c" or "/c": texture and normal indices must be integers.
  void CheckRefs(std::string_view rest) {
    while (true) {
      const std::size_t slash = rest.find('/');
      const std::string_view part = rest.substr(0, slash);
      std::int64_t unused = 0;
      if (!part.empty() && !ParseInt64(part, &unused)) {
        Fail(file_, Where() + ": " + Quote(part) + " in a face corner is not an index");
      }
      if (slash == std::string_view::npos) break;
      rest = rest.substr(slash + 1);
    }
  }

  void Face() {
    if (tokens_.size() < 4) {
      Fail(file_, Where() + ": a face needs at least 3 corners, found " +
                      std::to_string(tokens_.size() - 1));
    }
    corners_.clear();
    for (std::size_t t = 1; t < tokens_.size(); ++t) corners_.push_back(Corner(tokens_[t]));
    if (group_ < 0) group_ = GroupIndex("default");
    ++faces_in_file_;
    CheckCount(options_, file_, faces_in_file_, "number of faces", Where());
    for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {
      triangles_.insert(triangles_.end(), {corners_[0], corners_[k], corners_[k + 1]});
      face_group_.push_back(group_);
    }
  }

  void Group(std::string_view line) {
    std::string_view rest = Trim(line);
    rest.remove_prefix(1);  // the 'g' or 'o'
    rest = Trim(rest);
    group_ = GroupIndex(rest.empty() ? std::string_view("default") : rest);
  }

  int GroupIndex(std::string_view name) {
    const auto [it, inserted] =
        group_index_.emplace(std::string(name), static_cast<int>(group_names_.size()));
    if (inserted) group_names_.push_back(it->first);
    return it->second;
  }

  RawScan Finish() {
    RawScan raw;
    raw.encoding = "ascii";
    const auto n = static_cast<Eigen::Index>(xyz_.size() / 3);
    raw.cloud.points = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        xyz_.data(), n, 3);
    raw.fields = {"x", "y", "z"};
    if (all_colored_ && n > 0) {
      raw.cloud.colors =
          Eigen::Map<const Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 3, Eigen::RowMajor>>(
              rgb_.data(), n, 3);
      raw.fields.insert(raw.fields.end(), {"red", "green", "blue"});
    } else if (!rgb_.empty()) {
      raw.warnings.push_back("vertex colours ignored: not every vertex has one");
    }
    raw.faces = TrianglesToMatrix(file_, triangles_, n);
    raw.face_group = std::move(face_group_);
    raw.group_names = std::move(group_names_);
    raw.faces_in_file = faces_in_file_;
    return raw;
  }

  const ReadOptions& options_;
  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
  std::vector<double> xyz_;
  std::vector<std::uint8_t> rgb_;
  bool all_colored_ = true;
  std::int64_t faces_in_file_ = 0;
  std::vector<int> corners_, triangles_, face_group_;
  int group_ = -1;
  std::vector<std::string> group_names_;
  std::unordered_map<std::string, int> group_index_;
};

}  // namespace

RawScan ReadObj(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  return ObjParser(options, file, bytes).Parse();
}

std::string WriteObj(const WriteOptions& options, const TriangleMesh& mesh) {
  std::string out;
  LineCursor lines(options.comment);
  std::string_view line;
  while (lines.Next(&line)) out += "# " + std::string(line) + "\n";
  for (Eigen::Index i = 0; i < mesh.num_vertices(); ++i) {
    out += 'v';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      AppendNumber(&out, mesh.vertices(i, c));
    }
    out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    out += 'f';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      AppendNumber(&out, static_cast<std::int64_t>(mesh.faces(f, c)) + 1);
    }
    out += '\n';
  }
  return out;
}

}  // namespace bespoke::io
