# A second run in an output directory that another run holds is refused
# (exit code 2, a message naming the directory); once the holder is gone
# the same run goes through. flock(1) stands for the first run: it holds
# the same lock a running glissade holds.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
file(WRITE ${WORKDIR}/.glissade-lock "")
execute_process(COMMAND flock ${WORKDIR}/.glissade-lock
                        ${PROGRAM} ${INPUT} --set "Output/Directory=${WORKDIR}"
                RESULT_VARIABLE status
                ERROR_VARIABLE err)
message("held: exit code ${status}\n${err}")
if(NOT status EQUAL 2)
  message(FATAL_ERROR "a second run in a held directory: exit ${status}, expected 2")
endif()
if(NOT err MATCHES "Output/Directory: the output directory '.*directory_in_use' is in use by another glissade run")
  message(FATAL_ERROR "unexpected message")
endif()
if(EXISTS ${WORKDIR}/history.csv)
  message(FATAL_ERROR "the refused run wrote into the held directory")
endif()
execute_process(COMMAND ${PROGRAM} ${INPUT} --set "Output/Directory=${WORKDIR}"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the run in the released directory: exit ${status}")
endif()
