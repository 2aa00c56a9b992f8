// A generated body: a closed triangle mesh in the body frame with its datum
// points known exactly (the test oracle's ground truth).
//
// Frame (docs/contracts.md): millimetres, +z up, feet on z = 0, origin centred
// between the feet, facing +y; the person's right is +x, left is -x.
// Datum points (landmarks) are points ON the mesh surface, stored as a face
// and barycentric weights so that exact geodesics can start and end there.
// Their names and definitions are the measurement catalogue's
// (docs/measurements.md); the parametric model takes them from its
// construction, MakeHuman bodies from fixed points of the base topology.
#ifndef BESPOKE_ORACLE_BODY_BODY_H_
#define BESPOKE_ORACLE_BODY_BODY_H_

#include <map>
#include <string>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

// A point on a triangle mesh's surface.
struct SurfacePoint {
  int face = -1;                                          // row of mesh.faces
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();  // weights of the face's vertices, sum 1
};

// The 3-D position (mesh units) of `point`. Throws InternalError when the
// face index is out of range.
Eigen::Vector3d PositionOf(const TriangleMesh& mesh, const SurfacePoint& point);

// The surface point of `mesh` closest to `position` (brute force over faces,
// O(#F); for a few dozen landmarks this is fine).
SurfacePoint ClosestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& position);

// The limb a mesh vertex belongs to (Body::limbs).
enum class BodyLimb : signed char { kTrunk = 0, kArmRight, kArmLeft, kLegRight, kLegLeft };

struct Body {
  std::string model;                              // "parametric" or "makehuman"
  TriangleMesh mesh;                              // body frame, mm, closed and watertight
  std::map<std::string, SurfacePoint> landmarks;  // datum points, by catalogue name
  std::map<std::string, double> parameters;       // what generated it, e.g. "height_mm", "seed"
  // Per mesh vertex (#V), its limb, from the model's skeleton (MakeHuman: the
  // bones holding most of its skin weight); empty when the model has none.
  // A limb girth's truth is cut on its limb's own surface where the posed
  // limb passes into the trunk or the other leg (reference_measurements.h).
  std::vector<BodyLimb> limbs;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_BODY_H_
