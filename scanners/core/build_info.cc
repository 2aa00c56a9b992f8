#include "scanners/core/build_info.h"

#include <sstream>

// The version strings come from CMake (scanners/core/CMakeLists.txt), as the
// packages' config files reported them, so no third-party header is needed.
#ifndef BESPOKE_VERSION
#define BESPOKE_VERSION ""
#endif
#ifndef BESPOKE_BUILD_TYPE
#define BESPOKE_BUILD_TYPE ""
#endif
#ifndef BESPOKE_PCL_VERSION
#define BESPOKE_PCL_VERSION ""
#endif
#ifndef BESPOKE_CGAL_VERSION
#define BESPOKE_CGAL_VERSION ""
#endif
#ifndef BESPOKE_OPEN3D_VERSION
#define BESPOKE_OPEN3D_VERSION ""
#endif
#ifndef BESPOKE_OPENCV_VERSION
#define BESPOKE_OPENCV_VERSION ""
#endif
#ifndef BESPOKE_EIGEN_VERSION
#define BESPOKE_EIGEN_VERSION ""
#endif
#ifndef BESPOKE_FLANN_VERSION
#define BESPOKE_FLANN_VERSION ""
#endif

namespace bespoke {

namespace {

std::string OrUnknown(const char* value) {
  return value[0] == '\0' ? std::string("unknown") : std::string(value);
}

BuildInfo MakeBuildInfo() {
  BuildInfo info;
  info.version = OrUnknown(BESPOKE_VERSION);
  info.build_type = OrUnknown(BESPOKE_BUILD_TYPE);
  info.libraries = {
      {"pcl", OrUnknown(BESPOKE_PCL_VERSION)},       {"cgal", OrUnknown(BESPOKE_CGAL_VERSION)},
      {"open3d", OrUnknown(BESPOKE_OPEN3D_VERSION)}, {"opencv", OrUnknown(BESPOKE_OPENCV_VERSION)},
      {"eigen", OrUnknown(BESPOKE_EIGEN_VERSION)},   {"flann", OrUnknown(BESPOKE_FLANN_VERSION)}};
  return info;
}

// How `bespoke version` names each library.
const char* DisplayName(const std::string& key) {
  if (key == "pcl") return "PCL";
  if (key == "cgal") return "CGAL";
  if (key == "open3d") return "Open3D";
  if (key == "opencv") return "OpenCV";
  if (key == "eigen") return "Eigen";
  if (key == "flann") return "FLANN";
  return key.c_str();
}

}  // namespace

const BuildInfo& GetBuildInfo() {
  static const BuildInfo info = MakeBuildInfo();
  return info;
}

std::string BuildInfoText() {
  const BuildInfo& info = GetBuildInfo();
  std::ostringstream out;
  out << "bespoke " << info.version << " (" << info.build_type << ")\n";
  for (const auto& [name, version] : info.libraries)
    out << "  " << DisplayName(name) << " " << version << "\n";
  return out.str();
}

}  // namespace bespoke
