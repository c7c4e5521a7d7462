# GLSL -> SPIR-V at build time, embedded in the binaries as uint32_t arrays so
# they run from any directory. A shader compile error fails the build, and so does SPIR-V that
# SPIRV-Tools' validator rejects (glslang_checked.sh).
#
#   agaa_embed_shaders(TARGET name PROGRAMS <program> ...)
# creates an INTERFACE library `name` whose include directory (${PROJECT_BINARY_DIR}/generated/<name>:
# the project's own binary folder, also under a host's add_subdirectory) holds, for each program
# <dir>/<pass>.<stage>, a header shaders/<dir>/<pass>_<stage>.h defining
#   inline constexpr uint32_t k<Dir><Pass><Stage>[] (the SPIR-V words)
# e.g. reference/lighting_ms.comp -> #include "shaders/reference/lighting_ms_comp.h", kReferenceLightingMsComp.
# A program is written
#   <dir>/<pass>.<stage>[=<source>][:<MACRO>[,<MACRO>...]]
# and compiles shaders/glsl/<source> (default: the program's own name) with each MACRO defined to 1;
# a source declares every macro it reads with a default of 0 (#ifndef). One source thus makes every
# variant that changes bindings or capabilities (emission, shadows, the generation path), declared
# here in one table rather than as a wrapper file per variant:
#   agaa/lighting_gbuffer_shadow.comp=agaa/lighting.comp:AGAA_GBUFFER,AGAA_SHADOWS
# The table itself is generated too: shaders/<name>_programs.h defines
#   inline constexpr EmbeddedProgram k<Name>Programs[] = {{"<dir>/<pass>.<stage>", k<Dir><Pass><Stage>}, ...}
# in the table's order, so C++ selects a variant by its name and never spells the pairs again.

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
  cmake_parse_arguments(ARG "" "TARGET;ROOT" "PROGRAMS" ${ARGN})
  # The programs' folder: shaders/glsl, or ROOT (a sample's own shaders), which then include the
  # module's GLSL from shaders/glsl as a host's do from <prefix>/include/agaa/glsl.
  set(glsl_root ${PROJECT_SOURCE_DIR}/shaders/glsl)
  set(module_glsl ${glsl_root})
  if(ARG_ROOT)
    set(glsl_root ${ARG_ROOT})
  endif()
  set(out_root ${PROJECT_BINARY_DIR}/generated/${ARG_TARGET})
  set(raws "")
  set(index_includes "")
  set(index_entries "")
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
  foreach(program IN LISTS ARG_PROGRAMS)
    if(NOT program MATCHES "^([a-z0-9_/]+\\.(comp|frag|vert))(=([a-z0-9_/]+\\.(comp|frag|vert)))?(:([A-Z0-9_,]+))?$")
      message(FATAL_ERROR "agaa_embed_shaders(${ARG_TARGET}): '${program}' is not "
                          "<dir>/<pass>.<stage>[=<source>][:<MACRO>[,<MACRO>...]] (stage comp, frag or vert)")
    endif()
    set(name "${CMAKE_MATCH_1}")
    set(stage "${CMAKE_MATCH_2}")
    set(src "${CMAKE_MATCH_4}")
    set(macros "${CMAKE_MATCH_7}")
    if(src STREQUAL "")
      set(src "${name}")
    elseif(NOT CMAKE_MATCH_5 STREQUAL stage)
      message(FATAL_ERROR "agaa_embed_shaders(${ARG_TARGET}): '${program}' compiles a ${CMAKE_MATCH_5} "
                          "source as a ${stage} program")
    endif()
    set(defines "")
    if(NOT macros STREQUAL "")
      string(REPLACE "," ";" macros "${macros}")
      foreach(m IN LISTS macros)
        list(APPEND defines "-D${m}=1")
      endforeach()
    endif()
    get_filename_component(dir "${name}" DIRECTORY)
    get_filename_component(stem "${name}" NAME_WE)
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
      COMMAND sh ${PROJECT_SOURCE_DIR}/tools/cmake/glslang_checked.sh ${GLSLANG_VALIDATOR} -V --target-env vulkan1.3 -I${glsl_root} -I${module_glsl} -g0 ${perturb} ${defines}
              --vn ${symbol}Words --depfile ${raw}.d -o ${raw} ${glsl_root}/${src}
      COMMAND ${CMAKE_COMMAND} -DRAW=${raw} -DOUT=${header} -DSYMBOL=${symbol}
              -P ${PROJECT_SOURCE_DIR}/tools/cmake/wrap_spirv.cmake
      DEPENDS ${glsl_root}/${src} ${PROJECT_SOURCE_DIR}/tools/cmake/wrap_spirv.cmake
              ${PROJECT_SOURCE_DIR}/tools/cmake/glslang_checked.sh ${perturb_stamp}
      DEPFILE ${raw}.d
      COMMENT "GLSL ${name}"
      VERBATIM)
    list(APPEND raws ${raw})
    string(APPEND index_includes "#include \"shaders/${dir}/${stem}_${stage}.h\"\n")
    string(APPEND index_entries "    {\"${name}\", ${symbol}},\n")
  endforeach()
  _agaa_camel(table "${ARG_TARGET}")
  string(CONCAT index "// Generated by agaa_embed_shaders(TARGET ${ARG_TARGET}) (tools/cmake/embed_spirv.cmake):\n"
            "// every program of its table by its name, in the table's order.\n#pragma once\n${index_includes}\n"
            "#include <cstdint>\n#include <span>\n#include <string_view>\n\n"
            "#ifndef AGAA_EMBEDDED_PROGRAM_DEFINED\n#define AGAA_EMBEDDED_PROGRAM_DEFINED\n"
            "struct EmbeddedProgram {\n    std::string_view name; // \"<dir>/<pass>.<stage>\"\n"
            "    std::span<const uint32_t> code;\n};\n#endif\n\n"
            "inline constexpr EmbeddedProgram k${table}Programs[] = {\n${index_entries}};\n")
  # Written only when it changes, as the shaders' headers are.
  set(index_file ${out_root}/shaders/${ARG_TARGET}_programs.h)
  set(old_index "")
  if(EXISTS ${index_file})
    file(READ ${index_file} old_index)
  endif()
  if(NOT old_index STREQUAL index)
    file(WRITE ${index_file} "${index}")
  endif()
  add_custom_target(${ARG_TARGET}_spirv DEPENDS ${raws})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_spirv)
  target_include_directories(${ARG_TARGET} INTERFACE $<BUILD_INTERFACE:${out_root}> $<BUILD_INTERFACE:${glsl_root}>)
endfunction()
