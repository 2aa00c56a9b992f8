# Every dependency is a Debian 12 package installed by scripts/setup-debian.sh.
# Nothing is downloaded at configure, build or run time.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(spdlog REQUIRED)
find_package(fmt REQUIRED)
find_package(TBB REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)

if(NOT BESPOKE_FUZZ)
  find_package(PCL 1.13 REQUIRED COMPONENTS
    common io filters features kdtree search sample_consensus segmentation surface)
  find_package(flann REQUIRED)
  find_package(Open3D REQUIRED)
  find_package(CGAL REQUIRED)
  find_package(OpenCV REQUIRED COMPONENTS core imgproc)
  find_package(CLI11 REQUIRED)
  find_package(Pagmo REQUIRED)
  find_package(OpenMP REQUIRED COMPONENTS CXX)
endif()

if(BESPOKE_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(BESPOKE_BUILD_BENCHMARKS AND NOT BESPOKE_FUZZ)
  find_package(benchmark REQUIRED)
endif()

# PCL exports plain variables rather than targets; wrap them once so libraries
# can link `bespoke::pcl` privately like any other target.
if(NOT BESPOKE_FUZZ AND NOT TARGET bespoke::pcl)
  add_library(bespoke_pcl INTERFACE)
  target_include_directories(bespoke_pcl SYSTEM INTERFACE ${PCL_INCLUDE_DIRS})
  target_link_libraries(bespoke_pcl INTERFACE ${PCL_LIBRARIES})
  target_compile_definitions(bespoke_pcl INTERFACE ${PCL_DEFINITIONS})
  add_library(bespoke::pcl ALIAS bespoke_pcl)
endif()
