# The README's command-line synopsis is agaa-render's own: the first paragraph of `--help`, whose
# method settings come from their one declaration (agaa/method_settings.h).
#   cmake -DRENDER=<agaa-render> -DREADME=<README.md> -P readme_synopsis.cmake
execute_process(COMMAND ${RENDER} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "agaa-render --help exited ${status}")
endif()
string(FIND "${help}" "\n\n" end)
string(SUBSTRING "${help}" 0 ${end} synopsis)
file(READ ${README} readme)
string(FIND "${readme}" "## Command line\n\n```\n" start)
if(start EQUAL -1)
  message(FATAL_ERROR "${README}: no '## Command line' section opening with a ``` block")
endif()
math(EXPR start "${start} + 21") # past the heading and the fence
string(SUBSTRING "${readme}" ${start} -1 rest)
string(FIND "${rest}" "\n```" stop)
string(SUBSTRING "${rest}" 0 ${stop} documented)
if(NOT documented STREQUAL synopsis)
  message(FATAL_ERROR "${README}'s synopsis is not agaa-render's: replace the block under '## Command line' with "
                      "the first paragraph of `agaa-render --help`:\n${synopsis}\n\nREADME has:\n${documented}")
endif()
