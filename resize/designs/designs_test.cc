#include "resize/designs/designs.h"

#include <gtest/gtest.h>

#include "resize/io/pattern_svg.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

TEST(Designs, DraftsMeetTheirOwnBindingsAndSeams) {
  for (const std::string& design : DesignNames()) {
    const MeasurementSet base = BaseMeasurements(design);
    const Pattern p = DraftDesign(design, base);
    for (const MeasurementBinding& b : p.bindings)
      EXPECT_NEAR(BindingValue(p, b), base.at(b.measurement) + b.ease_mm, 1e-9) << b.id;
    for (const Piece& piece : p.pieces) {
      EXPECT_GT(SignedArea(piece.outline), 0) << piece.name;
      EXPECT_EQ(FindSelfIntersection(piece.outline).first, -1) << piece.name;
    }
  }
}

TEST(Designs, VertexCountsDoNotDependOnMeasurements) {
  for (const std::string& design : DesignNames()) {
    MeasurementSet big = BaseMeasurements(design);
    for (auto& [name, value] : big) value *= 1.3;
    const Pattern a = DraftDesign(design, BaseMeasurements(design));
    const Pattern b = DraftDesign(design, big);
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (size_t i = 0; i < a.pieces.size(); ++i)
      EXPECT_EQ(a.pieces[i].num_vertices(), b.pieces[i].num_vertices()) << a.pieces[i].name;
  }
}

TEST(Designs, ShirtChestFollowsAldrich) {
  // Aldrich: 1-4 = half chest + 12 cm, so the drafted chest line (back + front,
  // times two) is the chest girth + 24 cm: the binding's ease must be 240 mm.
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  for (const MeasurementBinding& b : p.bindings)
    if (b.id == "chest") {
      EXPECT_NEAR(b.ease_mm, 240, 1e-9);
    }
}

TEST(Designs, UnknownDesignAndMissingMeasurementAreInputErrors) {
  EXPECT_THROW(DraftDesign("kilt", {}), InputError);
  MeasurementSet m = BaseMeasurements("shirt");
  m.erase("neck_girth");
  EXPECT_THROW(DraftDesign("shirt", m), InputError);
}

}  // namespace
}  // namespace bespoke
