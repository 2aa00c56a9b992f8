// `bespoke info` as a user runs it: a separate process on files on disk.
// Every file of the malformed corpus (tests/support/malformed_corpus.h), a
// folder and a missing file must give exit code 1 with the file named on
// stderr; a valid scan gives exit 0 with its facts on stdout (text and JSON).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "scanners/io/scan_io.h"
#include "tests/support/malformed_corpus.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using testing::TempDir;

using ProcessResult = testing::CommandResult;

// Runs `bespoke info <args>` with stdout and stderr captured.
ProcessResult Info(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' info " + args, dir.path());
}

std::string Quoted(const std::filesystem::path& file) { return testing::Quote(file); }

void WriteFile(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

TEST(InfoCli, MalformedCorpusExitsOneNamingTheFile) {
  TempDir dir;
  std::filesystem::create_directory(dir / "scans");
  for (const auto& bad : testing::MalformedCorpus()) {
    SCOPED_TRACE(bad.name);
    const auto file = dir / "scans" / bad.name;
    WriteFile(file, bad.bytes);
    const ProcessResult run = Info(dir, Quoted(file));
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_THAT(run.err, ::testing::HasSubstr(file.string() + ": "));
    EXPECT_THAT(run.err, ::testing::HasSubstr(bad.fragment));
  }
  std::filesystem::create_directory(dir / "scans" / "folder.ply");
  const ProcessResult folder = Info(dir, Quoted(dir / "scans" / "folder.ply"));
  EXPECT_EQ(folder.exit_code, 1);
  EXPECT_THAT(folder.err, ::testing::HasSubstr("folder.ply: is a folder"));
  const ProcessResult missing = Info(dir, Quoted(dir / "scans" / "missing.pcd"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, ::testing::HasSubstr("missing.pcd: file not found"));
  const ProcessResult bad_units = Info(dir, Quoted(dir / "scans" / "empty.ply") + " --units inch");
  EXPECT_EQ(bad_units.exit_code, 1);
}

// A 1.8 m tall "person" (a helix of 2000 points) in metres, with NaN holes.
PointCloud Helix() {
  PointCloud cloud;
  cloud.points.resize(2000, 3);
  for (int i = 0; i < 2000; ++i) {
    const double t = i / 1999.0;
    cloud.points.row(i) << 0.2 * std::cos(40 * t), 0.15 * std::sin(40 * t), 1.8 * t;
  }
  cloud.points(7, 0) = std::numeric_limits<double>::quiet_NaN();
  return cloud;
}

TEST(InfoCli, ValidScanTextAndJson) {
  TempDir dir;
  WriteOptions options;
  options.pcd_encoding = PcdEncoding::kBinaryCompressed;
  WriteScan(options, Helix(), dir / "helix.pcd");
  const ProcessResult text = Info(dir, Quoted(dir / "helix.pcd"));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, ::testing::HasSubstr("format:    PCD (binary_compressed)"));
  EXPECT_THAT(text.out, ::testing::HasSubstr("1999 kept of 2000 in the file (1 NaN/Inf dropped)"));
  EXPECT_THAT(text.out, ::testing::HasSubstr("unit:      m (guessed"));
  const ProcessResult json = Info(dir, "--json --units m " + Quoted(dir / "helix.pcd"));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["format"], "PCD");
  EXPECT_EQ(j["points"], 1999);
  EXPECT_EQ(j["non_finite_dropped"], 1);
  EXPECT_EQ(j["file_unit"], "m");
  EXPECT_EQ(j["unit_guessed"], false);
  EXPECT_NEAR(j["size_mm"][2].get<double>(), 1800.0, 1e-3);  // float storage: < 1 um
  EXPECT_EQ(j["fields"], nlohmann::json::array({"x", "y", "z"}));
}

}  // namespace
}  // namespace bespoke
