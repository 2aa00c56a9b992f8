#include "scanners/core/types.h"

#include <cmath>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

void PointCloud::CheckShapes() const {
  const Eigen::Index n = points.rows();
  auto check = [n](Eigen::Index rows, const std::string& what) {
    if (rows != 0 && rows != n) {
      throw InternalError("point cloud has " + std::to_string(n) + " points but " +
                          std::to_string(rows) + " " + what);
    }
  };
  check(normals.rows(), "normals");
  check(colors.rows(), "colours");
  for (const auto& [name, values] : scalars) check(values.size(), "values of '" + name + "'");
}

PointCloud PointCloud::Select(const std::vector<Eigen::Index>& indices) const {
  CheckShapes();
  PointCloud out;
  const auto m = static_cast<Eigen::Index>(indices.size());
  out.points.resize(m, 3);
  if (has_normals()) out.normals.resize(m, 3);
  if (has_colors()) out.colors.resize(m, 3);
  for (const auto& [name, values] : scalars) {
    if (values.size() == size()) out.scalars[name].resize(m);
  }
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Index i = indices[static_cast<size_t>(k)];
    BESPOKE_CHECK(i >= 0 && i < size(), "PointCloud::Select index out of range");
    out.points.row(k) = points.row(i);
    if (has_normals()) out.normals.row(k) = normals.row(i);
    if (has_colors()) out.colors.row(k) = colors.row(i);
    for (auto& [name, values] : out.scalars) values[k] = scalars.at(name)[i];
  }
  return out;
}

void TriangleMesh::CheckIndices() const {
  const Eigen::Index nv = vertices.rows();
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = faces(f, c);
      if (v < 0 || v >= nv) {
        throw InputError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                         " but the mesh has " + std::to_string(nv) + " vertices");
      }
    }
  }
}

void TransformInPlace(const Eigen::Affine3d& b_from_a, PointCloud* cloud) {
  const Eigen::Matrix3d linear = b_from_a.linear();
  const Eigen::Vector3d t = b_from_a.translation();
  cloud->points = (cloud->points * linear.transpose()).rowwise() + t.transpose();
  if (cloud->has_normals()) {
    // Normals take the rotation only (the transform is a similarity).
    Eigen::Matrix3d rotation = linear / std::cbrt(std::abs(linear.determinant()));
    cloud->normals = cloud->normals * rotation.transpose();
  }
}

void TransformInPlace(const Eigen::Affine3d& b_from_a, TriangleMesh* mesh) {
  const Eigen::Matrix3d linear = b_from_a.linear();
  mesh->vertices =
      (mesh->vertices * linear.transpose()).rowwise() + b_from_a.translation().transpose();
}

}  // namespace bespoke
