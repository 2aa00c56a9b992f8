// PCD: hand-built fixtures (organised clouds with NaNs, packed rgb as float
// and uint, every field type, skipped fields, a literal-only LZF block),
// round trips of every encoding, and the malformed-file corpus.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "scanners/io/scan_io.h"
#include "tests/support/io_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::ExpectInputError;
using testing::ExpectScanRejected;
using testing::FixtureOptions;
using testing::TempDir;
using testing::WriteBytes;

template <typename T>
void Put(std::string* out, T value) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  out->append(b, sizeof(T));
}

float Bits(std::uint32_t packed) {
  float f;
  std::memcpy(&f, &packed, 4);
  return f;
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();

// An organised 3 x 2 cloud as PCL writes PointXYZRGBNormal-like data, plus a
// uint8 label, an int16, a double, a 3-value histogram and '_' padding.
std::string Header(const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\n"
         "VERSION 0.7\n"
         "FIELDS x y z rgb _ normal_x normal_y normal_z label temp hist weight\n"
         "SIZE 4 4 4 4 4 4 4 4 1 2 4 8\n"
         "TYPE F F F F U F F F U I F F\n"
         "COUNT 1 1 1 1 1 1 1 1 1 1 3 1\n"
         "WIDTH 3\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA " +
         data + "\n";
}

// The values of point i, in field order (NaN position for points 1 and 4).
void AppendPoint(std::string* s, int i) {
  const bool hole = i == 1 || i == 4;
  Put<float>(s, hole ? kNaN : 0.25f * i);
  Put<float>(s, hole ? kNaN : -1.5f * i);
  Put<float>(s, hole ? kNaN : 1000.0f + i);
  Put<float>(s, Bits((10u * i << 16) | (20u * i << 8) | (30u * i)));
  Put<std::uint32_t>(s, 0xdeadbeef);  // padding
  Put<float>(s, 0.0f);
  Put<float>(s, 0.6f);
  Put<float>(s, 0.8f);
  Put<std::uint8_t>(s, static_cast<std::uint8_t>(200 + i));
  Put<std::int16_t>(s, static_cast<std::int16_t>(-300 * i));
  for (int k = 0; k < 3; ++k) Put<float>(s, 7.0f);
  Put<double>(s, 1.0 / 3.0 + i);
}

constexpr int kPointBytes = 4 * 8 + 1 + 2 + 12 + 8;

std::string BinaryPcd() {
  std::string s = Header("binary");
  for (int i = 0; i < 6; ++i) AppendPoint(&s, i);
  return s;
}

// binary_compressed: the points' bytes regrouped field by field, stored as
// an LZF stream of literal runs only (control byte n-1, then n <= 32 bytes).
std::string CompressedPcd() {
  std::string aos;
  for (int i = 0; i < 6; ++i) AppendPoint(&aos, i);
  const int sizes[] = {4, 4, 4, 4, 4, 4, 4, 4, 1, 2, 12, 8};
  std::string soa;
  int offset = 0;
  for (const int size : sizes) {
    for (int i = 0; i < 6; ++i) soa += aos.substr(i * kPointBytes + offset, size);
    offset += size;
  }
  std::string lzf;
  for (std::size_t p = 0; p < soa.size(); p += 32) {
    const std::size_t n = std::min<std::size_t>(32, soa.size() - p);
    lzf += static_cast<char>(n - 1);
    lzf += soa.substr(p, n);
  }
  std::string s = Header("binary_compressed");
  Put<std::uint32_t>(&s, static_cast<std::uint32_t>(lzf.size()));
  Put<std::uint32_t>(&s, static_cast<std::uint32_t>(soa.size()));
  return s + lzf;
}

void ExpectFixtureContent(const Scan& scan) {
  EXPECT_EQ(scan.report.points_in_file, 6);
  EXPECT_EQ(scan.report.non_finite_dropped, 2);
  const PointCloud& c = scan.cloud;
  ASSERT_EQ(c.size(), 4);
  ASSERT_TRUE(c.has_colors());
  ASSERT_TRUE(c.has_normals());
  const int kept[] = {0, 2, 3, 5};
  for (int k = 0; k < 4; ++k) {
    const int i = kept[k];
    EXPECT_EQ(c.points.row(k), Eigen::RowVector3d(0.25 * i, -1.5 * i, 1000.0 + i));
    EXPECT_EQ(c.colors(k, 0), 10 * i);
    EXPECT_EQ(c.colors(k, 1), 20 * i);
    EXPECT_EQ(c.colors(k, 2), 30 * i);
    EXPECT_EQ(c.normals.row(k), Eigen::RowVector3d(0.0, 0.6f, 0.8f));
    EXPECT_EQ(c.scalars.at("label")[k], 200 + i);
    EXPECT_EQ(c.scalars.at("temp")[k], -300 * i);
    EXPECT_EQ(c.scalars.at("weight")[k], 1.0 / 3.0 + i);
  }
  EXPECT_EQ(c.scalars.count("hist"), 0u);  // 3 values per point: skipped
  EXPECT_EQ(c.scalars.count("_"), 0u);
  EXPECT_THAT(scan.report.warnings, ::testing::Contains(::testing::HasSubstr("'hist'")));
  EXPECT_EQ(scan.report.fields.size(), 11u);  // without '_'
}

TEST(PcdRead, BinaryOrganisedCloudWithHoles) {
  TempDir dir;
  WriteBytes(dir / "b.pcd", BinaryPcd());
  const Scan scan = ReadScan(FixtureOptions(), dir / "b.pcd");
  EXPECT_EQ(scan.report.encoding, "binary");
  EXPECT_EQ(scan.report.format, FileFormat::kPcd);
  ExpectFixtureContent(scan);
}

TEST(PcdRead, BinaryCompressed) {
  TempDir dir;
  WriteBytes(dir / "c.pcd", CompressedPcd());
  const Scan scan = ReadScan(FixtureOptions(), dir / "c.pcd");
  EXPECT_EQ(scan.report.encoding, "binary_compressed");
  ExpectFixtureContent(scan);
}

TEST(PcdRead, AsciiWithPackedRgbAsIntegerAndAsFloat) {
  TempDir dir;
  const std::uint32_t packed = (12u << 16) | (34u << 8) | 56u;
  std::string float_text;
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", Bits(packed));  // float rgb, as old PCL wrote
  const std::string text =
      "VERSION .7\nFIELDS x y z rgb intensity\nSIZE 4 4 4 4 4\nTYPE F F F F F\nCOUNT 1 1 1 1 1\n"
      "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n"
      "1 2 3 " +
      std::to_string(packed) +
      " 0.5\n"
      "nan nan nan 0 0\n"
      "4 5 6 " +
      std::string(buffer) + " 1e-2\n";
  WriteBytes(dir / "a.pcd", text);
  const Scan scan = ReadScan(FixtureOptions(), dir / "a.pcd");
  ASSERT_EQ(scan.cloud.size(), 2);
  EXPECT_EQ(scan.report.non_finite_dropped, 1);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(scan.cloud.colors(k, 0), 12);
    EXPECT_EQ(scan.cloud.colors(k, 1), 34);
    EXPECT_EQ(scan.cloud.colors(k, 2), 56);
  }
  EXPECT_EQ(scan.cloud.scalars.at("intensity")[1], static_cast<double>(1e-2f));
}

