# The installed package from outside (issue 18): installs the build to a temporary prefix,
# configures tests/package/consumer against it with find_package(agaa CONFIG REQUIRED) (no
# repository path reaches it), builds it with the build's own compiler and runs it: one small
# frame on lavapipe under the validation layer, which must be validation-clean and non-blank; then,
# for reference, no-AA, Simple/Complex and AGAA's two paths, the same frame as a host's own content
# (samples/host_engine/host_content.h and shaders/, built here against the installed
# headers and GLSL alone; no GpuScene), which must match the scene's frame (HDR RMSE at most 1e-4);
# then samples/host_engine, built as a host builds it, against agaa-render on the same glTF file.
#   cmake -DBUILD=<build> -DSOURCE=<repo> -DWORK=<folder> -DCXX=<compiler> [-DLAUNCHER=ccache]
#         -DGENERATOR=<generator> [-DCXX_FLAGS=...] [-DLINKER_FLAGS=...] -P package_test.cmake
foreach(var BUILD SOURCE WORK CXX GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "package_test.cmake: -D${var}= is missing")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "package test: ${what} failed (${code}):\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})

# What a host gets and only that: the umbrella header, no test content, no tool harness, and no
# include directory but <prefix>/include/agaa.
foreach(path include/agaa/agaa/agaa.h include/agaa/engine/vk/device.h include/agaa/shared/frame.h
             include/agaa/agaa/common/raster_pass.h include/agaa/glsl/raster/sample_gbuffer_output.glsl
             include/agaa/glsl/raster/camera_pass.glsl include/agaa/glsl/raster/shadow_pass.glsl
             lib/cmake/agaa/agaa-config.cmake lib/cmake/agaa/agaa-targets.cmake)
  if(NOT EXISTS ${prefix}/${path})
    message(FATAL_ERROR "package test: the install lacks ${path}")
  endif()
