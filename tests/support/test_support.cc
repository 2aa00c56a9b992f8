#include "tests/support/test_support.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <random>

namespace bespoke::testing {

std::optional<std::filesystem::path> SharedDir() {
  std::filesystem::path dir;
  if (const char* env = std::getenv("BESPOKE_SHARED_DIR"); env && *env) {
    dir = env;
  } else {
    dir = BESPOKE_DEFAULT_SHARED_DIR;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(dir / "data", ec)) return std::nullopt;
  return std::filesystem::weakly_canonical(dir, ec);
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  std::random_device rd;
  path_ = std::filesystem::temp_directory_path() /
          ("bespoke-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" +
           std::to_string(rd()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace bespoke::testing
