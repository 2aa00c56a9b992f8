// The parent a new node inherits its geodesic from, in the wavefront
// propagation (wavefront.h) of the mesh and point-cloud geodesics: thesis
// section 3.4.5 ("the visited neighbour whose path continues straightest").
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_PARENT_CHOICE_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_PARENT_CHOICE_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/mesh_geodesic/wavefront_options.h"

namespace bespoke {

struct ParentChoice {
  int parent = -1;      // the chosen settled neighbour; -1 when none is settled
  double estimate = 0;  // the node's predicted distance through it
};

// The parent of unsettled `node` among its settled neighbours (thesis rule:
// the one whose path continues straightest into it; kPredicted: among those
// predicting within `tie` of the smallest distance). A neighbour v predicts
// the distance from a virtual source distance(v) behind v along its arrival
// tangent, developed into v's tangent plane (exact on a plane). `view`
// gives, for a node u: neighbours_begin(u) / neighbours_end(u) (int
// ranges), settled(u), distance(u), tangent(u) (unit, or zero when
// unknown), position(u) and normal(u) (3-vectors, unit normal).
template <class View>
ParentChoice ChooseParent(const View& view, int node, ParentRule rule, double tie) {
  struct Candidate {
    int node;
    double predicted, cosine, simple;
  };
  Candidate found[64];
  int count = 0;
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector3d site = view.position(node);
  for (const int* l = view.neighbours_begin(node); l != view.neighbours_end(node) && count < 64;
       ++l) {
    const int v = *l;
    if (!view.settled(v)) continue;
    const Eigen::Vector3d e = site - view.position(v);
    const double length = e.norm();
    const Eigen::Vector3d& t = view.tangent(v);
    Candidate c{v, view.distance(v) + length, 1.0, view.distance(v) + length};
    if (t.squaredNorm() > 0 && length > 0) {
      const double along = t.dot(e);
      const Eigen::Vector3d n = view.normal(v);
      Eigen::Vector3d lateral = e - along * t;
      lateral -= n * n.dot(lateral);
      c.predicted = std::hypot(view.distance(v) + along, lateral.norm());
      c.cosine = along / length;
    }
    best = std::min(best, c.predicted);
    found[count++] = c;
  }
  ParentChoice choice;
  double best_cosine = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i) {
    const Candidate& c = found[i];
    if (rule == ParentRule::kPredicted && c.predicted > best + tie) continue;
    if (c.cosine <= best_cosine) continue;
    best_cosine = c.cosine;
    choice.parent = c.node;
    choice.estimate = rule == ParentRule::kPredicted ? c.predicted : c.simple;
  }
  return choice;
}

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_PARENT_CHOICE_H_
