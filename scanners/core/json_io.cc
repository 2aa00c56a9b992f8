#include "scanners/core/json_io.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"

namespace bespoke {

nlohmann::json ReadJsonFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(file,
                     std::filesystem::exists(file, ec) ? "is not a regular file" : "no such file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open for reading");
  try {
    return nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, std::string("not valid JSON: ") + e.what());
  }
}

void WriteJsonFile(const std::filesystem::path& file, const nlohmann::json& document) {
  WriteFileAtomically(file, document.dump(2) + "\n");
}

nlohmann::json ToJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Vector3d Vector3FromJson(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + " must be an array [x, y, z]");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) throw InputError(what + " must hold three numbers");
    v[i] = j[i].get<double>();
    if (!std::isfinite(v[i])) throw InputError(what + " has a value that is not finite");
  }
  return v;
}

nlohmann::json ToJson(const Eigen::Affine3d& transform) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) {
    rows.push_back({transform.matrix()(r, 0), transform.matrix()(r, 1), transform.matrix()(r, 2),
                    transform.matrix()(r, 3)});
  }
  return rows;
}

Eigen::Affine3d AffineFromJson(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 4) throw InputError(what + " must be a 4x4 array");
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    if (!j[r].is_array() || j[r].size() != 4) throw InputError(what + " must be a 4x4 array");
    for (int c = 0; c < 4; ++c) {
      if (!j[r][c].is_number()) throw InputError(what + " must hold numbers");
      m(r, c) = j[r][c].get<double>();
    }
  }
  Eigen::Affine3d t;
  t.matrix() = m;
  return t;
}

}  // namespace bespoke
