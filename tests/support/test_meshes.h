// Meshes with known geodesics for the mesh-geodesic tests, built in code.
#ifndef BESPOKE_TESTS_SUPPORT_TEST_MESHES_H_
#define BESPOKE_TESTS_SUPPORT_TEST_MESHES_H_

#include "scanners/core/types.h"

namespace bespoke::testing {

// An icosahedron subdivided `levels` times, vertices on the sphere of
// `radius_mm` about the origin (10 * 4^levels + 2 vertices), outward faces.
TriangleMesh Icosphere(double radius_mm, int levels);

// An open tube: `around` vertices per ring (ring i at angle 2 pi i / around),
// `rings` rings from z = 0 to z = height_mm. Vertex (ring j, index i) is
// j * around + i. Side quads split into two triangles. The polyhedral
// geodesic between two vertices is straight on the unrolled prism.
TriangleMesh Tube(double radius_mm, double height_mm, int around, int rings);

// The exact polyhedral geodesic between vertices a and b of Tube(...).
double TubeDistance(double radius_mm, double height_mm, int around, int rings, int a, int b);

// A flat (z = 0) grid of nx x ny vertices with `spacing_mm`, jittered in x, y
// by up to `jitter` spacings (deterministic), split into triangles.
TriangleMesh FlatGrid(int nx, int ny, double spacing_mm, double jitter);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_TEST_MESHES_H_
