# Fails when samples/embed_node.cpp has 60 or more lines of host code (issue 18: "the host needs
# under 60 lines to render a frame with its own device and targets"). Counted: every line that is
# not blank, not only a comment, and not an #include.
file(STRINGS "${FILE}" lines)
set(count 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^[ \t]*$" AND NOT line MATCHES "^[ \t]*//" AND NOT line MATCHES "^#include")
    math(EXPR count "${count} + 1")
  endif()
endforeach()
message(STATUS "${FILE}: ${count} lines of host code")
if(count GREATER_EQUAL 60)
  message(FATAL_ERROR "${FILE} has ${count} lines of host code; the limit is 59")
endif()
