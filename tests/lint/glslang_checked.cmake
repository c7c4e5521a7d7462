# tools/cmake/glslang_checked.sh, which every embedded shader's compile runs through, must fail a
# compile whose SPIR-V SPIRV-Tools rejects although glslang exits 0 (glslang 11 does: it prints the
# validator's errors and succeeds), remove the output so that the next build compiles it again,
# and pass a clean compile through. A stand-in compiler plays glslang, so the check does not rest
# on a glslang bug staying unfixed.
#   cmake -DROOT=<source> -DWORK=<folder> -P glslang_checked.cmake
file(MAKE_DIRECTORY ${WORK})
foreach(kind rejected clean)
  set(compiler ${WORK}/${kind}_compiler.sh)
  set(message "shader.comp")
  if(kind STREQUAL "rejected")
    set(message "shader.comp\\nerror: SPIRV-Tools Validation Errors\\nerror: ID '64' does not dominate its use")
  endif()
  # Writes the file after -o, prints its message, exits 0.
  file(WRITE ${compiler} "previous=\nfor arg in \"$@\"; do\n  [ \"$previous\" != -o ] || echo spirv > \"$arg\"\n"
                         "  previous=\"$arg\"\ndone\nprintf '${message}\\n'\n")
  set(output ${WORK}/${kind}.spv)
  file(REMOVE ${output})
  execute_process(COMMAND sh ${ROOT}/tools/cmake/glslang_checked.sh sh ${compiler} -V -o ${output} shader.comp
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${kind}: exit ${status}\n${out}${err}")
  if(kind STREQUAL "rejected")
    if(status EQUAL 0)
      message(FATAL_ERROR "glslang_checked.sh passed a compile SPIRV-Tools rejected")
    endif()
    if(EXISTS ${output})
      message(FATAL_ERROR "glslang_checked.sh left the rejected SPIR-V in place")
    endif()
    if(NOT "${out}${err}" MATCHES "does not dominate.*the SPIR-V above is invalid")
      message(FATAL_ERROR "glslang_checked.sh did not pass on the validator's error and name it invalid")
    endif()
  elseif(NOT status EQUAL 0 OR NOT EXISTS ${output})
    message(FATAL_ERROR "glslang_checked.sh failed a clean compile or removed its output")
  endif()
endforeach()
