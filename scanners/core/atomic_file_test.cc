#include "scanners/core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

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

size_t CountEntries(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, CommitReplacesTargetCompletely) {
  testing::TempDir dir;
  const auto target = dir / "out.txt";
  WriteFileAtomically(target, "old content that is longer");
  WriteFileAtomically(target, "new");
  EXPECT_EQ(Slurp(target), "new");
  EXPECT_EQ(CountEntries(dir.path()), 1u);  // no temporary file left behind
}

TEST(AtomicFile, ThrowBeforeCommitLeavesTargetUntouched) {
  testing::TempDir dir;
  const auto target = dir / "out.txt";
  WriteFileAtomically(target, "precious");
  try {
    AtomicFile file(target);
    file.stream() << "half-writ";
    throw std::runtime_error("simulated failure mid-write");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(Slurp(target), "precious");
  EXPECT_EQ(CountEntries(dir.path()), 1u);
}

TEST(AtomicFile, MissingFolderIsAnInputErrorNamingTheFile) {
  testing::TempDir dir;
  const auto target = dir / "no-such-folder" / "out.txt";
  try {
    AtomicFile file(target);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("out.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bespoke
