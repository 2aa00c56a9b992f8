// The wavefront propagation shared by the mesh geodesics (mesh_geodesics.h)
// and the point-cloud geodesics (measure/cloud_geodesic/propagation.h):
// thesis section 3.4.5, "continuous Dijkstra" without a priority queue.
//
// Over a graph of nodes (mesh vertices, grid cells) with positions and unit
// normals, wavefronts W (being expanded), W' (settled this pass, expanded
// next) and W_next (nodes with neighbours held back) and the radius limit
// r_max keep causality: a node is settled only when its estimated distance
// is <= r_max; when W and W' run dry, r_max grows and W_next is expanded.
// A new node's parent is one of its settled neighbours (parent_choice.h);
// what settling a node means (inheriting the parent's window, the curvature flow,
// projection onto faces) is the solver's.
//
// Lengths are in the surface's units (mm for scans). The options count
// lengths in spacings s of the surface: a mesh's mean edge length, a grid's
// cell size, so that one setting suits bodies in mm and small objects alike.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_H_

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "measure/mesh_geodesic/parent_choice.h"
#include "scanners/core/progress.h"

namespace bespoke {

// The scheduler: W, W', W_next and r_max of one propagation. The solver
// gives num_nodes(), neighbours_begin/end(u), settled(u), settled_count(),
// ChooseParent(u) -> ParentChoice and Settle(u, parent).
class Wavefront {
 public:
  // `band`: r_max grows by this per round (surface units); 0 = the thesis's
  // r_max = the largest held-back estimate.
  Wavefront(int num_nodes, double band) : band_(band), stamp_(static_cast<size_t>(num_nodes), -1) {}

  // Starts the front at settled `node`; `r_max` is the first radius limit.
  void Seed(int node) { front_.push_back(node); }
  void set_r_max(double r_max) { r_max_ = r_max; }

  bool done() const { return done_; }
  std::int64_t rounds() const { return rounds_; }

  // Propagates until `target` is settled, or everything reachable when
  // `target` < 0, reporting progress every `report_every` settled nodes.
  template <class Solver>
  void Run(Solver& solver, int target, const char* stage, std::int64_t report_every,
           Progress* progress) {
    if (done_ || (target >= 0 && solver.settled(target))) return;
    ProgressBegin(progress, stage, solver.num_nodes());
    std::int64_t reported = solver.settled_count();
    std::vector<int> wave;
    while (!(target >= 0 && solver.settled(target))) {
      if (front_.empty() && !NextRound()) break;
      wave.clear();
      wave.swap(front_);  // W; nodes settled now go to W' (front_)
      for (const int c : wave) Expand(solver, c);
      if (solver.settled_count() - reported >= report_every) {
        reported = solver.settled_count();
        ProgressUpdate(progress, reported);
      }
    }
    ProgressEnd(progress);
  }

 private:
  // W and W' are exhausted: widen r_max and expand W_next; false when empty.
  bool NextRound();

  template <class Solver>
  void Expand(Solver& solver, int c) {
    bool held = false;
    for (const int* l = solver.neighbours_begin(c); l != solver.neighbours_end(c); ++l) {
      if (solver.settled(*l)) continue;
      const ParentChoice choice = solver.ChooseParent(*l);
      if (choice.estimate <= r_max_) {
        solver.Settle(*l, choice.parent);
        front_.push_back(*l);
      } else {
        held = true;
        min_held_ = std::min(min_held_, choice.estimate);
        max_held_ = std::max(max_held_, choice.estimate);
      }
    }
    if (held && stamp_[static_cast<size_t>(c)] != rounds_) {
      stamp_[static_cast<size_t>(c)] = static_cast<int>(rounds_);
      next_.push_back(c);
    }
  }

  double band_;
  std::vector<int> front_, next_, stamp_;  // W / W', W_next, dedup of W_next
  double r_max_ = 0, min_held_ = std::numeric_limits<double>::infinity(), max_held_ = 0;
  std::int64_t rounds_ = 0;
  bool done_ = false;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_H_
