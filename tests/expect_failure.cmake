# Runs glissade on a bad input and checks that it stops with a non-zero exit
# code and a message matching EXPECTED (a regular expression).
string(REPLACE "|" ";" extra "${EXTRA}")
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${PROGRAM} ${INPUT} ${extra}
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err
                WORKING_DIRECTORY ${WORKDIR})
message("exit code: ${status}\nstderr: ${err}")
if(status EQUAL 0)
  message(FATAL_ERROR "glissade accepted ${INPUT}")
endif()
if(NOT err MATCHES "${EXPECTED}")
  message(FATAL_ERROR "the message does not match '${EXPECTED}'")
endif()
if(err MATCHES "Stacktrace|An error occurred in line")
  message(FATAL_ERROR "the message leaks a deal.II stack trace")
endif()
# One message, not the expression parser's own diagnosis printed before it.
if(err MATCHES "Errc: +<")
  message(FATAL_ERROR "muparser's diagnosis is printed besides the message")
endif()