class PcdRoundTrip : public ::testing::TestWithParam<PcdEncoding> {};

TEST_P(PcdRoundTrip, FloatFieldsSurviveExactly) {
  TempDir dir;
  const PointCloud cloud = testing::RichCloud(40);
  WriteOptions options;
  options.pcd_encoding = GetParam();
  options.comment = "units mm";
  WriteScan(options, cloud, dir / "c.pcd");
  const Scan back = ReadScan(FixtureOptions(), dir / "c.pcd");
  // PCD stores 4-byte floats (PCL's layout): exact to float precision.
  EXPECT_EQ(back.cloud.points, cloud.points.cast<float>().cast<double>());
  EXPECT_EQ(back.cloud.normals, cloud.normals.cast<float>().cast<double>());
  EXPECT_EQ(back.cloud.colors, cloud.colors);
  EXPECT_EQ(back.cloud.scalars.at("intensity"),
            cloud.scalars.at("intensity").cast<float>().cast<double>());
  EXPECT_EQ(back.cloud.scalars.size(), 2u);
}

TEST_P(PcdRoundTrip, EmptyCloud) {
  TempDir dir;
  WriteOptions options;
  options.pcd_encoding = GetParam();
  WriteScan(options, PointCloud(), dir / "e.pcd");
  EXPECT_EQ(ReadScan(FixtureOptions(), dir / "e.pcd").cloud.size(), 0);
}

