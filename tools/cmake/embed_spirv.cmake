# GLSL -> SPIR-V at build time, embedded in the binaries as uint32_t arrays so
# they run from any directory. A shader compile error fails the build.
#
#   agaa_embed_shaders(TARGET name SOURCES a/b.comp ...)
# creates an INTERFACE library `name` whose include directory (${PROJECT_BINARY_DIR}/generated/<name>:
# the project's own binary folder, also under a host's add_subdirectory) holds, for each
# shaders/glsl/<dir>/<pass>.<stage>, a header shaders/<dir>/<pass>_<stage>.h defining
#   inline constexpr uint32_t k<Dir><Pass><Stage>[] (the SPIR-V words)
# e.g. shaders/glsl/reference/lighting.comp -> #include "shaders/reference/lighting_comp.h", kReferenceLightingComp.

function(_agaa_camel out text)
  string(REGEX REPLACE "[-./]" "_" text "${text}")
  string(REPLACE "_" ";" parts "${text}")
  set(result "")
  foreach(p IN LISTS parts)
    if(p STREQUAL "")
      continue()
    endif()
    string(SUBSTRING "${p}" 0 1 first)
    string(SUBSTRING "${p}" 1 -1 rest)
    string(TOUPPER "${first}" first)
    string(APPEND result "${first}${rest}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

function(agaa_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(glsl_root ${PROJECT_SOURCE_DIR}/shaders/glsl)
  set(out_root ${PROJECT_BINARY_DIR}/generated/${ARG_TARGET})
  set(raws "")
  # AGAA_TEST_PERTURB (top-level CMakeLists.txt): a deliberate shader error for the suite to catch.
  set(perturb "")
  if(NOT AGAA_TEST_PERTURB STREQUAL "none")
    string(TOUPPER "${AGAA_TEST_PERTURB}" perturb)
    set(perturb "-DAGAA_TEST_PERTURB_${perturb}")
  endif()
  # The variant as a file every shader depends on, rewritten only when it changes: a Makefile
  # build does not rerun a command whose command line changed, so this is what recompiles the
  # shaders when the same folder is reconfigured with another AGAA_TEST_PERTURB.
  set(perturb_stamp ${PROJECT_BINARY_DIR}/generated/test_perturb.txt)
  set(old "")
  if(EXISTS ${perturb_stamp})
    file(READ ${perturb_stamp} old)
  endif()
  if(NOT old STREQUAL "${AGAA_TEST_PERTURB}\n")
    file(WRITE ${perturb_stamp} "${AGAA_TEST_PERTURB}\n")
  endif()
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(dir "${src}" DIRECTORY)
    get_filename_component(stem "${src}" NAME_WE)
    get_filename_component(ext "${src}" LAST_EXT)
    string(SUBSTRING "${ext}" 1 -1 stage)
    _agaa_camel(symbol "${dir}_${stem}_${stage}")
    set(symbol "k${symbol}")
    set(header ${out_root}/shaders/${dir}/${stem}_${stage}.h)
    set(raw ${header}.raw)
    # raw is rewritten on every run, header only when its words change (wrap_spirv.cmake): a
    # byproduct, so neither Ninja (restat) nor make rebuilds its includers for an unchanged one.
    add_custom_command(
      OUTPUT ${raw}
      BYPRODUCTS ${header}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${out_root}/shaders/${dir}
      COMMAND ${GLSLANG_VALIDATOR} -V --target-env vulkan1.3 -I${glsl_root} -g0 ${perturb}
              --vn ${symbol}Words --depfile ${raw}.d -o ${raw} ${glsl_root}/${src}
      COMMAND ${CMAKE_COMMAND} -DRAW=${raw} -DOUT=${header} -DSYMBOL=${symbol}
              -P ${PROJECT_SOURCE_DIR}/tools/cmake/wrap_spirv.cmake
      DEPENDS ${glsl_root}/${src} ${PROJECT_SOURCE_DIR}/tools/cmake/wrap_spirv.cmake ${perturb_stamp}
      DEPFILE ${raw}.d
      COMMENT "GLSL ${src}"
      VERBATIM)
    list(APPEND raws ${raw})
  endforeach()
  add_custom_target(${ARG_TARGET}_spirv DEPENDS ${raws})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_spirv)
  target_include_directories(${ARG_TARGET} INTERFACE $<BUILD_INTERFACE:${out_root}> $<BUILD_INTERFACE:${glsl_root}>)
endfunction()
