#include "scanners/core/build_info.h"

#include <gtest/gtest.h>

namespace bespoke {
namespace {

TEST(BuildInfo, NamesEveryLibraryOnceWithAVersion) {
  const BuildInfo& info = GetBuildInfo();
  EXPECT_FALSE(info.version.empty());
  ASSERT_EQ(info.libraries.size(), 6u);
  for (const auto& [name, version] : info.libraries) {
    EXPECT_FALSE(name.empty());
    EXPECT_FALSE(version.empty()) << name;
  }
  EXPECT_EQ(&GetBuildInfo(), &info);  // one instance
}

TEST(BuildInfo, TextHasALinePerLibrary) {
  const std::string text = BuildInfoText();
  EXPECT_EQ(text.rfind("bespoke ", 0), 0u);
  EXPECT_NE(text.find("  PCL "), std::string::npos);
  EXPECT_NE(text.find("  CGAL "), std::string::npos);
  EXPECT_NE(text.find("  Eigen "), std::string::npos);
  size_t lines = 0;
  for (const char c : text) lines += c == '\n';
  EXPECT_EQ(lines, 1 + GetBuildInfo().libraries.size());
}

}  // namespace
}  // namespace bespoke