endforeach()
file(GLOB_RECURSE installed RELATIVE ${prefix} ${prefix}/*)
foreach(path IN LISTS installed)
  if(path MATCHES "adversarial_scenes|frame_renderer|harness|test_scenes|test_shaders|/tests/|gtest")
    message(FATAL_ERROR "package test: test or tool content installed: ${path}")
  endif()
endforeach()
# A technique's passes are its inside, not a host's API (issue 50): AGAA's are not installed.
if(EXISTS ${prefix}/include/agaa/agaa/aggregate/passes)
  message(FATAL_ERROR "package test: AGAA's passes (agaa/aggregate/passes) are installed as public headers")
endif()
# The public surface a host reads, printed so that a change to it shows in the log.
file(GLOB_RECURSE headers ${prefix}/include/agaa/*.h)
list(FILTER headers EXCLUDE REGEX "/include/agaa/glsl/") # the GLSL includes' copy of shared/
file(GLOB_RECURSE glsl_includes ${prefix}/include/agaa/glsl/*)
list(LENGTH glsl_includes glsl_count)
message(STATUS "package test: ${glsl_count} GLSL include files for a host's shaders (include/agaa/glsl)")
list(LENGTH headers header_count)
set(header_lines 0)
foreach(header IN LISTS headers)
  file(STRINGS ${header} lines)
  list(LENGTH lines n)
  math(EXPR header_lines "${header_lines} + ${n}")
endforeach()
message(STATUS "package test: ${header_count} public headers, ${header_lines} non-empty lines")
file(READ ${prefix}/lib/cmake/agaa/agaa-targets.cmake targets)
string(FIND "${targets}" "${SOURCE}" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "package test: the exported targets name the source tree ${SOURCE}")
endif()

# samples/host_engine, built as a host builds it: against the installed package alone, its
# shaders (programs.cmake) against <prefix>/include/agaa/glsl alone, so the module's raster includes
# and what they include are complete. The consumer below draws with the same programs.
if(DEFINED GLSLANG)
  set(sample_args -S ${SOURCE}/samples/host_engine -B ${WORK}/host_engine -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX}
      "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}")
  if(LAUNCHER)
    list(APPEND sample_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
  endif()
  run("configuring samples/host_engine" ${CMAKE_COMMAND} ${sample_args})
  run("building samples/host_engine" ${CMAKE_COMMAND} --build ${WORK}/host_engine)
  set(host_programs ${WORK}/host_engine/shaders)
  file(GLOB spirv ${host_programs}/*.spv)
  list(LENGTH spirv spirv_count)
  message(STATUS "package test: a host's ${spirv_count} programs build against include/agaa/glsl alone")
  file(STRINGS ${SOURCE}/samples/host_engine/main.cpp sample_lines REGEX "[^ ]")
  file(STRINGS ${SOURCE}/samples/host_engine/host_content.h content_lines REGEX "[^ ]")
  list(LENGTH sample_lines sample_count)
  list(LENGTH content_lines content_count)
  message(STATUS "package test: samples/host_engine: ${sample_count} + ${content_count} non-empty lines "
                 "(main.cpp + host_content.h), installed headers only")
endif()

# The host's C++ (its vertex layout, material, drawer and traits), copied out of the source tree
# alone so that no other repository header can reach the consumer.
file(COPY ${SOURCE}/tests/node/host_mesh.h DESTINATION ${WORK}/host_include/tests/node)
file(COPY ${SOURCE}/samples/host_engine/host_content.h DESTINATION ${WORK}/host_include/samples/host_engine)
set(args -S ${SOURCE}/tests/package/consumer -B ${WORK}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
         -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
         "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}" -DHOST_INCLUDE=${WORK}/host_include)
if(LAUNCHER)
  list(APPEND args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} ${args})
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
run("running the consumer" ${WORK}/build/consumer agaa plane 32)
message(STATUS "${last_output}")
if(NOT last_output MATCHES "not blank, 0 validation error")
  message(FATAL_ERROR "package test: the consumer's frame is not a clean non-blank one:\n${last_output}")
endif()
# As a host with its own content: the technique from the host's traits alone, the host's drawer,
# vertex layout, material and the programs built above, against the scene's own frame.
if(DEFINED GLSLANG)
  foreach(method reference noaa simple-complex agaa agaa-accumulate)
    run("running the consumer as a host's content (${method})" ${WORK}/build/consumer ${method} railings 32
        ${host_programs})
    message(STATUS "${last_output}")
  endforeach()
endif()

# samples/host_engine renders a scenegen file with its own importer, vertex layout,
# material and command buffer; agaa-render renders the same file. Each method's display RMSE
# between the two must stay within 1e-4 (the sample exits 1 otherwise).
if(DEFINED GLSLANG AND DEFINED SCENEGEN AND DEFINED AGAA_RENDER)
  set(content ${WORK}/railings.gltf)
  run("writing the sample's content" ${SCENEGEN} --kind railings --out ${content})
  # Bad input: a folder without its programs is refused by name with exit code 2, nothing drawn.
  execute_process(COMMAND ${WORK}/host_engine/host_engine ${content} sbaa 32 ${WORK}/host_sbaa.exr ${WORK}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT code EQUAL 2 OR NOT out MATCHES "no host programs" OR out MATCHES "VUID|validation error\\]")
    message(FATAL_ERROR "package test: samples/host_engine without its programs: want exit 2 naming the "
                        "folder, got ${code}:\n${out}")
  endif()
  foreach(method reference noaa fxaa simple-complex sbaa streaming agaa agaa-accumulate)
    set(flags --scene ${content} --method ${method} --width 32 --height 32 --exposure 1 --lights scene
              --out ${WORK}/render_${method})
    if(method MATCHES "^agaa")
      list(APPEND flags --agaa-atomics 32 --agaa-subgroup-reduce off) # the sample's one build
    endif()
    run("agaa-render on the sample's content (${method})" ${AGAA_RENDER} ${flags})
    run("samples/host_engine (${method})" ${WORK}/host_engine/host_engine ${content} ${method} 32
        ${WORK}/host_${method}.exr ${WORK}/host_engine/shaders --compare ${WORK}/render_${method}.exr)
    message(STATUS "${last_output}")
  endforeach()
endif()
