#include "eval/validate/surface_reconstruction.h"

#include <open3d/geometry/KDTreeSearchParam.h>
#include <open3d/geometry/PointCloud.h>
#include <open3d/geometry/TriangleMesh.h>

#include <algorithm>
#include <string>

#include "measure/cloud_geodesic/point_index.h"
#include "scanners/core/errors.h"

namespace bespoke {

void PoissonOptions::Check() const {
  if (depth < 5 || depth > 12) throw InputError("poisson: depth must be in [5, 12]");
  if (normal_neighbours < 5) throw InputError("poisson: normal_neighbours must be >= 5");
  if (!(trim_distance_mm >= 0)) throw InputError("poisson: trim_distance_mm must be >= 0");
  if (max_vertices < 1000) throw InputError("poisson: max_vertices must be >= 1000");
}

namespace {

// Removes faces round non-manifold vertices and edges until CGAL would
// accept the mesh (a few passes suffice in practice).
void MakeManifold(open3d::geometry::TriangleMesh* mesh) {
  for (int pass = 0; pass < 8; ++pass) {
    mesh->RemoveDuplicatedVertices();
    mesh->RemoveDuplicatedTriangles();
    mesh->RemoveDegenerateTriangles();
    mesh->RemoveNonManifoldEdges();
    mesh->RemoveUnreferencedVertices();
    const std::vector<int> bad = mesh->GetNonManifoldVertices();
    if (bad.empty()) return;
    std::vector<bool> mask(mesh->vertices_.size(), false);
    for (const int v : bad) mask[static_cast<size_t>(v)] = true;
    mesh->RemoveVerticesByMask(mask);
  }
}

}  // namespace

TriangleMesh ReconstructPoisson(const PoissonOptions& options, const PointCloud& cloud,
                                Progress* progress) {
  options.Check();
  if (cloud.size() < 100)
    throw InputError("poisson: need at least 100 points, got " + std::to_string(cloud.size()));
  ProgressBegin(progress, "reconstructing a reference mesh", 4);
  open3d::geometry::PointCloud pcd;
  pcd.points_.resize(static_cast<size_t>(cloud.size()));
  for (Eigen::Index i = 0; i < cloud.size(); ++i) pcd.points_[i] = cloud.points.row(i).transpose();
  if (cloud.has_normals()) {
    pcd.normals_.resize(pcd.points_.size());
    for (Eigen::Index i = 0; i < cloud.size(); ++i)
      pcd.normals_[i] = cloud.normals.row(i).transpose().normalized();
  } else {
    pcd.EstimateNormals(open3d::geometry::KDTreeSearchParamKNN(options.normal_neighbours));
    pcd.OrientNormalsConsistentTangentPlane(static_cast<size_t>(options.normal_neighbours));
  }
  ProgressUpdate(progress, 1);
  auto [mesh, density] = open3d::geometry::TriangleMesh::CreateFromPointCloudPoisson(
      pcd, static_cast<size_t>(options.depth), 0.0f, 1.1f, false, 1);
  (void)density;
  ProgressUpdate(progress, 2);
  // Trim what Poisson invented far from the scan.
  const PointIndex index(cloud.points);
  const double trim =
      options.trim_distance_mm > 0 ? options.trim_distance_mm : 5 * index.MedianSpacing();
  std::vector<bool> far(mesh->vertices_.size(), false);
  for (size_t v = 0; v < mesh->vertices_.size(); ++v) {
    double d2 = 0;
    index.Nearest(mesh->vertices_[v], &d2);
    far[v] = d2 > trim * trim;
  }
  mesh->RemoveVerticesByMask(far);
  if (static_cast<int>(mesh->vertices_.size()) > options.max_vertices)
    mesh = mesh->SimplifyQuadricDecimation(2 * options.max_vertices, 1e30, 1.0);
  ProgressUpdate(progress, 3);
  MakeManifold(mesh.get());
  ProgressEnd(progress);
  if (mesh->triangles_.empty())
    throw InternalError("poisson: the reconstructed mesh is empty after trimming and cleaning");
  TriangleMesh out;
  out.vertices.resize(static_cast<Eigen::Index>(mesh->vertices_.size()), 3);
  for (size_t v = 0; v < mesh->vertices_.size(); ++v)
    out.vertices.row(static_cast<Eigen::Index>(v)) = mesh->vertices_[v].transpose();
  out.faces.resize(static_cast<Eigen::Index>(mesh->triangles_.size()), 3);
  for (size_t f = 0; f < mesh->triangles_.size(); ++f)
    out.faces.row(static_cast<Eigen::Index>(f)) = mesh->triangles_[f].transpose();
  return out;
}

}  // namespace bespoke
