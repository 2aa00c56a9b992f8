# Compiler settings shared by every Bespoke target, and helpers that keep the
# per-folder CMakeLists.txt files short.

add_library(bespoke_warnings INTERFACE)
target_compile_options(bespoke_warnings INTERFACE -Wall -Wextra)
if(BESPOKE_SANITIZE)
  target_compile_options(bespoke_warnings INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(bespoke_warnings INTERFACE -fsanitize=address,undefined)
  # Eigen stops trusting malloc's 16-byte alignment when __SANITIZE_ADDRESS__
  # is defined and then allocates with its own offset ("handmade") scheme,
  # while Debian's PCL, built without ASan, uses plain malloc/free. Eigen
  # objects that cross that boundary (pcl::SACSegmentation's model
  # coefficients) were then freed the other way: ASan reported "attempting
  # free on address which was not malloc()-ed" in
  # RandomSampleConsensus::computeModel. ASan's allocator aligns to 16 bytes
  # on x86-64, so the prebuilt libraries' assumption holds: use it here too.
  target_compile_definitions(bespoke_warnings INTERFACE EIGEN_MALLOC_ALREADY_ALIGNED=1)
  # Leak suppressions for third-party process-lifetime caches (tests/sanitizer).
  set(BESPOKE_TEST_ENVIRONMENT
    "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/sanitizer/lsan.supp:print_suppressions=0")
endif()

set(BESPOKE_SHARED_DIR "${PROJECT_SOURCE_DIR}/../shared" CACHE PATH
  "The ../shared folder with the thesis and test data (tests skip where it is absent)")

# bespoke_add_library(NAME <name> SOURCES ... [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
# One static library per stage folder; headers are included as
# "top/stage/file.h" from the repository root. Heavy third-party libraries go
# in PRIVATE_LIBS so that users of the library never see their headers.
function(bespoke_add_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
  # A unity build parses the heavy headers (Eigen, JSON, PCL, CGAL, CLI11) once
  # per batch instead of once per file; tests and tools stay one file a unit.
  set_target_properties(${ARG_NAME} PROPERTIES UNITY_BUILD ${BESPOKE_UNITY_BUILD}
                                               UNITY_BUILD_BATCH_SIZE 8)
  target_include_directories(${ARG_NAME} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${ARG_NAME} PUBLIC ${ARG_PUBLIC_LIBS} bespoke_warnings
                                    PRIVATE ${ARG_PRIVATE_LIBS})
endfunction()

# bespoke_add_test(NAME <name> SOURCES ... LIBS ... [LABELS ...] [TIMEOUT s])
# One GoogleTest binary per library; every TEST becomes a ctest test.
# Labels (one per binary): `shared` (reads ../shared, skips without it), `slow` (> 10 s).
function(bespoke_add_test)
  if(NOT BESPOKE_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} bespoke_test_support
                                          GTest::gtest GTest::gmock GTest::gtest_main)
  # Property names and values as one list: an empty value would vanish from
  # it and shift every pair after it, so empty ones are left out.
  set(properties TIMEOUT ${ARG_TIMEOUT})
  if(ARG_LABELS)
    list(APPEND properties LABELS "${ARG_LABELS}")
  endif()
  if(BESPOKE_TEST_ENVIRONMENT)
    list(APPEND properties ENVIRONMENT "${BESPOKE_TEST_ENVIRONMENT}")
  endif()
  gtest_discover_tests(${ARG_NAME}
    DISCOVERY_MODE PRE_TEST
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}
    PROPERTIES ${properties})
endfunction()

# bespoke_add_cli_test(NAME <name> SOURCES ... [LIBS ...] [LABELS ...])
# A test binary that runs the `bespoke` command as a process; it gets the
# binary's path as BESPOKE_BINARY and is rebuilt with it.
function(bespoke_add_cli_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS;LABELS" ${ARGN})
  bespoke_add_test(NAME ${ARG_NAME} SOURCES ${ARG_SOURCES} LIBS ${ARG_LIBS} LABELS ${ARG_LABELS})
  if(TARGET ${ARG_NAME})
    add_dependencies(${ARG_NAME} bespoke)
    target_compile_definitions(${ARG_NAME} PRIVATE BESPOKE_BINARY="$<TARGET_FILE:bespoke>")
  endif()
endfunction()

# bespoke_add_tool(NAME <name> SOURCES ... LIBS ...)
# A benchmark or evaluation program (eval/bench): built with the benchmarks
# (BESPOKE_BUILD_BENCHMARKS), never a test; BESPOKE_DEFAULT_SHARED_DIR tells
# it where ../shared is.
function(bespoke_add_tool)
  if(NOT BESPOKE_BUILD_BENCHMARKS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} bespoke_warnings)
  target_compile_definitions(${ARG_NAME} PRIVATE
    BESPOKE_DEFAULT_SHARED_DIR="${BESPOKE_SHARED_DIR}")
endfunction()
