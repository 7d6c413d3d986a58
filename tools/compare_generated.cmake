# cmake -DTOOL=... -DCOMMITTED=... -DFRESH=... -P compare_generated.cmake: runs TOOL FRESH and
# fails unless FRESH equals COMMITTED byte for byte, saying how to refresh the committed copy.
execute_process(COMMAND ${TOOL} ${FRESH} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${TOOL} failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${FRESH} ${COMMITTED} RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is not what the generator makes today; if the change is "
                      "intended, run: ${TOOL} ${COMMITTED}")
endif()
