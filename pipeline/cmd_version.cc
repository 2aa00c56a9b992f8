// `bespoke version`: the version and the library versions it was built with.
#include <CGAL/version.h>
#include <Eigen/Core>
#include <opencv2/core/version.hpp>
#include <pcl/pcl_config.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "pipeline/commands.h"

#ifndef BESPOKE_VERSION
#define BESPOKE_VERSION "unknown"
#endif

namespace bespoke {

CommandRunner SetupVersionCommand(CLI::App& /*app*/) {
  return [](const GlobalOptions&) {
    std::cout << "bespoke " << BESPOKE_VERSION << "\n"
              << "  PCL " << PCL_VERSION_PRETTY << "\n"
              << "  CGAL " << CGAL_VERSION_STR << "\n"
              << "  OpenCV " << CV_VERSION << "\n"
              << "  Eigen " << EIGEN_WORLD_VERSION << "." << EIGEN_MAJOR_VERSION << "."
              << EIGEN_MINOR_VERSION << "\n";
    return 0;
  };
}

}  // namespace bespoke
