// The datum points of MakeHuman bodies: fixed vertices of the base topology
// (the skin group `body` of base.obj, after dropping unused vertices), so
// they are known exactly on every generated body.
//
// The table (makehuman_landmarks.cc) was chosen with the geometric analysis
// in landmark_analysis.h: each rule (e.g. "armpit: the saddle vertex where
// the horizontal section of the arm separates from the trunk") was run on a
// spread of generated bodies, and the vertex with the smallest median
// distance to the rule's answer over those bodies was kept. The test
// MakeHumanLandmarks.TableStaysNearTheRulesOnUnseenBodies
// (makehuman_test.cc) re-runs the analysis on seeds the table was not chosen
// on and checks every table vertex stays within 100 mm of its rule's answer,
// with a median under 20 mm (measured: 3.5 mm on seeds 101 and 202).
// Exception: GenerateMakeHumanBody replaces the crown by each body's highest
// vertex.
#ifndef BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_LANDMARKS_H_
#define BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_LANDMARKS_H_

#include <map>
#include <string>
#include <vector>

#include "oracle/body/body.h"

namespace bespoke {

struct MakeHumanLandmark {
  const char* name;  // catalogue name
  int vertex;        // skin vertex index (MakeHumanModel::base_body() row)
};

// Every landmark of the catalogue's canonical list, both sides.
const std::vector<MakeHumanLandmark>& MakeHumanLandmarkTable();

// Bony datum points whose skin vertex takes most of its weight from another
// bone's (the acromion's vertex lies on the shoulder cap, 87 % upper arm):
// linear blend skinning would carry them with the arm, while the bone they
// belong to (the shoulder blade) stays. A posed body carries each of them
// rigidly with its own bone and puts it on the posed skin's closest point.
struct BoneCarriedLandmark {
  const char* name;  // catalogue name
  const char* bone;  // MakeHuman default skeleton bone
};
const std::vector<BoneCarriedLandmark>& MakeHumanBoneCarriedLandmarks();

// The landmarks as surface points of a body mesh with the skin's topology
// (any morph of base_body(), in any frame). InternalError when the mesh has
// fewer vertices than the table refers to.
std::map<std::string, SurfacePoint> MakeHumanLandmarkPoints(const TriangleMesh& body_mesh);

// Translates `body` (mesh, already rotated into the body frame's axes) so its
// lowest point is on z = 0 and the midpoint of its four malleoli
// (ankle_inside/outside_left/right) is at x = y = 0.
void PlaceOnFloorBetweenAnkles(Body* body);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_MAKEHUMAN_MAKEHUMAN_LANDMARKS_H_
