// Test-only helpers for scanners/io tests: writing fixture bytes to files,
// asserting that a read fails with an InputError naming the file, and small
// clouds with every attribute set.
#ifndef BESPOKE_TESTS_SUPPORT_IO_TEST_UTIL_H_
#define BESPOKE_TESTS_SUPPORT_IO_TEST_UTIL_H_

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke::testing {

inline void WriteBytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << file;
}

inline std::string ReadBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Options for small fixtures: no minimum point count, millimetres.
inline ReadOptions FixtureOptions() {
  ReadOptions options;
  options.min_finite_points = 0;
  options.units = LengthUnit::kMillimetre;
  return options;
}

// Runs `read` and expects an InputError whose message names `file` and
// contains `fragment` (when given). Any other exception fails the test.
template <typename F>
void ExpectInputError(F&& read, const std::filesystem::path& file,
                      const std::string& fragment = "") {
  try {
    read();
    ADD_FAILURE() << "expected InputError for " << file << " (" << fragment << ")";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(file.string()));
    if (!fragment.empty()) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment));
    }
  }
}

// Writes `bytes` to `file` and expects ReadScan to fail naming it.
inline void ExpectScanRejected(const std::filesystem::path& file, const std::string& bytes,
                               const std::string& fragment = "",
                               const ReadOptions& options = FixtureOptions()) {
  WriteBytes(file, bytes);
  ExpectInputError([&] { ReadScan(options, file); }, file, fragment);
}

// A cloud of `n` points with normals, colours and two scalars, values chosen
// so that none is a short decimal (exercises exact round trips).
inline PointCloud RichCloud(int n) {
  PointCloud cloud;
  cloud.points.resize(n, 3);
  cloud.normals.resize(n, 3);
  cloud.colors.resize(n, 3);
  Eigen::VectorXd intensity(n), curvature(n);
  for (int i = 0; i < n; ++i) {
    cloud.points.row(i) << 100.0 / 3.0 + i, -1234.5678901234 * (i + 1) / 7.0, 1e-3 * i + 0.1;
    Eigen::Vector3d normal(1.0 + i, 2.0 - i, 0.5);
    cloud.normals.row(i) = normal.normalized();
    cloud.colors.row(i) << static_cast<std::uint8_t>(i * 37 % 256),
        static_cast<std::uint8_t>(255 - i), static_cast<std::uint8_t>(i % 7);
    intensity[i] = 0.1 * i + 1.0 / 9.0;
    curvature[i] = -2.0 / (i + 3.0);
  }
  cloud.scalars["intensity"] = intensity;
  cloud.scalars["curvature"] = curvature;
  return cloud;
}

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_IO_TEST_UTIL_H_
