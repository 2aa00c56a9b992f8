#include "oracle/makehuman/makehuman_model.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "oracle/makehuman/makehuman_pose.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

// Every undirected edge must be used by exactly two faces, once in each
// direction (closed, consistently oriented 2-manifold surface).
void CheckClosedManifold(const TriangleMesh& mesh, const std::filesystem::path& file) {
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(static_cast<std::size_t>(3 * mesh.num_faces()));
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = static_cast<std::uint32_t>(mesh.faces(f, k));
      const std::uint64_t b = static_cast<std::uint32_t>(mesh.faces(f, (k + 1) % 3));
      if (++directed[(a << 32) | b] > 1)
        throw InputError(file, "group 'body': edge " + std::to_string(a) + "-" + std::to_string(b) +
                                   " is used twice in one direction "
                                   "(non-manifold or inconsistently oriented)");
    }
  for (const auto& [key, count] : directed) {
    const std::uint64_t reverse = (key << 32) | (key >> 32);
    if (directed.find(reverse) == directed.end())
      throw InputError(file, "group 'body' is not closed: edge " + std::to_string(key >> 32) + "-" +
                                 std::to_string(key & 0xffffffffu) + " has one face");
  }
}

}  // namespace

MakeHumanModel::MakeHumanModel(const std::filesystem::path& dir) : dir_(dir) {
  const std::filesystem::path file = dir / "base.obj";
  ReadOptions options;
  options.units = LengthUnit::kDecimetre;
  const Mesh base = ReadMesh(options, file);
  const auto group = std::find(base.group_names.begin(), base.group_names.end(), "body");
  if (group == base.group_names.end()) throw InputError(file, "has no group 'body' (the skin)");
  const int body_group = static_cast<int>(group - base.group_names.begin());
  num_base_vertices_ = static_cast<int>(base.mesh.num_vertices());
  body_vertex_.assign(static_cast<std::size_t>(num_base_vertices_), -1);
  std::vector<Eigen::Index> faces;
  for (std::size_t f = 0; f < base.face_group.size(); ++f)
    if (base.face_group[f] == body_group) faces.push_back(static_cast<Eigen::Index>(f));
  if (faces.empty()) throw InputError(file, "group 'body' has no faces");
  for (const Eigen::Index f : faces)
    for (int k = 0; k < 3; ++k) body_vertex_[static_cast<std::size_t>(base.mesh.faces(f, k))] = 0;
  for (int v = 0; v < num_base_vertices_; ++v)
    if (body_vertex_[static_cast<std::size_t>(v)] == 0) {
      body_vertex_[static_cast<std::size_t>(v)] = static_cast<int>(base_index_.size());
      base_index_.push_back(v);
    }
  body_.vertices.resize(static_cast<Eigen::Index>(base_index_.size()), 3);
  for (std::size_t i = 0; i < base_index_.size(); ++i)
    body_.vertices.row(static_cast<Eigen::Index>(i)) = base.mesh.vertices.row(base_index_[i]);
  body_.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k)
      body_.faces(static_cast<Eigen::Index>(i), k) =
          body_vertex_[static_cast<std::size_t>(base.mesh.faces(faces[i], k))];
  CheckClosedManifold(body_, file);
  base_vertices_ = base.mesh.vertices;
  for (std::size_t f = 0; f < base.face_group.size(); ++f) {
    const std::string& name = base.group_names[static_cast<std::size_t>(base.face_group[f])];
    if (name.rfind("joint-", 0) != 0) continue;
    std::vector<int>& list = joints_[name];
    for (int k = 0; k < 3; ++k) list.push_back(base.mesh.faces(static_cast<Eigen::Index>(f), k));
  }
  for (auto& [name, list] : joints_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
}

int MakeHumanModel::BodyVertex(int base_vertex) const {
  if (base_vertex < 0 || base_vertex >= num_base_vertices_) return -1;
  return body_vertex_[static_cast<std::size_t>(base_vertex)];
}

bool MakeHumanModel::HasTarget(const std::string& name) const {
  std::error_code ec;
  return std::filesystem::is_regular_file(dir_ / "targets" / name, ec);
}

const MakeHumanTarget& MakeHumanModel::Target(const std::string& name) {
  const auto it = cache_.find(name);
  if (it != cache_.end()) return it->second;
  const std::filesystem::path file = dir_ / "targets" / name;
  MakeHumanTarget target = ReadMakeHumanTarget(file);
  for (const int v : target.vertex)
    if (v >= num_base_vertices_)
      throw InputError(file, "vertex index " + std::to_string(v) + " is past base.obj's " +
                                 std::to_string(num_base_vertices_) + " vertices");
  return cache_.emplace(name, std::move(target)).first->second;
}

TriangleMesh MakeHumanModel::Morph(const std::map<std::string, double>& weights) {
  return MorphWithJoints(weights).body;
}

Eigen::MatrixX3d MakeHumanModel::MorphAll(const std::map<std::string, double>& weights) {
  Eigen::MatrixX3d all = base_vertices_;
  for (const auto& [name, weight] : weights) {
    if (weight == 0) continue;
    const MakeHumanTarget& target = Target(name);
    for (std::size_t i = 0; i < target.vertex.size(); ++i)
      all.row(target.vertex[i]) += weight * target.offset.row(static_cast<Eigen::Index>(i));
  }
  return all;
}

Eigen::MatrixX3d MakeHumanModel::SkinRows(const Eigen::MatrixX3d& all) const {
  Eigen::MatrixX3d skin(static_cast<Eigen::Index>(base_index_.size()), 3);
  for (std::size_t i = 0; i < base_index_.size(); ++i)
    skin.row(static_cast<Eigen::Index>(i)) = all.row(base_index_[i]);
  return skin;
}

MakeHumanModel::Morphed MakeHumanModel::MorphWithJoints(
    const std::map<std::string, double>& weights) {
  const Eigen::MatrixX3d all = MorphAll(weights);
  Morphed out;
  out.body.faces = body_.faces;
  out.body.vertices = SkinRows(all);
  for (const auto& [name, list] : joints_) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const int v : list) centre += all.row(v).transpose();
    out.joints[name] = centre / static_cast<double>(list.size());
  }
  return out;
}

MakeHumanModel::~MakeHumanModel() = default;

const MakeHumanRig& MakeHumanModel::Rig() {
  if (!rig_) rig_ = std::make_unique<MakeHumanRig>(LoadMakeHumanRig(dir_ / "rig", *this));
  return *rig_;
}

Eigen::Affine3d MakeHumanModel::BodyFromMakeHuman() {
  Eigen::Matrix3d r;
  r << -1, 0, 0,  //
      0, 0, 1,    //
      0, 1, 0;
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.linear() = 100.0 * r;
  return t;
}

}  // namespace bespoke
