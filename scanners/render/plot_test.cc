#include "scanners/render/plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(NiceTicks, UsesOneTwoFiveSteps) {
  const auto ticks = NiceTicks(0.0, 10.0, 5);
  ASSERT_EQ(ticks.size(), 6u);  // 0 2 4 6 8 10
  EXPECT_DOUBLE_EQ(ticks.front(), 0.0);
  EXPECT_DOUBLE_EQ(ticks[1], 2.0);
  EXPECT_DOUBLE_EQ(ticks.back(), 10.0);
  const auto small = NiceTicks(-0.013, 0.021, 4);
  for (double t : small) EXPECT_NEAR(std::remainder(t, 0.01), 0.0, 1e-12) << t;
  EXPECT_TRUE(NiceTicks(1.0, 1.0, 5).empty());
}

TEST(Histogram, CountsEveryValueInItsBin) {
  const Series s = HistogramSeries({0.0, 0.1, 0.9, 1.0, 2.0, 2.5, 3.0}, 3, "h", 0.0, 3.0);
  ASSERT_EQ(s.y.size(), 3u);
  // Bins [0,1), [1,2), [2,3]; the top edge belongs to the last bin.
  EXPECT_DOUBLE_EQ(s.y[0], 3.0);  // 0, 0.1, 0.9
  EXPECT_DOUBLE_EQ(s.y[1], 1.0);  // 1.0
  EXPECT_DOUBLE_EQ(s.y[2], 3.0);  // 2.0, 2.5, 3.0
  EXPECT_DOUBLE_EQ(s.x[0], 0.5);
}

TEST(WriteChart, WritesPngAndSvg) {
  testing::TempDir dir;
  Chart chart;
  chart.title = "time per vertex";
  chart.x_label = "vertices";
  chart.y_label = "time (us)";
  chart.log_x = true;
  chart.series.push_back({"ours", {1e4, 1e5, 1e6}, {2.0, 2.1, 2.2}, Series::Style::kLinePoints});
  chart.series.push_back(
      {"", {1e4, 1e6}, {3.0, 3.0}, Series::Style::kLine, {0.5, 0.5, 0.5}, 0, true});
  WriteChart(chart, dir / "c.png");
  WriteChart(chart, dir / "c.svg");
  const std::string png = Slurp(dir / "c.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_NE(Slurp(dir / "c.svg").find("<svg"), std::string::npos);
}

TEST(WriteChart, RejectsBadInput) {
  testing::TempDir dir;
  Chart chart;
  chart.series.push_back({"bad", {1, 2}, {1}});
  EXPECT_THROW(WriteChart(chart, dir / "c.png"), InputError);
  chart.series.clear();
  EXPECT_THROW(WriteChart(chart, dir / "c.jpg"), InputError);
}

}  // namespace
}  // namespace bespoke
