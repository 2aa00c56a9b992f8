#include "scanners/clean/mesh_sampling.h"

#include <open3d/geometry/PointCloud.h>
#include <open3d/geometry/TriangleMesh.h>
#include <open3d/utility/Random.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>

#include "scanners/core/errors.h"
#include "scanners/core/units.h"

namespace bespoke {
namespace {

// Open3D's random engine is global: one sampling at a time.
std::mutex& SamplingMutex() {
  static std::mutex mutex;
  return mutex;
}

double SurfaceAreaMm2(const TriangleMesh& mesh) {
  double area = 0;
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace

void MeshSamplingOptions::Check() const {
  if (!(points_per_cm2 >= 0.1 && points_per_cm2 <= 1000))
    throw InputError("mesh sampling: points_per_cm2 must be in [0.1, 1000]");
  if (max_points < 1 || max_points > 100'000'000)
    throw InputError("mesh sampling: max_points must be in [1, 100000000]");
}

PointCloud SampleMeshSurface(const MeshSamplingOptions& options, const TriangleMesh& mesh) {
  options.Check();
  mesh.CheckIndices();
  if (mesh.num_faces() == 0) throw InputError("mesh sampling: the mesh has no faces");
  const double area_cm2 = SurfaceAreaMm2(mesh) / 100;
  if (!(area_cm2 > 0)) throw InputError("mesh sampling: the mesh has zero area");
  const auto count = static_cast<std::size_t>(std::clamp<double>(
      std::round(area_cm2 * options.points_per_cm2), 1, static_cast<double>(options.max_points)));
  open3d::geometry::TriangleMesh o3d;
  o3d.vertices_.resize(static_cast<std::size_t>(mesh.num_vertices()));
  for (Eigen::Index v = 0; v < mesh.num_vertices(); ++v)
    o3d.vertices_[static_cast<std::size_t>(v)] = mesh.vertices.row(v).transpose();
  o3d.triangles_.resize(static_cast<std::size_t>(mesh.num_faces()));
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    o3d.triangles_[static_cast<std::size_t>(f)] = mesh.faces.row(f).transpose();
  std::shared_ptr<open3d::geometry::PointCloud> sampled;
  {
    const std::lock_guard<std::mutex> lock(SamplingMutex());
    open3d::utility::random::Seed(options.seed);
    sampled = o3d.SamplePointsUniformly(count, /*use_triangle_normal=*/true);
  }
  PointCloud cloud;
  const auto n = static_cast<Eigen::Index>(sampled->points_.size());
  cloud.points.resize(n, 3);
  cloud.normals.resize(sampled->HasNormals() ? n : 0, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    cloud.points.row(i) = sampled->points_[static_cast<std::size_t>(i)].transpose();
    if (sampled->HasNormals())
      cloud.normals.row(i) =
          sampled->normals_[static_cast<std::size_t>(i)].normalized().transpose();
  }
  return cloud;
}

Scan ReadScanSamplingMeshes(const ReadOptions& read, const MeshSamplingOptions& sampling,
                            const std::filesystem::path& file) {
  sampling.Check();
  Scan scan = ReadScan(read, file);
  if (scan.report.faces_in_file <= 0) return scan;
  const Mesh mesh = ReadMesh(read, file);
  TriangleMesh mm = mesh.mesh;
  mm.vertices *= MillimetresPer(scan.report.unit);
  scan.cloud = SampleMeshSurface(sampling, mm);
  scan.report.warnings.push_back(
      "a mesh (" + std::to_string(mesh.mesh.num_vertices()) + " vertices, " +
      std::to_string(mesh.mesh.num_faces()) + " faces): sampled over its faces into " +
      std::to_string(scan.cloud.size()) + " points, not taken as its vertices");
  return scan;
}

}  // namespace bespoke
