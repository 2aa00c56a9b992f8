// Geodesics from one mesh vertex to every vertex: thesis Algorithm 3
// (approximate, linear time) and Algorithm 2 (accurate), section 3.4.5.
//
// "Continuous Dijkstra" without a priority queue over the mesh's vertex
// graph: wavefronts W (being expanded), W' (settled this pass) and W_next
// (vertices with neighbours held back) and the radius limit r_max, grown by
// `band_edges` mean edge lengths per round, keep causality. A new vertex
// takes as parent the settled neighbour whose path continues straightest into
// it among those predicting (nearly) the shortest distance, inherits the
// parent's path plus its own position (no backtracing), and the geodesic
// curvature flow (measure/mesh_geodesic/curvature_flow.h, Eq 3.12-3.17, tangent
// planes from PCA of one-ring face normals: mesh_surface.h) straightens
//   - Algorithm 3: the last `window` samples, the first held fixed;
//   - Algorithm 2 (`whole_path`): the whole path, source held fixed.
// The flowed path floats on tangent planes ("offset" geodesic); its length is
// the offset distance. Algorithm 1 (path_projection.h) projects it onto the
// faces for the projected distance: for Algorithm 3 only the window is
// re-projected and added to the projected length of the inherited prefix.
//
// Error estimate (Eq 3.20-3.24) for Algorithm 3: the window's first sample is
// held on the parent's path; the kink theta it leaves there (in the tangent
// plane) says how far the true geodesic may pass from it, y_max = L sin(theta)
// / 2 with L the window's length; Eq 3.22 turns that into a length error
// sqrt(L^2 + 4 y_max^2) - L, summed along the chain of parents as Eq 3.24
// sums it over the path. Reported per vertex (error_bound); 0 for Algorithm 2.
//
// Memory: each vertex's window is freed once all its neighbours are settled
// (no vertex can inherit from it any more) unless `keep_paths`, so the live
// windows are the wavefront's: O(#V) total for Algorithm 3. `keep_paths`
// keeps every window (O(#V w)) so Path() can rebuild any path.
// Units: the mesh's.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_MESH_GEODESICS_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_MESH_GEODESICS_H_

#include <cstdint>
#include <vector>

#include "measure/mesh_geodesic/curvature_flow.h"
#include "measure/mesh_geodesic/mesh_surface.h"
#include "measure/mesh_geodesic/wavefront.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct MeshGeodesicsOptions {
  // The propagation; lengths in mean edge lengths. Edges are finer than a
  // grid's cells, so the flow's tolerance defaults to 0.002 edges.
  WavefrontOptions wavefront = MeshWavefrontDefaults();
  bool project = true;      // Algorithm 1 projected distances; default on
  bool keep_paths = false;  // keep every window so Path() works; default off
  void Check() const;       // InputError when out of range

  static WavefrontOptions MeshWavefrontDefaults() {
    WavefrontOptions defaults;
    defaults.flow_tolerance_spacings = 0.002;
    return defaults;
  }
};

struct MeshGeodesicsStats : WavefrontStats {
  std::int64_t projection_fallbacks = 0;  // projected segments measured as chords
  std::int64_t peak_window_samples = 0;   // most samples stored at once
};

class MeshGeodesics {
 public:
  // `source`: a used vertex of `surface` (InputError otherwise). The surface
  // must outlive this object.
  MeshGeodesics(const MeshGeodesicsOptions& options, const MeshSurface& surface, int source);

  // Propagates until `target` is settled, or everything reachable when < 0.
  void Run(int target = -1, Progress* progress = nullptr);

  int source() const { return source_; }
  bool settled(int v) const { return settled_[static_cast<size_t>(v)] != 0; }
  // Lengths from the source (mesh units); +inf for unsettled vertices.
  double offset_distance(int v) const { return offset_[static_cast<size_t>(v)]; }
  double projected_distance(int v) const { return projected_[static_cast<size_t>(v)]; }
  double error_bound(int v) const { return bound_[static_cast<size_t>(v)]; }  // Eq 3.24
  // The floating path source -> v (#S x 3) and its hint vertices. Needs
  // keep_paths (InputError otherwise, or when v is not settled).
  Eigen::MatrixX3d Path(int v, std::vector<int>* hints = nullptr) const;

  const MeshGeodesicsStats& stats() const { return stats_; }

 private:
  struct Sample {
    Eigen::Vector3d point;
    TangentPlane plane;
    double arc = 0, projected = 0;  // lengths from the source to here
    int hint = -1;
  };
  friend class Wavefront;
  template <class View>
  friend ParentChoice ChooseParent(const View&, int, ParentRule, double);
  // The solver interface of Wavefront and ChooseParent (parent_choice.h).
  int num_nodes() const { return surface_.num_vertices(); }
  const int* neighbours_begin(int v) const { return surface_.neighbours_begin(v); }
  const int* neighbours_end(int v) const { return surface_.neighbours_end(v); }
  std::int64_t settled_count() const { return stats_.settled; }
  double distance(int v) const { return offset_[static_cast<size_t>(v)]; }
  const Eigen::Vector3d& tangent(int v) const { return tangent_[static_cast<size_t>(v)]; }
  Eigen::Vector3d position(int v) const { return surface_.position(v); }
  const Eigen::Vector3d& normal(int v) const { return surface_.normal(v); }
  ParentChoice ChooseParent(int v) const;
  void Settle(int v, int parent);
  void Release(int v);

  MeshGeodesicsOptions options_;
  CurvatureFlowOptions flow_;
  const MeshSurface& surface_;
  int source_;
  std::vector<double> offset_, projected_, bound_;
  std::vector<int> parent_, start_, open_;
  std::vector<char> settled_;
  std::vector<Eigen::Vector3d> tangent_;
  std::vector<std::vector<Sample>> windows_;
  Wavefront wavefront_;
  std::int64_t live_samples_ = 0;
  MeshGeodesicsStats stats_;
  // Scratch reused by Settle.
  Eigen::MatrixX3d path_;
  std::vector<int> hints_;
  std::vector<TangentPlane> planes_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_MESH_GEODESICS_H_
