# A host's scene becomes goldens through the documented path (tests/README.md, "A host's scenes"):
# a glTF of the host's and a case file, written into the host's own folder by
# tools/update-goldens.sh, then compared by the same test binary; an image that no longer matches
# fails it, and a bad case file is refused with its file, line and field.
#   cmake -DROOT=... -DBUILD=... -DSCENEGEN=... -DGOLDEN=... -DWORK=... -P host_scene.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/host")
execute_process(COMMAND "${SCENEGEN}" --kind default --out "${WORK}/host/scene.gltf" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "scenegen failed (${rc})")
endif()
file(WRITE "${WORK}/host/cases.txt" "# the host's own goldens\nscene box scene.gltf 32\ncase agaa 8 2\ncase reference 8\n")

function(run_checked what expect_rc)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${expect_rc}\n${out}\n${err}")
  endif()
  set(out "${out}${err}" PARENT_SCOPE)
endfunction()

set(ENV{AGAA_GOLDEN_HOST_CASES} "${WORK}/host/cases.txt")
set(ENV{AGAA_BUILD_DIR} "${BUILD}")
run_checked("update-goldens.sh" 0 "${ROOT}/tools/update-goldens.sh")
if(NOT out MATCHES "2 new")
  message(FATAL_ERROR "update-goldens.sh did not write the host's two goldens:\n${out}")
endif()
foreach(stem box/agaa-n8-c2 box/reference-n8)
  if(NOT EXISTS "${WORK}/host/goldens/${stem}.exr" OR NOT EXISTS "${WORK}/host/goldens/${stem}.png")
    message(FATAL_ERROR "${WORK}/host/goldens/${stem}.{exr,png} missing")
  endif()
endforeach()
if(EXISTS "${ROOT}/tests/golden/images/box")
  message(FATAL_ERROR "a host's golden went into tests/golden/images")
endif()

run_checked("test_golden on the host's goldens" 0 "${GOLDEN}")
string(REGEX MATCHALL "differ \\([0-9]+ ms\\) PASS" passes "${out}")
list(LENGTH passes n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected 2 passing host goldens, saw ${n}:\n${out}")
endif()

# A change the golden must catch: the AGAA image replaced by the reference's.
file(COPY_FILE "${WORK}/host/goldens/box/reference-n8.exr" "${WORK}/host/goldens/box/agaa-n8-c2.exr")
run_checked("test_golden after a golden changed" 1 "${GOLDEN}")
if(NOT out MATCHES "box/agaa-n8-c2 differs from its golden")
  message(FATAL_ERROR "the changed host golden did not fail:\n${out}")
endif()

# A bad case file: its file, line and field, exit 2.
file(WRITE "${WORK}/host/cases.txt" "scene box scene.gltf 32\ncase agaa 64\n")
run_checked("test_golden with a bad case file" 2 "${GOLDEN}")
if(NOT out MATCHES "cases.txt:2: SAMPLES '64' is not a whole number in 1..32")
  message(FATAL_ERROR "the bad case file's message does not name its line and field:\n${out}")
endif()
