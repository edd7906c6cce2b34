# Runs glissade twice on the same scene, in separate processes and output
# directories, and requires every file written to be identical, byte for
# byte: the numbers must not depend on memory addresses, thread timing or
# anything else that changes from run to run.
# SETS: the --set overrides, separated by |.
string(REPLACE "|" ";" sets "${SETS}")
set(extra "")
foreach(s ${sets})
  list(APPEND extra --set "${s}")
endforeach()
foreach(run 1 2)
  file(REMOVE_RECURSE ${WORKDIR}/run${run})
  execute_process(COMMAND ${PROGRAM} ${INPUT} ${extra}
                          --set "Output/Directory=${WORKDIR}/run${run}"
                  RESULT_VARIABLE status
                  OUTPUT_QUIET
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run ${run} failed: ${err}")
  endif()
endforeach()
file(GLOB_RECURSE files RELATIVE ${WORKDIR}/run1 ${WORKDIR}/run1/*)
# summary.txt reports wall times, which do change; the figures are in the
# history and the per-increment files.
list(REMOVE_ITEM files summary.txt)
list(LENGTH files n)
if(n EQUAL 0)
  message(FATAL_ERROR "the run wrote no files")
endif()
foreach(f ${files})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                          ${WORKDIR}/run1/${f} ${WORKDIR}/run2/${f}
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${f} differs between two runs of the same scene")
  endif()
endforeach()
message("${n} files identical between two runs")
