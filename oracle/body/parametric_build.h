// Internal to the parametric body (parametric_body.cc, parametric_limbs.cc):
// the state shared while the mesh is assembled. Not for other callers.
#ifndef BESPOKE_ORACLE_BODY_PARAMETRIC_BUILD_H_
#define BESPOKE_ORACLE_BODY_PARAMETRIC_BUILD_H_

#include <map>
#include <string>
#include <vector>

#include "oracle/body/mesh_builder.h"
#include "oracle/body/parametric_layout.h"

namespace bespoke::parametric {

// A ring built at a girth level (right side for limbs; the left is the mirror).
struct GirthRing {
  std::string measurement;
  std::vector<int> ring;         // vertex indices in order around the ring
  Section section;               // the analytic shape in the ring's plane
  Eigen::Vector3d plane_point;   // body frame, mm
  Eigen::Vector3d plane_normal;  // unit
  // The section's coordinates: a point (u, v) of `section` is at
  // origin + u * axis_u + v * axis_v (body frame, mm).
  Eigen::Vector3d origin, axis_u, axis_v;
  bool limb = false;  // true: mirrored to the left side as well
};

struct Build {
  const BodyLayout* layout = nullptr;
  MeshBuilder mesh;
  int n = 0;  // torso_segments (N): columns of the torso, vertices around a leg
  int h = 0;  // armhole half-width in columns
  int ring_armpit = 0, ring_shoulder = 0;     // torso ring indices bounding the armholes
  std::vector<double> torso_z;                // torso ring heights
  std::vector<std::vector<int>> torso;        // [ring][column] vertex, -1 inside an armhole
  std::map<std::string, int> torso_key_ring;  // key name ("hip_girth", "jugulare", ...) -> ring
  std::vector<int> bridge;                    // crotch bridge vertices, front to back (interior)
  int crown = -1;
  std::vector<int> mirror;  // vertex -> its mirror image (x -> -x)
  std::vector<GirthRing> girths;
  std::map<std::string, int> landmarks;   // right-side and centre landmarks -> vertex
  std::map<std::string, double> derived;  // construction values reported in Body::parameters
  std::vector<std::pair<int, BodyPart>> part_starts;  // first vertex of each part, ascending
  std::map<std::string, Eigen::Vector3d> joints;  // right side and centre (ParametricBodyDetails)

  // Column index modulo n.
  int Col(int j) const { return ((j % n) + n) % n; }
  int Mirror(int v) const { return mirror[static_cast<size_t>(v)]; }
  void SetMirror(int a, int b);
};

// Torso grid, crotch bridge and crown (parametric_body.cc).
void BuildTorso(Build* b);
// Right and left legs (parametric_limbs.cc); needs the torso.
void BuildLegs(Build* b);
// Right and left arms (parametric_limbs.cc); needs the torso.
void BuildArms(Build* b);

// Ring levels between `from` and `to` (exclusive of `from`, inclusive of
// `to`), at most `spacing` apart, at least `min_steps` steps.
std::vector<double> Subdivide(double from, double to, double spacing, int min_steps = 1);

// Splits the edges of every girth ring (and the mirrored left limb rings) so
// that each ring has at least `min_segments` vertices; the new vertices lie
// exactly on the analytic section (radial projection from its centre).
// Faces beside the rings become fans; everything stays closed.
void RefineGirthRings(Build* b, int min_segments);

// The breasts (parametric_bust.cc): the torso's front between the bust
// points pressed back into a cleavage. At the bust level the front is flat
// between the bust points (the tape's line); the skin inside them is moved
// back by depth * (1 - s^2)^2, s = |x| / w (w: the flat part's half-width
// at that height), so each bust point is the most forward point of its side
// and the tape round the bust is unchanged. The depth is a quarter of bust
// minus under-bust girth (at most 40 % of the bust's front depth), full at
// the bust level and fading (smoothstep) to nothing at the under-bust level
// and 60 % of that distance above the bust (at most up to the armpit level).
// `part`: #V; only the torso's vertices move. Records "cleavage_depth_mm" in
// derived.
void CarveCleavage(const std::vector<BodyPart>& part, Build* b);

// Largest horizontal change between two sections (mm): how far a ring
// moves sideways between them, used to place enough rings.
double SidewaysChange(const Section& x, const Section& y);

// Adds a tube: `first` (existing vertices), then rings of new vertices,
// then a pole; orients the new faces like the rest. Returns the new rings'
// vertex indices (the pole last, as a one-element ring).
std::vector<std::vector<int>> AddTube(Build* b, const std::vector<int>& first,
                                      const std::vector<std::vector<Eigen::Vector3d>>& rings,
                                      const Eigen::Vector3d& pole);

// The same tube mirrored to the left (x -> -x, ring order reversed so that
// the orientation is kept): `right` are the right tube's new rings as
// returned by AddTube; the mirror map is filled.
std::vector<std::vector<int>> AddMirroredTube(Build* b, const std::vector<int>& right_first,
                                              const std::vector<std::vector<int>>& right);

}  // namespace bespoke::parametric

#endif  // BESPOKE_ORACLE_BODY_PARAMETRIC_BUILD_H_
