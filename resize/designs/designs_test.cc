#include "resize/designs/designs.h"

#include <gtest/gtest.h>

#include "resize/io/pattern_svg.h"
#include "resize/pattern/geometry.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

TEST(Designs, DraftsMeetTheirOwnBindingsAndSeams) {
  for (const std::string& design : DesignNames()) {
    const MeasurementSet base = BaseMeasurements(design);
    const Pattern p = DraftDesign(design, base);
    for (const MeasurementBinding& b : p.bindings)
      EXPECT_NEAR(BindingValue(p, b), BindingTarget(b, base), 1e-9) << b.id;
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

TEST(Designs, TrouserRiseBindingFollowsTheDraftForOtherBodies) {
  // The rise binding measures the crotch depth the draft sets from body_rise
  // (= waist_height - inside_leg): a draft for another body meets it with the
  // base draft's ease to within 0.2 mm (its two terms are 10 and 2 mm off
  // the vertical).
  const Pattern base = DraftDesign("trousers", BaseMeasurements("trousers"));
  int count = 0;
  for (size_t rise = 0; rise < base.bindings.size(); ++rise) {
    if (base.bindings[rise].measurement != "body_rise") continue;
    ++count;
    for (double extra : {-40.0, 60.0}) {
      MeasurementSet m = BaseMeasurements("trousers");
      m.erase("body_rise");
      m["waist_height"] += extra;  // same leg, longer or shorter rise
      m["waist_girth"] *= 1.2;
      m["hip_girth"] *= 0.9;
      const Pattern p = DraftDesign("trousers", m);
      EXPECT_NEAR(BindingValue(p, base.bindings[rise]),
                  m.at("waist_height") - m.at("inside_leg") + base.bindings[rise].ease_mm, 0.2)
          << base.bindings[rise].id << " " << extra;
      EXPECT_NEAR(BindingValue(p, base.bindings[rise]) - BindingValue(base, base.bindings[rise]),
                  extra, 0.2)
          << base.bindings[rise].id << " " << extra;
    }
  }
  EXPECT_EQ(count, 5);  // rise, back_rise, rise_cf, front and back seat lines
}

TEST(Designs, DraftingRejectsABodyRiseThatIsNotWaistHeightMinusInsideLeg) {
  MeasurementSet m = BaseMeasurements("trousers");
  m["body_rise"] += 30;
  EXPECT_THROW(DraftDesign("trousers", m), InputError);
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
