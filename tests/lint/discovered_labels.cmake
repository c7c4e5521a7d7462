# Fails when a gtest_discover_tests call gives LABELS as one list ("gpu;sanitize"): the discovered
# tests' file flattens its PROPERTIES, so every label but the first is lost and tools/test.sh's
# stages, which select by label, silently skip or repeat those tests (tests/CMakeLists.txt).
# Usage: cmake -DROOT=<dir> -P discovered_labels.cmake
if(NOT ROOT)
  message(FATAL_ERROR "discovered_labels.cmake: pass -DROOT=<source root>")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/lint_lines.cmake)
set(found "")
file(GLOB_RECURSE lists LIST_DIRECTORIES false ${ROOT}/tests/CMakeLists.txt ${ROOT}/tests/*.cmake)
foreach(list IN LISTS lists)
  file(RELATIVE_PATH relative ${ROOT} ${list})
  if(NOT relative MATCHES "^tests/lint/fixtures/")
    lint_lines(found ${ROOT} ${list} "gtest_discover_tests.*LABELS[ \t]+\"[^\"]*;")
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "gtest_discover_tests given LABELS as one list (ctest keeps only the first); "
                      "write each on its own, LABELS gpu LABELS sanitize:${found}")
endif()
