# Issue 15: agaa-bench over the light-count axis on a tiny frame, validation on: it must exit 0,
# write the jobs of both light counts, and a report whose light-count section tables the scene.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${BENCH} --out ${OUT} --scenes plane --methods simple-complex,agaa --samples 4
                        --aggregates 2 --size 16x16 --frames 1 --warmup 0 --temporal 0 --extra-lights 0,4 --validate
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "agaa-bench exited ${rc}:\n${out}\n${err}")
endif()
foreach(job plane__agaa__n4__c2 plane+l4__agaa__n4__c2 plane+l4__simple-complex__n4__c0)
  if(NOT EXISTS ${OUT}/jobs/${job}.json)
    message(FATAL_ERROR "no ${OUT}/jobs/${job}.json: the light axis did not plan K = 0 and 4")
  endif()
endforeach()
file(READ ${OUT}/report.html html)
foreach(needle "<section id=\"lights\">" "data-scene=\"plane\"" "<th>K = 4</th>" "against Simple/Complex")
  string(FIND "${html}" "${needle}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report.html lacks '${needle}'")
  endif()
endforeach()
