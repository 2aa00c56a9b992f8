#include "resize/ga/operators.h"

#include <gtest/gtest.h>

#include "resize/designs/designs.h"
#include "resize/ga/block.h"
#include "resize/ga/grading.h"
#include "resize/pattern/geometry.h"

namespace bespoke {
namespace {

TEST(Blocks, BaseGridReproducesEveryPieceAndHitsCriticalPoints) {
  const Pattern p = DraftDesign("trousers", BaseMeasurements("trousers"));
  const BlockSet blocks = BuildBlocks(BlockOptions{}, p);
  const Pattern q = ApplyGenes(p, blocks, blocks.base_genes);
  for (size_t k = 0; k < p.pieces.size(); ++k) {
    EXPECT_LT((p.pieces[k].outline - q.pieces[k].outline).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_TRUE(BlockValid(blocks.blocks[k], blocks.base_genes.data(), 0.1));
  }
  // A critical point sits on a grid node: moving that node moves it 1:1.
  const Block& front = blocks.blocks[0];
  const GridParam& g = front.outline[p.pieces[0].critical[0]];
  EXPECT_TRUE((g.s == 0 || g.s == 1) && (g.t == 0 || g.t == 1));
}

TEST(Blocks, ScalingTheGridScalesThePiece) {
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  const BlockSet blocks = BuildBlocks(BlockOptions{}, p);
  // The base grid gives the piece back up to the runs kept straight (the
  // straight edges InferStructure finds within its tolerance and chains of
  // collinear points, put back on their chord); a scaled grid scales that
  // reconstruction exactly.
  const Pattern q0 = ApplyGenes(p, blocks, blocks.base_genes);
  const Pattern q = ApplyGenes(p, blocks, 1.2 * blocks.base_genes);
  for (size_t k = 0; k < p.pieces.size(); ++k) {
    EXPECT_LT((p.pieces[k].outline - q0.pieces[k].outline).cwiseAbs().maxCoeff(), 0.1);
    EXPECT_NEAR(Perimeter(q.pieces[k].outline), 1.2 * Perimeter(q0.pieces[k].outline), 1e-6);
  }
}

TEST(Operators, MutationAndCrossoverKeepGridsOrdered) {
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  const BlockSet blocks = BuildBlocks(BlockOptions{}, p);
  Rng rng(7);
  MutationParams params;
  params.max_generations = 10;
  params.range_fraction = 0.3;  // large moves: many draws must be redrawn
  Eigen::VectorXd a = blocks.base_genes, b = blocks.base_genes;
  for (int round = 0; round < 50; ++round) {
    params.generation = round % 10;
    NonUniformMutation(blocks, params, rng, &a);
    NonUniformMutation(blocks, params, rng, &b);
    UniformCrossover(blocks, params.min_gap_mm, rng, &a, &b);
    for (const Block& block : blocks.blocks) {
      ASSERT_TRUE(BlockValid(block, a.data(), params.min_gap_mm));
      ASSERT_TRUE(BlockValid(block, b.data(), params.min_gap_mm));
    }
  }
  EXPECT_GT((a - blocks.base_genes).cwiseAbs().maxCoeff(), 1.0);  // it did move
}

TEST(Operators, NonUniformMutationShrinksWithGenerations) {
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  const BlockSet blocks = BuildBlocks(BlockOptions{}, p);
  auto mean_move = [&](int generation) {
    Rng rng(3);
    MutationParams params;
    params.generation = generation;
    params.max_generations = 100;
    double total = 0;
    for (int i = 0; i < 200; ++i) {
      Eigen::VectorXd g = blocks.base_genes;
      NonUniformMutation(blocks, params, rng, &g);
      total += (g - blocks.base_genes).cwiseAbs().sum();
    }
    return total;
  };
  EXPECT_GT(mean_move(0), 3 * mean_move(90));
  EXPECT_EQ(mean_move(100), 0.0);  // Delta(Gen_max, t) = 0
}

TEST(Operators, LifeSpanIsBilinear) {
  // Eq 4.2 with life 2..10 (eta 4), costs 0..4, expected cost 1.
  EXPECT_DOUBLE_EQ(LifeSpan(4, 0, 4, 1, 2, 10), 2);   // worst: shortest life
  EXPECT_DOUBLE_EQ(LifeSpan(1, 0, 4, 1, 2, 10), 6);   // at the expected cost
  EXPECT_DOUBLE_EQ(LifeSpan(0, 0, 4, 1, 2, 10), 10);  // best: longest life
  EXPECT_DOUBLE_EQ(LifeSpan(2.5, 0, 4, 1, 2, 10), 4);
}

TEST(Grading, Algorithm6TakesTheLargestRatioPerPiece) {
  const Pattern p = DraftDesign("shirt", BaseMeasurements("shirt"));
  MeasurementSet body = BaseMeasurements("shirt");
  body["chest_girth"] = 1100;  // chest target +100 mm on 1240 mm of pattern
  const std::vector<double> s = ProportionalScales(p, body);
  EXPECT_NEAR(s[0], 1340.0 / 1240.0, 1e-9);    // back: chest is its largest ratio
  EXPECT_NEAR(s[2], 1.0, 1e-9);                // sleeve: arm length unchanged
  EXPECT_NEAR(s[4], (s[0] + s[1]) / 2, 1e-9);  // collar: mean of back and front (its seams)
}

TEST(Geometry, SelfIntersectionOffsetAndComparison) {
  Outline bow(4, 2);
  bow << 0, 0, 10, 10, 10, 0, 0, 10;
  EXPECT_GE(FindSelfIntersection(bow).first, 0);
  Outline square(4, 2);
  square << 0, 0, 10, 0, 10, 10, 0, 10;
  EXPECT_EQ(FindSelfIntersection(square).first, -1);
  EXPECT_NEAR(SignedArea(square), 100, 1e-12);
  EXPECT_NEAR(Perimeter(OffsetOutline(square, 1)), 48, 1e-9);
  EXPECT_NEAR(OutlineDistance(square, 3, 1), 20, 1e-12);  // wraps 3 -> 0 -> 1
  EXPECT_NEAR(CompareOutlines(square, OffsetOutline(square, 1)).max_mm, std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace bespoke
