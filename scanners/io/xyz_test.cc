// XYZ / CSV / TXT text: column layouts, headers, round trips, malformed files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scanners/io/scan_io.h"
#include "tests/support/io_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectScanRejected;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

Scan Read(const TempDir& dir, const std::string& name, const std::string& text) {
  WriteBytes(dir / name, text);
  return ReadScan(FixtureOptions(), dir / name);
}

TEST(XyzRead, ThreeColumnsWithCommentsAndBlankLines) {
  TempDir dir;
  const Scan scan = Read(dir, "p.xyz", "# scanner export\n\n1 2 3\n4\t5  6\r\n\n-7e1 +8 .5\n");
  ASSERT_EQ(scan.cloud.size(), 3);
  EXPECT_EQ(scan.cloud.points.row(2), Eigen::RowVector3d(-70, 8, 0.5));
  EXPECT_FALSE(scan.cloud.has_normals());
  EXPECT_EQ(scan.report.format, FileFormat::kXyz);
  EXPECT_EQ(scan.report.fields, (std::vector<std::string>{"x", "y", "z"}));
}

TEST(XyzRead, SixColumnsAreNormalsAndMoreAreScalars) {
  TempDir dir;
  const Scan six = Read(dir, "n.xyz", "1 2 3 0 0 1\n4 5 6 0 1 0\n");
  ASSERT_TRUE(six.cloud.has_normals());
  EXPECT_EQ(six.cloud.normals.row(1), Eigen::RowVector3d(0, 1, 0));
  const Scan seven = Read(dir, "s.txt", "1 2 3 0 0 1 0.25\n4 5 6 0 1 0 0.5\n");
  EXPECT_EQ(seven.cloud.scalars.at("column_7")[1], 0.5);
  const Scan four = Read(dir, "f.txt", "1;2;3;9\n4;5;6;8\n");
  EXPECT_FALSE(four.cloud.has_normals());
  EXPECT_EQ(four.cloud.scalars.at("column_4")[0], 9);
}

TEST(XyzRead, CsvHeaderNamesColumnsInAnyOrder) {
  TempDir dir;
  const Scan scan = Read(dir, "p.csv",
                         "Intensity,X,Y,Z,R,G,B\n"
                         "0.5,1,2,3,255,0,10\n"
                         "0.25,4,5,6,0,128,20\n");
  ASSERT_EQ(scan.cloud.size(), 2);
  EXPECT_EQ(scan.cloud.points.row(1), Eigen::RowVector3d(4, 5, 6));
  ASSERT_TRUE(scan.cloud.has_colors());
  EXPECT_EQ(scan.cloud.colors(1, 1), 128);
  EXPECT_EQ(scan.cloud.scalars.at("Intensity")[1], 0.25);
  EXPECT_EQ(scan.report.fields.front(), "Intensity");
  // A byte order mark (Windows exports) before the header is ignored.
  const Scan bom = Read(dir, "bom.csv", "\xEF\xBB\xBFx,y,z\n1,2,3\n");
  EXPECT_EQ(bom.cloud.points.row(0), Eigen::RowVector3d(1, 2, 3));
}

TEST(XyzRead, CloudCompareHeaderUnitColoursAndPtsCount) {
  TempDir dir;
  const Scan cc = Read(dir, "cc.txt", "//X Y Z R G B\n1 2 3 1 0.5 0\n4 5 6 0 0 1\n");
  ASSERT_TRUE(cc.cloud.has_colors());
  EXPECT_EQ(cc.cloud.colors(0, 0), 255);
  EXPECT_EQ(cc.cloud.colors(0, 1), 128);
  const Scan pts = Read(dir, "p.pts", "2\n1 2 3 10\n4 5 6 20\n");
  EXPECT_EQ(pts.cloud.size(), 2);
  EXPECT_EQ(pts.cloud.scalars.at("column_4")[1], 20);
}

TEST(XyzRead, RepeatedColumnNamesGetNumberedInLinearTime) {
  TempDir dir;
  const Scan scan = Read(dir, "d.csv", "x,y,z,a,a,a\n1,2,3,4,5,6\n");
  EXPECT_EQ(scan.cloud.scalars.at("a")[0], 4);
  EXPECT_EQ(scan.cloud.scalars.at("a_2")[0], 5);
  EXPECT_EQ(scan.cloud.scalars.at("a_3")[0], 6);
  // 100,000 columns of one name (a quadratic renaming would take minutes).
  std::string header = "x y z", values = "1 2 3";
  for (int i = 0; i < 100000; ++i) {
    header += " a";
    values += " 7";
  }
  const Scan wide = ReadScanFromBytes(FixtureOptions(), "w.xyz", header + "\n" + values + "\n");
  EXPECT_EQ(wide.cloud.scalars.size(), 100000u);
  EXPECT_EQ(wide.cloud.scalars.at("a_100000")[0], 7);
}

class XyzRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(XyzRoundTrip, EverythingSurvivesExactly) {
  TempDir dir;
  const PointCloud cloud = testing::RichCloud(30);
  WriteOptions options;
  options.comment = "units mm";
  const auto file = dir / ("c" + GetParam());
  WriteScan(options, cloud, file);
  const Scan back = ReadScan(FixtureOptions(), file);
  EXPECT_EQ(back.cloud.points, cloud.points);  // shortest round-trip text
  EXPECT_EQ(back.cloud.normals, cloud.normals);
  EXPECT_EQ(back.cloud.colors, cloud.colors);
  EXPECT_EQ(back.cloud.scalars.at("intensity"), cloud.scalars.at("intensity"));
  EXPECT_EQ(back.cloud.scalars.at("curvature"), cloud.scalars.at("curvature"));
}

INSTANTIATE_TEST_SUITE_P(Extensions, XyzRoundTrip, ::testing::Values(".xyz", ".csv", ".txt"));

TEST(XyzMalformed, Corpus) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1 2\n3 4\n", "line 1: a point needs at least 3 values"},
      {"1 2 3\n4 5 6 7\n", "line 2: expected 3 values, found 4"},
      {"1 2 3\n4 5\n", "line 2: expected 3 values, found 2"},
      {"1 2 3\n4 5 x\n", "line 2: 'x' is not a number"},
      {"a b c\n1 2 3\n", "names no x, y and z"},
      {"x y z w\n1 2 3\n", "the header names 4 columns but the first point has 3"},
      {"# only a comment\n\n", "no points"},
      {"x y z\n", "no points"},
      {"1 2 3\n\x01 \x02 \x03\n", "is not a number"},
  };
  int k = 0;
  for (const auto& [text, fragment] : cases) {
    SCOPED_TRACE(fragment);
    ExpectScanRejected(dir / ("bad" + std::to_string(k++) + ".xyz"), text, fragment);
  }
  ReadOptions options = FixtureOptions();
  options.max_elements = 2;
  ExpectScanRejected(dir / "many.xyz", "1 2 3\n4 5 6\n7 8 9\n", "more than the limit", options);
}

}  // namespace
}  // namespace bespoke
