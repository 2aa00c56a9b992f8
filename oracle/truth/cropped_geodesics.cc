#include "oracle/truth/cropped_geodesics.h"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

#include "scanners/core/cell_key.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// The sub-mesh of `faces` (vertices renumbered, face order kept) and the map
// from mesh faces to crop faces (-1 where dropped).
struct Crop {
  TriangleMesh mesh;
  std::vector<int> face_in_crop;
};

Crop MakeCrop(const TriangleMesh& mesh, const std::vector<int>& faces) {
  Crop crop;
  crop.face_in_crop.assign(static_cast<std::size_t>(mesh.num_faces()), -1);
  std::vector<int> vertex_in_crop(static_cast<std::size_t>(mesh.num_vertices()), -1);
  std::vector<int> used;
  crop.mesh.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    crop.face_in_crop[static_cast<std::size_t>(faces[i])] = static_cast<int>(i);
    for (int k = 0; k < 3; ++k) {
      int& v = vertex_in_crop[static_cast<std::size_t>(mesh.faces(faces[i], k))];
      if (v < 0) v = static_cast<int>(used.size()), used.push_back(mesh.faces(faces[i], k));
      crop.mesh.faces(static_cast<Eigen::Index>(i), k) = v;
    }
  }
  crop.mesh.vertices.resize(static_cast<Eigen::Index>(used.size()), 3);
  for (std::size_t i = 0; i < used.size(); ++i)
    crop.mesh.vertices.row(static_cast<Eigen::Index>(i)) = mesh.vertices.row(used[i]);
  return crop;
}

SurfacePoint InCrop(const Crop& crop, const SurfacePoint& p) {
  SurfacePoint q = p;
  q.face = crop.face_in_crop[static_cast<std::size_t>(p.face)];
  BESPOKE_CHECK(q.face >= 0, "cropped geodesics: an end point's face is not in the crop");
  return q;
}

}  // namespace

void CroppedGeodesicsOptions::Check() const {
  if (!(initial_ratio >= 1)) throw InputError("cropped geodesics: initial_ratio must be >= 1");
  if (!(initial_margin >= 0)) throw InputError("cropped geodesics: initial_margin must be >= 0");
}

CroppedExactGeodesics::CroppedExactGeodesics(const TriangleMesh& mesh,
                                             const CroppedGeodesicsOptions& options)
    : mesh_(mesh), options_(options) {
  options_.Check();
  mesh_.CheckIndices();
  longest_edge_.resize(mesh_.num_faces());
  vertex_faces_.resize(static_cast<std::size_t>(mesh_.num_vertices()));
  for (Eigen::Index f = 0; f < mesh_.num_faces(); ++f) {
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh_.faces(f, k), w = mesh_.faces(f, (k + 1) % 3);
      longest = std::max(longest, (mesh_.vertices.row(v) - mesh_.vertices.row(w)).norm());
      vertex_faces_[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
    }
    longest_edge_[f] = longest;
  }
}

void CroppedExactGeodesics::AddPinchedStars(std::vector<char>* keep) const {
  for (int round = 0; round < 1000; ++round) {
    std::unordered_map<std::uint64_t, int> uses;
    for (Eigen::Index f = 0; f < mesh_.num_faces(); ++f) {
      if (!(*keep)[static_cast<std::size_t>(f)]) continue;
      for (int k = 0; k < 3; ++k) ++uses[EdgeKey(mesh_.faces(f, k), mesh_.faces(f, (k + 1) % 3))];
    }
    // A vertex whose kept faces form several fans has more than two
    // boundary edges among them.
    std::unordered_map<int, int> boundary_edges;
    for (const auto& [key, count] : uses) {
      if (count != 1) continue;
      ++boundary_edges[static_cast<int>(key >> 32)];
      ++boundary_edges[static_cast<int>(key & 0xffffffffu)];
    }
    bool added = false;
    for (const auto& [vertex, count] : boundary_edges) {
      if (count <= 2) continue;
      for (const int f : vertex_faces_[static_cast<std::size_t>(vertex)])
        (*keep)[static_cast<std::size_t>(f)] = 1;
      added = true;
    }
    if (!added) return;
  }
}

std::vector<int> CroppedExactGeodesics::CropFaces(const Eigen::Vector3d& a,
                                                  const Eigen::Vector3d& b, double radius) const {
  const Eigen::Index nv = mesh_.num_vertices();
  Eigen::VectorXd focal(nv);  // |v - a| + |v - b|
  for (Eigen::Index v = 0; v < nv; ++v) {
    const Eigen::Vector3d p = mesh_.vertices.row(v).transpose();
    focal[v] = (p - a).norm() + (p - b).norm();
  }
  std::vector<char> keep(static_cast<std::size_t>(mesh_.num_faces()), 0);
  for (Eigen::Index f = 0; f < mesh_.num_faces(); ++f) {
    const double nearest =
        std::min({focal[mesh_.faces(f, 0)], focal[mesh_.faces(f, 1)], focal[mesh_.faces(f, 2)]});
    keep[static_cast<std::size_t>(f)] = nearest <= radius + 2 * longest_edge_[f];
  }
  AddPinchedStars(&keep);
  std::vector<int> faces;
  for (std::size_t f = 0; f < keep.size(); ++f)
    if (keep[f]) faces.push_back(static_cast<int>(f));
  return faces;
}

GeodesicPath CroppedExactGeodesics::Path(const SurfacePoint& from, const SurfacePoint& to,
                                         bool keep_points) {
  for (const SurfacePoint* p : {&from, &to})
    if (p->face < 0 || p->face >= mesh_.num_faces())
      throw InputError("cropped geodesics: surface point on face " + std::to_string(p->face) +
                       ", but the mesh has " + std::to_string(mesh_.num_faces()) + " faces");
  ++stats_.queries;
  const Eigen::Vector3d a = PositionOf(mesh_, from), b = PositionOf(mesh_, to);
  double radius = options_.initial_ratio * (a - b).norm() + options_.initial_margin;
  while (true) {
    std::vector<int> faces = CropFaces(a, b, radius);
    const bool whole = static_cast<Eigen::Index>(faces.size()) == mesh_.num_faces();
    const Crop crop = MakeCrop(mesh_, faces);
    ExactGeodesics geodesics(crop.mesh);
    ++stats_.propagations;
    stats_.faces_used += static_cast<std::int64_t>(faces.size());
    stats_.whole_mesh += whole ? 1 : 0;
    const SurfacePoint s = InCrop(crop, from), t = InCrop(crop, to);
    double length = std::numeric_limits<double>::infinity();
    if (whole) {
      length = geodesics.Distance(s, t);  // throws when unreachable on the whole mesh
    } else {
      try {
        length = geodesics.Distance(s, t);
      } catch (const InputError&) {  // not connected within the crop: grow it
        radius *= 1.5;
        continue;
      }
    }
    if (whole || length <= radius) {
      GeodesicPath path;
      path.length = length;
      if (keep_points) path = geodesics.Path(s, t);
      return path;
    }
    radius = std::max(length, radius * 1.0001);  // holds the shortest path now
  }
}

}  // namespace bespoke
