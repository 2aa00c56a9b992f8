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
# One static library per top-level folder; headers are included as
# "folder/sub/file.h" from the repository root.
function(bespoke_add_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  add_library(${ARG_NAME} STATIC ${ARG_SOURCES})
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
