// OFF (Object File Format, ascii) reader and writer.
//
// Read: a keyword line OFF / COFF / NOFF / CNOFF / STOFF ... (the counts may
// follow on the same line), then "#V #F [#E]", then one vertex per line
// (x y z, then nx ny nz with N, u v with ST, r g b [a] with C: integers 0-255
// or floats 0-1) and one face per line ("n i1 .. in", optionally followed by
// up to 4 colour values). Comments '#' and blank lines are skipped. Binary
// OFF and 4OFF/nOFF (other dimensions) are rejected.
// Write: "OFF", "#V #F 0", vertices, triangles.
#include <algorithm>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

class OffParser {
 public:
  OffParser(const ReadOptions& options, const std::filesystem::path& file, std::string_view bytes)
      : options_(options), file_(file), lines_(bytes) {}

  RawScan Parse() {
    if (!NextLine()) Fail(file_, "no OFF keyword line");
    Keyword();
    if (tokens_.empty() && !NextLine()) Fail(file_, "the vertex and face counts are missing");
    Counts();
    Vertices();
    Faces();
    while (NextLine()) {
      Fail(file_, Where() + ": data after the last face (the face count is too small)");
    }
    raw_.encoding = "ascii";
    raw_.faces = TrianglesToMatrix(file_, triangles_, raw_.cloud.size());
    return std::move(raw_);
  }

 private:
  std::string Where() const { return "line " + std::to_string(lines_.line_number()); }

  // The next line that is neither blank nor a comment, tokenised; false at the end.
  bool NextLine() {
    std::string_view line;
    while (lines_.Next(&line)) {
      const std::size_t hash = line.find('#');
      if (hash != std::string_view::npos) line = line.substr(0, hash);
      if (Tokenize(line, &tokens_) > 0) return true;
    }
    return false;
  }

  void Keyword() {
    const std::string_view key = tokens_[0];
    if (key.size() < 3 || key.substr(key.size() - 3) != "OFF") {
      Fail(file_, "not an OFF file: the first line must start with OFF (found " + Quote(key) + ")");
    }
    std::string_view prefix = key.substr(0, key.size() - 3);
    if (prefix.substr(0, 2) == "ST") texture_ = true, prefix.remove_prefix(2);
    if (!prefix.empty() && prefix.front() == 'C') colors_ = true, prefix.remove_prefix(1);
    if (!prefix.empty() && prefix.front() == 'N') normals_ = true, prefix.remove_prefix(1);
    if (!prefix.empty()) Fail(file_, "unsupported OFF variant " + Quote(key));
    tokens_.erase(tokens_.begin());
    if (!tokens_.empty() && tokens_[0] == "BINARY") Fail(file_, "binary OFF is not supported");
  }

  void Counts() {
    if (tokens_.size() < 2 || tokens_.size() > 3) {
      Fail(file_, Where() + ": expected '#vertices #faces [#edges]'");
    }
    std::int64_t counts[3] = {0, 0, 0};
    for (std::size_t k = 0; k < tokens_.size(); ++k) {
      if (!ParseInt64(tokens_[k], &counts[k])) {
        Fail(file_, Where() + ": count " + Quote(tokens_[k]) + " is not an integer");
      }
    }
    CheckCount(options_, file_, counts[0], "number of vertices", Where());
    CheckCount(options_, file_, counts[1], "number of faces", Where());
    // Every vertex line has >= 3 values and every face line >= 4, each value
    // at least one character and a separator.
    const auto left = static_cast<std::int64_t>(lines_.remaining()) + 1;
    if (counts[0] > left / 6 || counts[1] > (left - 6 * counts[0]) / 8) {
      Fail(file_, Where() + ": " + std::to_string(counts[0]) + " vertices and " +
                      std::to_string(counts[1]) + " faces cannot fit in the " +
                      std::to_string(lines_.remaining()) + " bytes left (truncated file?)");
    }
    num_vertices_ = counts[0];
    num_faces_ = counts[1];
  }

  double Number(std::size_t t) {
    double v = 0.0;
    if (!ParseDouble(tokens_[t], &v))
      Fail(file_, Where() + ": " + Quote(tokens_[t]) + " is not a number");
    return v;
  }

