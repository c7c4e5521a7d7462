# Wraps glslangValidator's --vn output into a header with an inline constexpr
# array and a std::span accessor, so one header can be included anywhere.
file(READ ${RAW} body)
string(REPLACE "const uint32_t ${SYMBOL}Words[] =" "inline constexpr uint32_t ${SYMBOL}Words[] =" body "${body}")
string(REPLACE "#pragma once" "" body "${body}")
file(WRITE ${OUT} "#pragma once\n#include <cstdint>\n#include <span>\n${body}\ninline constexpr std::span<const uint32_t> ${SYMBOL}{${SYMBOL}Words};\n")
