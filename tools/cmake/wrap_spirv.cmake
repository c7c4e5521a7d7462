# Wraps glslangValidator's --vn output into a header with an inline constexpr
# array and a std::span accessor, so one header can be included anywhere.
file(READ ${RAW} body)
string(REPLACE "const uint32_t ${SYMBOL}Words[] =" "inline constexpr uint32_t ${SYMBOL}Words[] =" body "${body}")
string(REPLACE "#pragma once" "" body "${body}")
set(header "#pragma once\n#include <cstdint>\n#include <span>\n${body}\ninline constexpr std::span<const uint32_t> ${SYMBOL}{${SYMBOL}Words};\n")
# Written only when the words change, so its time stamp (and every source that embeds it) stays as
# it is when a shader recompiles to the same SPIR-V: switching AGAA_TEST_PERTURB in a build folder
# (tools/perturb-test.sh) rebuilds only the sources whose shaders the perturbation reaches.
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL header)
  file(WRITE ${OUT} "${header}")
endif()