  void Vertices() {
    const std::size_t base = 3 + (normals_ ? 3 : 0) + (texture_ ? 2 : 0);
    PointCloud& cloud = raw_.cloud;
    cloud.points.resize(num_vertices_, 3);
    if (normals_) cloud.normals.resize(num_vertices_, 3);
    if (colors_) cloud.colors.resize(num_vertices_, 3);
    raw_.fields = {"x", "y", "z"};
    if (normals_) raw_.fields.insert(raw_.fields.end(), {"nx", "ny", "nz"});
    if (colors_) raw_.fields.insert(raw_.fields.end(), {"red", "green", "blue"});
    for (Eigen::Index i = 0; i < num_vertices_; ++i) {
      if (!NextLine())
        Fail(file_, "file ends after " + std::to_string(i) + " of " +
                        std::to_string(num_vertices_) + " vertices (truncated)");
      const std::size_t n = tokens_.size();
      if (n != base && !(colors_ && (n == base + 3 || n == base + 4))) {
        Fail(file_, Where() + ": a vertex needs " + std::to_string(base) +
                        (colors_ ? " values plus 3 or 4 colour values" : " values") + ", found " +
                        std::to_string(n));
      }
      for (int c = 0; c < 3; ++c) cloud.points(i, c) = Number(static_cast<std::size_t>(c));
      for (int c = 0; c < 3 && normals_; ++c)
        cloud.normals(i, c) = Number(3 + static_cast<std::size_t>(c));
      for (std::size_t t = 3 + (normals_ ? 3 : 0); t < base; ++t) Number(t);  // texture: checked
      for (int c = 0; c < 3 && colors_; ++c) {
        const std::size_t t = base + static_cast<std::size_t>(c);
        const bool is_float = n > base && tokens_[t].find_first_of(".eE") != std::string_view::npos;
        cloud.colors(i, c) = n > base ? ColorByte(Number(t), is_float) : 0;
      }
    }
  }

  void Faces() {
    raw_.faces_in_file = num_faces_;
    for (std::int64_t f = 0; f < num_faces_; ++f) {
      if (!NextLine())
        Fail(file_, "file ends after " + std::to_string(f) + " of " + std::to_string(num_faces_) +
                        " faces (truncated)");
      std::int64_t n = 0;
      if (!ParseInt64(tokens_[0], &n) || n < 3) {
        Fail(file_,
             Where() + ": a face starts with its vertex count (>= 3), found " + Quote(tokens_[0]));
      }
      const auto extra = static_cast<std::int64_t>(tokens_.size()) - 1 - n;
      if (extra < 0 || extra > 4) {
        Fail(file_, Where() + ": a face of " + std::to_string(n) + " vertices needs " +
                        std::to_string(n + 1) + " values (plus up to 4 colour values), found " +
                        std::to_string(tokens_.size()));
      }
      corners_.clear();
      for (std::int64_t k = 1; k <= n; ++k) {
        std::int64_t v = 0;
        if (!ParseInt64(tokens_[static_cast<std::size_t>(k)], &v) || v < 0 || v >= num_vertices_) {
          Fail(file_, Where() + ": face " + std::to_string(f) + " refers to vertex " +
                          Quote(tokens_[static_cast<std::size_t>(k)]) + " but there are " +
                          std::to_string(num_vertices_) + " vertices (0-based)");
        }
        corners_.push_back(static_cast<int>(v));
      }
      for (std::size_t k = 1; k + 1 < corners_.size(); ++k) {
        triangles_.insert(triangles_.end(), {corners_[0], corners_[k], corners_[k + 1]});
      }
    }
  }

  const ReadOptions& options_;
  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
  bool normals_ = false, colors_ = false, texture_ = false;
  std::int64_t num_vertices_ = 0, num_faces_ = 0;
  std::vector<int> corners_, triangles_;
  RawScan raw_;
};

}  // namespace

RawScan ReadOff(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  return OffParser(options, file, bytes).Parse();
}

std::string WriteOff(const WriteOptions& options, const TriangleMesh& mesh) {
  std::string out = "OFF\n";
  LineCursor comments(options.comment);
  std::string_view line;
  while (comments.Next(&line)) out += "# " + std::string(line) + "\n";
  out += std::to_string(mesh.num_vertices()) + " " + std::to_string(mesh.num_faces()) + " 0\n";
  for (Eigen::Index i = 0; i < mesh.num_vertices(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (c) out += ' ';
      AppendNumber(&out, mesh.vertices(i, c));
    }
    out += '\n';
  }
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    out += '3';
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      AppendNumber(&out, static_cast<std::int64_t>(mesh.faces(f, c)));
    }
    out += '\n';
  }
  return out;
}

}  // namespace bespoke::io
