# agaa-render's stats name every method setting the method reads, as the flags do, and no other:
#   cmake -DRENDER=<agaa-render> -DOUT=<dir> -P stats_settings.cmake
execute_process(COMMAND ${RENDER} --validate --builtin plane --width 8 --height 8 --method agaa-samples
                        --agaa-ndf toksvig --shadow-map-size 256 --out ${OUT}/frame --stats ${OUT}/stats.json
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "agaa-render exited ${status}")
endif()
file(READ ${OUT}/stats.json stats)
string(JSON settings GET "${stats}" settings)
foreach(expected "agaa-ndf;toksvig" "shadow-map-size;256" "samples;8" "aggregates;2" "agaa-lighting;auto"
                 "curvature-roughness;off")
  list(GET expected 0 name)
  list(GET expected 1 value)
  string(JSON got ERROR_VARIABLE missing GET "${settings}" ${name})
  if(NOT got STREQUAL value)
    message(FATAL_ERROR "stats settings.${name} is '${got}', expected '${value}' (${missing})")
  endif()
endforeach()
foreach(unread surfaces streaming-normal-angle agaa-generation)
  string(JSON got ERROR_VARIABLE missing GET "${settings}" ${unread})
  if(missing STREQUAL "NOTFOUND")
    message(FATAL_ERROR "stats settings name ${unread}, which agaa-samples does not read")
  endif()
endforeach()
