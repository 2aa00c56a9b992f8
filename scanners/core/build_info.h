// What this build of Bespoke is: its version and the versions of the
// libraries it was built with. One source for `bespoke version` and for every
// record that stores the versions it ran with (batch done records, reports).
#ifndef BESPOKE_SCANNERS_CORE_BUILD_INFO_H_
#define BESPOKE_SCANNERS_CORE_BUILD_INFO_H_

#include <string>
#include <utility>
#include <vector>

namespace bespoke {

struct BuildInfo {
  std::string version;     // Bespoke's own, e.g. "0.1.0"
  std::string build_type;  // CMake build type, e.g. "Release"
  // (library, version) in a fixed order: pcl, cgal, open3d, opencv, eigen,
  // flann; "unknown" where the build did not configure the library.
  std::vector<std::pair<std::string, std::string>> libraries;
};

// The build's information (the same on every call).
const BuildInfo& GetBuildInfo();

// "bespoke 0.1.0 (Release)" and one "  PCL 1.13.0" line per library.
std::string BuildInfoText();

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_BUILD_INFO_H_
