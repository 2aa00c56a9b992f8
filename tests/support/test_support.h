// Helpers shared by every test binary.
//
// SharedDir(): the ../shared folder beside the checkout (thesis, MakeHuman
// body, meshes, patterns), taken from $BESPOKE_SHARED_DIR or the path CMake
// was configured with; nullopt when absent. Tests that need it use
//   BESPOKE_REQUIRE_SHARED(dir);   // skips with a clear message when absent
// TempDir: a fresh folder under the system temp dir, removed at scope exit.
#ifndef BESPOKE_TESTS_SUPPORT_TEST_SUPPORT_H_
#define BESPOKE_TESTS_SUPPORT_TEST_SUPPORT_H_

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

namespace bespoke::testing {

std::optional<std::filesystem::path> SharedDir();

class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace bespoke::testing

#define BESPOKE_REQUIRE_SHARED(dir_var)                                              \
  const auto dir_var##_optional = ::bespoke::testing::SharedDir();                   \
  if (!dir_var##_optional)                                                           \
    GTEST_SKIP() << "needs ../shared (set BESPOKE_SHARED_DIR); not found, skipping"; \
  const std::filesystem::path dir_var = *dir_var##_optional

#endif  // BESPOKE_TESTS_SUPPORT_TEST_SUPPORT_H_
