// The under-bust by its definition on parametric bodies: the profile's bends
// are computed here by brute force from the mesh's sections, and the level
// is checked against a brute-force search of the profile and against the
// no-fold convention, not against the code's own numbers.
#include "oracle/truth/defined_landmarks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "oracle/body/parametric_body.h"
#include "oracle/truth/mesh_section.h"

namespace bespoke {
namespace {

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

struct Defined {
  Body body;
  ParametricBodyDetails details;
  DefinedLevels levels;
};

Defined Make(const ParametricBodyOptions& options) {
  Defined d;
  d.body = GenerateParametricBody(options, &d.details);
  d.levels = PlaceDefinedLandmarks(DefinedLandmarkOptions{}, {}, &d.body);
  return d;
}

// The front of every section loop at height z on the vertical x = x0 (mm).
double FrontY(const Body& body, double z, double x0) {
  double front = -1e9;
  for (const SectionLoop& loop :
       SectionLoops(body.mesh, Eigen::Vector3d(0, 0, z), Eigen::Vector3d::UnitZ())) {
    const Eigen::Index n = loop.points.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3d a = loop.points.row(i), b = loop.points.row((i + 1) % n);
      if ((a.x() - x0) * (b.x() - x0) > 0 || a.x() == b.x()) continue;
      front = std::max(front, a.y() + (x0 - a.x()) / (b.x() - a.x()) * (b.y() - a.y()));
    }
  }
  return front;
}

// The bend of the front profile through the bust points at z: second
// difference of its depth over +-10 mm, both sides averaged.
double Bend(const Body& body, double z) {
  double sum = 0;
  for (const char* name : {"bust_right", "bust_left"}) {
    const double x = At(body, name).x();
    sum += FrontY(body, z + 10, x) + FrontY(body, z - 10, x) - 2 * FrontY(body, z, x);
  }
  return 0.5 * sum;
}

double BustZ(const Body& body) {
  return 0.5 * (At(body, "bust_right").z() + At(body, "bust_left").z());
}

// Going down from the bust, the first corner of the profile: found here by
// brute force at 1 mm (a local maximum of the bend over +-3 mm reaching half
// the band's sharpest), within 2 mm of the definition's level.
TEST(DefinedUnderBust, TheAverageWomansFoldIsTheFirstCornerUnderTheBust) {
  const Defined d = Make(ParametricBodyOptions{});
  const double bust = BustZ(d.body), stature = d.body.mesh.vertices.col(2).maxCoeff();
  std::vector<double> at, bend;
  for (double z = bust - 0.01 * stature; z >= bust - 0.08 * stature; z -= 1)
    at.push_back(z), bend.push_back(Bend(d.body, z));
  const double sharpest = *std::max_element(bend.begin(), bend.end());
  ASSERT_GE(sharpest, 3.0);  // a clear fold, not a flat chest
  double first = -1;
  for (std::size_t k = 3; k + 3 < at.size() && first < 0; ++k) {
    bool peak = bend[k] >= 0.5 * sharpest;
    for (std::size_t j = k - 3; j <= k + 3; ++j) peak = peak && bend[k] >= bend[j];
    if (peak) first = at[k];
  }
  EXPECT_NEAR(d.levels.under_bust_mm, first, 2.0);
  EXPECT_NEAR(At(d.body, "under_bust").z(), d.levels.under_bust_mm, 0.5);
}

// A big belly sharpens a corner under the fold (the under-bust ring's) until
// it bends more than the fold itself: the fold keeps its level (the sharpest
// bend alone would take the corner below).
TEST(DefinedUnderBust, ABellyThatBendsMoreBelowDoesNotTakeTheFold) {
  const Defined plain = Make(ParametricBodyOptions{});
  ParametricBodyOptions o;
  o.waist_girth_mm = 1200, o.middle_hip_girth_mm = 1250, o.hip_girth_mm = 1280;
  const Defined belly = Make(o);
  const double fold = belly.levels.under_bust_mm, stature = o.stature_mm;
  double lower_peak = 0;
  for (double z = fold - 6; z > BustZ(belly.body) - 0.08 * stature; z -= 1)
    lower_peak = std::max(lower_peak, Bend(belly.body, z));
  EXPECT_GT(lower_peak, Bend(belly.body, fold));  // the case this test is about
  EXPECT_NEAR(fold, plain.levels.under_bust_mm, 2.0);
}

// A small bust over a full front (full-range seed 1005): no bend of 1 mm
// 1-8 % of stature under the bust points, so the under-bust is 4 % of
// stature under them.
TEST(DefinedUnderBust, AFlatChestHasTheNoFoldLevel) {
  ParametricBodyOptions o;
  o.seed = 1005;
  const ParametricBodyOptions drawn = SeededOptions(o, "full");
  const Defined d = Make(drawn);
  const double bust = BustZ(d.body), stature = d.body.mesh.vertices.col(2).maxCoeff();
  double sharpest = -1e9;
  for (double z = bust - 0.08 * stature; z <= bust - 0.01 * stature; z += 2)
    sharpest = std::max(sharpest, Bend(d.body, z));
  ASSERT_LT(sharpest, 1.0) << "seed 1005 is no longer a flat chest";
  EXPECT_NEAR(d.levels.under_bust_mm, bust - 0.04 * stature, 0.5);
}

// The average woman's bust grown 5 mm at a time from 845 to 890 mm: its fold
// sharpens from a bend under 1 mm to over 3 mm (brute force, printed),
// and the level goes from the flat chest's to the fold's above it without a
// jump (a single threshold moves it the whole way in one step).
TEST(DefinedUnderBust, AFoldThatSharpensMovesTheLevelSmoothly) {
  double previous = -1, first_sharpest = 0, last_sharpest = 0;
  for (double girth = 845; girth <= 890; girth += 5) {
    ParametricBodyOptions o;
    o.bust_girth_mm = girth;
    const Defined d = Make(o);
    const double bust = BustZ(d.body), stature = o.stature_mm;
    double sharpest = -1e9;
    for (double z = bust - 0.08 * stature; z <= bust - 0.01 * stature; z += 2)
      sharpest = std::max(sharpest, Bend(d.body, z));
    (girth == 845 ? first_sharpest : last_sharpest) = sharpest;
    std::printf("bust girth %.0f mm: sharpest bend %.2f mm, under-bust %.1f mm\n", girth, sharpest,
                d.levels.under_bust_mm);
    if (previous > 0) {
      EXPECT_LT(std::abs(d.levels.under_bust_mm - previous), 5.0) << girth;
    }
    previous = d.levels.under_bust_mm;
  }
  EXPECT_LT(first_sharpest, 1.5);  // the family spans the change from flat to fold
  EXPECT_GT(last_sharpest, 3.0);
}

}  // namespace
}  // namespace bespoke