INSTANTIATE_TEST_SUITE_P(Encodings, PcdRoundTrip,
                         ::testing::Values(PcdEncoding::kAscii, PcdEncoding::kBinary,
                                           PcdEncoding::kBinaryCompressed));

TEST(PcdMalformed, EveryTruncationOfBinaryAndCompressedFiles) {
  const std::filesystem::path file = "t.pcd";
  for (const std::string& full : {BinaryPcd(), CompressedPcd()}) {
    for (std::size_t n = 0; n < full.size(); ++n) {
      SCOPED_TRACE("truncated at byte " + std::to_string(n));
      ExpectInputError([&] { ReadScanFromBytes(FixtureOptions(), file, full.substr(0, n)); }, file);
    }
  }
}

std::string Pcd(const std::string& fields, const std::string& rest) {
  return "VERSION 0.7\n" + fields + rest;
}
const std::string kXyzFields = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

TEST(PcdMalformed, HeaderAndDataCorpus) {
  TempDir dir;
  const std::string one = "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n";
  std::string lzf_header = Pcd(kXyzFields, "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary_compressed\n");
  auto compressed = [&](std::uint32_t packed, std::uint32_t unpacked, const std::string& body) {
    std::string s = lzf_header;
    Put<std::uint32_t>(&s, packed);
    Put<std::uint32_t>(&s, unpacked);
    return s + body;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"VERSION 0.7\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n", "no FIELDS line"},
      {Pcd(kXyzFields, "WIDTH 1\nPOINTS 1\n"), "no DATA line"},
      {Pcd(kXyzFields, "HEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n"), "no WIDTH line"},
      {Pcd("FIELDS x y z\nSIZE 4 4\nTYPE F F F\n", one), "SIZE has 2"},
      {Pcd("FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\n", one), "SIZE '3' is not 1, 2, 4 or 8"},
      {Pcd("FIELDS x y z\nSIZE 4 4 4\nTYPE F F X\n", one), "TYPE 'X'"},
      {Pcd("FIELDS x y z\nSIZE 4 4 2\nTYPE F F F\n", one), "is not F (4/8)"},
      {Pcd("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 0\n", one), "COUNT '0'"},
      {Pcd("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 -5\n", one), "COUNT '-5'"},
      {Pcd("FIELDS x y q\nSIZE 4 4 4\nTYPE F F F\n", one), "x, y and z"},
      {Pcd("FIELDS x y z x\nSIZE 4 4 4 4\nTYPE F F F F\n", one), "appears twice"},
      {Pcd("FIELDS x y z h\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 9000000\n", one),
       "more than 1048576 bytes"},
      {Pcd(kXyzFields, "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n"), "is not WIDTH * HEIGHT"},
      {Pcd(kXyzFields, "WIDTH -1\nHEIGHT 1\nDATA ascii\n"), "is negative"},
      {Pcd(kXyzFields, "WIDTH 9999999999\nHEIGHT 1\nDATA ascii\n"), "more than the limit"},
      {Pcd(kXyzFields, "WIDTH 40000\nHEIGHT 40000\nDATA ascii\n"), "more than the limit"},
      {Pcd(kXyzFields, "WIDTH 1\nWIDTH 1\nDATA ascii\n"), "a second WIDTH"},
      {Pcd(kXyzFields, "WIDTH 1\nVIEWPOINT 0 0 0 1 0 0\nDATA ascii\n"), "VIEWPOINT needs 7"},
      {Pcd(kXyzFields, "WIDTH 1\nDATA gzip\n"), "unknown PCD DATA encoding"},
      {Pcd(kXyzFields, "WIDTH 1\nCOLOUR blue\nDATA ascii\n"), "unknown PCD header keyword"},
      {Pcd(kXyzFields, "WIDTH 10000000\nDATA binary\n\x01\x02\x03"), "only 3 follow"},
      {Pcd(kXyzFields, "WIDTH 1000000\nDATA ascii\n1 2 3\n"), "cannot fit"},
      {Pcd(kXyzFields, "WIDTH 2\nDATA ascii\n1 2 3\n4 5 6 7\n"), "line 9: expected 3 values"},
      {Pcd(kXyzFields, "WIDTH 2\nDATA ascii\n1 2 3\n4 5 six\n"), "'six' is not a number"},
      {Pcd(kXyzFields, "WIDTH 1\nDATA ascii\n1 2 3\n4 5 6\n"), "data after the last point"},
      {Pcd(kXyzFields, "WIDTH 3\nDATA ascii\n1 2 3\n4 5 6\n       \n"), "truncated"},
      {lzf_header + "\x01\x02", "sizes are missing"},
      {compressed(13, 13, std::string(13, '\x0c')), "unpacks to 13 bytes but 1 points"},
      {compressed(100, 12, std::string(13, '\x0b')), "claims 100 bytes but only 13"},
      {compressed(0, 12, ""), "cannot unpack"},
      // A back reference before the start of the output: corrupt LZF.
      {compressed(3, 12, "\xe0\x05\x01"), "LZF-compressed data is corrupt"},
      // A literal run that stops short of the declared size.
      {compressed(5, 12, std::string("\x03\x01\x02\x03\x04", 5)), "LZF-compressed data is corrupt"},
  };
  int k = 0;
  for (const auto& [bytes, fragment] : cases) {
    SCOPED_TRACE(fragment);
    ExpectScanRejected(dir / ("bad" + std::to_string(k++) + ".pcd"), bytes, fragment);
  }
  // Huge claims are rejected before allocating: 50 million points of 1 MB.
  ReadOptions options = FixtureOptions();
  ExpectScanRejected(dir / "huge.pcd",
                     Pcd("FIELDS x y z h\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 1000000\n",
                         "WIDTH 50000000\nDATA binary_compressed\n") +
                         std::string("\x10\x00\x00\x00\x00\x00\x00\x00", 8),
                     "unpacks to 0 bytes", options);
}

