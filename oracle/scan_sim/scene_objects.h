// What else stands in a scanner booth besides the subject: the floor patch
// and stray objects (a handle pole, a box or stool), as meshes in the body
// frame (mm) for the virtual scanner to cast rays against.
#ifndef BESPOKE_ORACLE_SCAN_SIM_SCENE_OBJECTS_H_
#define BESPOKE_ORACLE_SCAN_SIM_SCENE_OBJECTS_H_

#include <random>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

// A square on z = 0, centred on the booth axis, side 2 * half_size_mm,
// facing up, split into a grid of triangles about 100 mm across.
TriangleMesh FloorPatch(double half_size_mm);

// Up to `count` closed objects on the floor, alternating poles (cylinders,
// radius 15-30 mm, 0.9-1.9 m tall) and boxes (250-450 mm wide, 0.3-1 m
// tall), placed 0.45-0.75 x booth_radius_mm from the axis, each at least
// 80 mm (horizontally) from every body vertex at its height and from the
// other objects. Objects that find no free place in 200 tries are skipped.
std::vector<TriangleMesh> PlaceStrayObjects(const TriangleMesh& body, int count,
                                            double booth_radius_mm, std::mt19937_64& rng);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_SCENE_OBJECTS_H_
