# doc/parameters.prm must be what `glissade --print-parameters` prints.
execute_process(COMMAND ${PROGRAM} --print-parameters
                OUTPUT_VARIABLE printed RESULT_VARIABLE status)
file(READ ${REFERENCE} reference)
if(NOT status EQUAL 0 OR NOT printed STREQUAL reference)
  message(FATAL_ERROR "doc/parameters.prm is out of date: regenerate it with "
                      "`glissade --print-parameters > doc/parameters.prm`")
endif()