// 200,000 fields: the duplicate-name check is linear, not quadratic.
TEST(PcdMalformed, HugeHeadersParseInLinearTime) {
  std::string fields = "FIELDS x y z", sizes = "SIZE 4 4 4", types = "TYPE F F F";
  for (int i = 0; i < 200000; ++i) {
    fields += " f" + std::to_string(i);
    sizes += " 1";
    types += " U";
  }
  const std::string pcd =
      "VERSION 0.7\n" + fields + "\n" + sizes + "\n" + types + "\nWIDTH 0\nDATA binary\n";
  EXPECT_EQ(ReadScanFromBytes(FixtureOptions(), "h.pcd", pcd).report.fields.size(), 200003u);
}

TEST(PcdMalformed, NaNOnlyOrganisedCloud) {
  TempDir dir;
  std::string s = Pcd(kXyzFields, "WIDTH 2\nHEIGHT 2\nPOINTS 4\nDATA binary\n");
  for (int i = 0; i < 12; ++i) Put<float>(&s, kNaN);
  ReadOptions options = FixtureOptions();
  options.min_finite_points = 1;
  ExpectScanRejected(dir / "nan.pcd", s, "only 0 finite points (4 NaN/Inf points dropped)",
                     options);
}

}  // namespace
}  // namespace bespoke
