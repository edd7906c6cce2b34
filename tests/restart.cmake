# Stops a run half-way (Checkpoint/Stop after increment), restarts it from
# its checkpoint, and requires every file it ends with to be identical, byte
# for byte, to those of an uninterrupted run of the same scene.
# SETS: the --set overrides, separated by |; STOP: the increment to stop
# after; N_TOTAL: the increments of the whole run. With MISTAKES, also
# checks that a restart refuses a changed scene and a damaged checkpoint.
string(REPLACE "|" ";" sets "${SETS}")
set(extra "")
foreach(s ${sets})
  list(APPEND extra --set "${s}")
endforeach()

function(run_glissade directory expect_status)
  execute_process(COMMAND ${PROGRAM} ${INPUT} ${extra}
                          --set "Output/Directory=${directory}" ${ARGN}
                  RESULT_VARIABLE status
                  OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT status EQUAL ${expect_status})
    message(FATAL_ERROR "glissade ${ARGN}: exit ${status} (expected "
                        "${expect_status})\n${out}\n${err}")
  endif()
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORKDIR}/whole ${WORKDIR}/split)
run_glissade(${WORKDIR}/whole 0)
run_glissade(${WORKDIR}/split 0 --set "Checkpoint/Stop after increment=${STOP}")

# The first half did stop: a history row per increment 0..STOP, and no
# output of the last increment yet.
file(STRINGS ${WORKDIR}/split/history.csv rows)
list(LENGTH rows n_rows)
math(EXPR expected_rows "${STOP} + 2")
if(NOT n_rows EQUAL expected_rows)
  message(FATAL_ERROR "the stopped run has ${n_rows} history lines, "
                      "expected ${expected_rows}")
endif()
if(NOT EXISTS ${WORKDIR}/split/checkpoint.bin)
  message(FATAL_ERROR "the stopped run wrote no checkpoint")
endif()

if(MISTAKES)
  # A changed scene is refused, and so is a damaged checkpoint; neither
  # touches the checkpoint, so the restart below still works.
  run_glissade(${WORKDIR}/split 2 --restart
               --set "Newton/Maximum iterations=24")
  if(NOT last_error MATCHES "checkpoint.bin: was written for another scene")
    message(FATAL_ERROR "unexpected message: ${last_error}")
  endif()
  file(REMOVE_RECURSE ${WORKDIR}/damaged)
  file(WRITE ${WORKDIR}/damaged/checkpoint.bin "22 serialization::archive")
  run_glissade(${WORKDIR}/damaged 2 --restart)
  if(NOT last_error MATCHES "checkpoint.bin: (is unreadable|is not a checkpoint)")
    message(FATAL_ERROR "unexpected message: ${last_error}")
  endif()
  message("refused: a changed scene and a damaged checkpoint")
endif()

run_glissade(${WORKDIR}/split 0 --restart)

file(GLOB_RECURSE files RELATIVE ${WORKDIR}/whole ${WORKDIR}/whole/*)
# summary.txt and the checkpoints carry wall times.
list(REMOVE_ITEM files summary.txt checkpoint.bin)
list(LENGTH files n)
foreach(f ${files})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                          ${WORKDIR}/whole/${f} ${WORKDIR}/split/${f}
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "${f} differs between the uninterrupted run and "
                        "the run restarted after increment ${STOP}")
  endif()
endforeach()
message("${n} files identical between the uninterrupted run and the run "
        "stopped after increment ${STOP} and restarted")
