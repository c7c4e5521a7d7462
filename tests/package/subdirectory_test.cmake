# add_subdirectory from a host (issue 18): configures tests/package/parent, which adds the repository
# as a subdirectory, and checks nothing leaks into the host: no CMAKE_BUILD_TYPE forced into its
# cache, no tests and no tool targets, no clash with its own eng_vk target, and the generated
# SPIR-V headers in the subproject's own binary folder (the shaders are compiled to prove it).
#   cmake -DSOURCE=<repo> -DWORK=<folder> -DCXX=<compiler> -DGENERATOR=<generator> -P subdirectory_test.cmake
foreach(var SOURCE WORK CXX GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "subdirectory_test.cmake: -D${var}= is missing")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "subdirectory test: ${what} failed (${code}):\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
set(build ${WORK}/build)
run("configuring the parent" ${CMAKE_COMMAND} -S ${SOURCE}/tests/package/parent -B ${build} -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DAGAA_SOURCE_DIR=${SOURCE})

file(STRINGS ${build}/CMakeCache.txt build_type REGEX "^CMAKE_BUILD_TYPE:")
if(NOT build_type MATCHES "^CMAKE_BUILD_TYPE:[A-Z]+=$")
  message(FATAL_ERROR "subdirectory test: the host's cache has a build type it never set: ${build_type}")
endif()
foreach(option AGAA_BUILD_TESTS AGAA_BUILD_TOOLS AGAA_BUILD_SAMPLES AGAA_INSTALL)
  file(STRINGS ${build}/CMakeCache.txt value REGEX "^${option}:")
  if(NOT value MATCHES "=OFF$")
    message(FATAL_ERROR "subdirectory test: ${option} is not OFF under add_subdirectory: ${value}")
  endif()
endforeach()

run("listing the tests" ${CMAKE_CTEST_COMMAND} --test-dir ${build} -N)
if(NOT last_output MATCHES "Total Tests: 0")
  message(FATAL_ERROR "subdirectory test: the host got tests:\n${last_output}")
endif()
file(READ ${build}/agaa-targets-seen.txt seen)
if(NOT seen STREQUAL "agaa_vk;agaa::agaa")
  message(FATAL_ERROR "subdirectory test: the host sees the targets '${seen}'; only agaa_vk;agaa::agaa "
                      "of the ones checked (tests/package/parent/CMakeLists.txt) should be there")
endif()

set(header agaa/generated/agaa_shaders/shaders/fxaa/fxaa_comp.h)
run("compiling the shaders" ${CMAKE_COMMAND} --build ${build} --target agaa_shaders_spirv)
if(NOT EXISTS ${build}/${header})
  message(FATAL_ERROR "subdirectory test: ${header} was not generated in the subproject's binary folder")
endif()
if(EXISTS ${build}/generated)
  message(FATAL_ERROR "subdirectory test: the subproject wrote ${build}/generated into the host's binary folder")
endif()
