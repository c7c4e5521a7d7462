# The results-page check must fail on a README whose headline table was edited by hand: copy the
# README with one figure of the table changed, run the check on the copy, and fail unless the
# check refuses it naming the README.
#   cmake -DROOT=<source> -DPYTHON=<python3> -DWORK=<folder> -P results_page_edited.cmake
file(READ ${ROOT}/README.md readme)
string(FIND "${readme}" "<!-- results:headline begin -->" begin)
string(FIND "${readme}" "<!-- results:headline end -->" end)
if(begin EQUAL -1 OR end LESS begin)
  message(FATAL_ERROR "README.md has no headline block to edit")
endif()
math(EXPR length "${end} - ${begin}")
string(SUBSTRING "${readme}" ${begin} ${length} table)
# The first "0." in the table (the truth's own error of the first scene) becomes "9.".
string(FIND "${table}" "| 0." at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md's headline table has no figure '| 0.' to edit")
endif()
math(EXPR at "${begin} + ${at} + 2")
string(SUBSTRING "${readme}" 0 ${at} head)
math(EXPR rest "${at} + 1")
string(SUBSTRING "${readme}" ${rest} -1 tail)
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/README.md "${head}9${tail}")
execute_process(COMMAND ${PYTHON} ${ROOT}/tools/results-page.py --check --page ${ROOT}/docs/results.md
                        --readme ${WORK}/README.md
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(status EQUAL 0)
  message(FATAL_ERROR "the check passed a README whose headline table was edited")
endif()
if(NOT err MATCHES "README.md's headline table differs from")
  message(FATAL_ERROR "the check failed, but not naming the README's table")
endif()
message("the edited README was refused, as it should be")
