// Checks shared by the format readers (see formats.h).
#include "scanners/io/formats.h"

#include <algorithm>
#include <cmath>

#include "scanners/io/byte_reader.h"

namespace bespoke::io {

void CheckCount(const ReadOptions& options, const std::filesystem::path& file, std::int64_t count,
                const std::string& what, const std::string& where) {
  if (count < 0) {
    Fail(file, where + ": " + what + " is negative (" + std::to_string(count) + ")");
  }
  if (count > options.max_elements) {
    Fail(file, where + ": " + what + " is " + std::to_string(count) + ", more than the limit of " +
                   std::to_string(options.max_elements) + " (corrupt header?)");
  }
}

Eigen::MatrixX3i TrianglesToMatrix(const std::filesystem::path& file, const std::vector<int>& flat,
                                   Eigen::Index num_vertices) {
  const auto n = static_cast<Eigen::Index>(flat.size() / 3);
  Eigen::MatrixX3i faces(n, 3);
  for (Eigen::Index f = 0; f < n; ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = flat[static_cast<std::size_t>(3 * f + c)];
      if (v < 0 || v >= num_vertices) {
        Fail(file, "triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                       " but there are " + std::to_string(num_vertices) + " vertices");
      }
      faces(f, c) = v;
    }
  }
  return faces;
}

std::string NameSet::Unique(const std::string& name) {
  if (used_.insert(name).second) return name;
  int& k = next_suffix_[name];
  if (k < 2) k = 2;
  std::string candidate;
  do {
    candidate = name + "_" + std::to_string(k++);
  } while (!used_.insert(candidate).second);
  return candidate;
}

std::uint8_t ColorByte(double value, bool is_float) {
  if (!std::isfinite(value)) return 0;
  const double v = is_float ? value * 255.0 : value;
  return static_cast<std::uint8_t>(std::clamp(std::round(v), 0.0, 255.0));
}

}  // namespace bespoke::io
