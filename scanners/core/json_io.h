// Reading and writing JSON documents with Bespoke's error conventions.
//
// ReadJsonFile: InputError("<file>: <parse error with line/column>") for
// missing, unreadable or malformed files. WriteJsonFile: atomic, pretty
// printed (2-space indent), ends with a newline.
#ifndef BESPOKE_SCANNERS_CORE_JSON_IO_H_
#define BESPOKE_SCANNERS_CORE_JSON_IO_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace bespoke {

nlohmann::json ReadJsonFile(const std::filesystem::path& file);
void WriteJsonFile(const std::filesystem::path& file, const nlohmann::json& document);

// [x, y, z] <-> Eigen::Vector3d. FromJson throws InputError when `j` is not
// an array of three finite numbers; `what` names the value in that message.
nlohmann::json ToJson(const Eigen::Vector3d& v);
Eigen::Vector3d Vector3FromJson(const nlohmann::json& j, const std::string& what);

// A 4x4 row-major nested array <-> Eigen::Affine3d.
nlohmann::json ToJson(const Eigen::Affine3d& transform);
Eigen::Affine3d AffineFromJson(const nlohmann::json& j, const std::string& what);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_JSON_IO_H_
