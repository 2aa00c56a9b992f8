#include "scanners/body/parametric_body.h"

#include <gtest/gtest.h>

#include "scanners/body/mesh_checks.h"

namespace bespoke {
namespace {

TEST(ParametricBody, DefaultIsAClosedSphere) {
  ParametricBodyDetails details;
  const Body body = GenerateParametricBody(ParametricBodyOptions(), &details);
  const MeshTopology t = AnalyzeTopology(body.mesh);
  EXPECT_TRUE(t.IsClosedSphere()) << t.Describe();
  EXPECT_FALSE(SelfIntersects(body.mesh));
}

}  // namespace
}  // namespace bespoke
