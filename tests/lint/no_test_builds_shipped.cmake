# Fails when test instrumentation reaches the shipping build (STYLE.md: exports, records and
# timing switches live in test-only passes or test builds of a shader, never in the shipping
# layout). A test or benchmark build is a main of its own (shaders/glsl/tests/, shaders/glsl/breakdown/)
# over a pass's shared parts, declared in the tests' or agaa-timings' own program table
# (tests/CMakeLists.txt, tools/agaa_timings/CMakeLists.txt). The shipping table
# (shaders/CMakeLists.txt) declares none, no shipping source switches on AGAA_EXPORT, AGAA_RECORD
# or an AGAA_BREAKDOWN_* macro (nor defines one to 1 outside shaders/glsl/tests/), and no
# shipping C++ includes a test kernel or test support.
# Usage: cmake -DROOT=<dir> -P no_test_builds_shipped.cmake
if(NOT ROOT)
  message(FATAL_ERROR "no_test_builds_shipped.cmake: pass -DROOT=<source root>")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/lint_lines.cmake)
set(found "")
file(GLOB_RECURSE shaders LIST_DIRECTORIES false ${ROOT}/shaders/glsl/*.comp ${ROOT}/shaders/glsl/*.frag
     ${ROOT}/shaders/glsl/*.vert ${ROOT}/shaders/glsl/*.glsl)
foreach(source IN LISTS shaders)
  file(RELATIVE_PATH relative ${ROOT} ${source})
  if(relative MATCHES "^shaders/glsl/tests/")
    continue()
  endif()
  lint_lines(found ${ROOT} ${source} "^[ \t]*#[ \t]*define[ \t]+AGAA_(EXPORT|RECORD|BREAKDOWN_[A-Z_]+)[ \t]+1"
             "a test build outside shaders/glsl/tests/")
  # A test or benchmark build is a main of its own over the pass's shared parts (issue 50): no
  # shipping source switches on one, and agaa-timings' builds live in shaders/glsl/breakdown/.
  if(relative MATCHES "^shaders/glsl/breakdown/")
    continue()
  endif()
  lint_lines(found ${ROOT} ${source} "^[ \t]*#[ \t]*(if|ifdef|ifndef|elif)[^\n]*AGAA_(EXPORT|RECORD|BREAKDOWN_[A-Z_]+)"
             "a test or benchmark switch in a shipping source")
endforeach()
if(EXISTS ${ROOT}/shaders/CMakeLists.txt)
  lint_lines(found ${ROOT} ${ROOT}/shaders/CMakeLists.txt "^[ \t]*tests/" "a test kernel in the shipping library")
  lint_lines(found ${ROOT} ${ROOT}/shaders/CMakeLists.txt "^[^#]*[:,]AGAA_(EXPORT|RECORD|BREAKDOWN_[A-Z_]+)"
             "a test or benchmark build in the shipping library")
endif()
file(GLOB_RECURSE sources LIST_DIRECTORIES false ${ROOT}/engine/*.cpp ${ROOT}/engine/*.h ${ROOT}/agaa/*.cpp
     ${ROOT}/agaa/*.h ${ROOT}/agaa/*.cpp.txt ${ROOT}/samples/*.cpp ${ROOT}/samples/*.h)
foreach(source IN LISTS sources)
  lint_lines(found ${ROOT} ${source} "#include \"(shaders/tests/|tests/)" "shipping code including test support")
endforeach()
if(found)
  message(FATAL_ERROR "test instrumentation in the shipping build:${found}")
endif()
message(STATUS "no test build of a shader and no test support in the shipping build under ${ROOT}")
