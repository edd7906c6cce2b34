# The trade study on small sweeps of every measure. Besides running every
# path of the driver, it checks the Q4 rates the driver fits against
# references that do not come from the code:
# - geometric gap: a chord of angle pi/n misses the circle by
#   R (1 - cos(pi/2n)), so the error goes like n^-2;
# - geometric normal: at a facet's end the normal is off by pi/2n, so n^-1;
# - Table 1: Q4's displacement error in bending goes like h^2 (n^-2, a
#   little less on these coarse meshes: the clamp's corners);
# - cases 1, 2 and 3: refining Q4 must reduce the error (a negative rate).
string(REPLACE "|" ";" extra "${EXTRA}")
execute_process(COMMAND ${PROGRAM} ${INPUT} ${extra}
                RESULT_VARIABLE status
                OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}\n${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the trade study failed (exit ${status})")
endif()
# The fitted rates, in the order of the measures.
string(REGEX MATCHALL "Q4 over the sweep: error ~ n\\^[-0-9.e]+" rates "${out}")
list(LENGTH rates count)
if(NOT count EQUAL 6)
  message(FATAL_ERROR "expected 6 fitted Q4 rates, found ${count}: ${rates}")
endif()
set(expected
  "n\\^-(1\\.99[0-9]*|2|2\\.00[0-9]*)$"   # geometric gap: 2
  "n\\^-(0\\.99[0-9]*|1|1\\.00[0-9]*)$"   # geometric normal: 1
  "n\\^-(1\\.[6-9][0-9]*|2|2\\.0[0-9]*)$" # Table 1: 1.6-2.1
  "n\\^-[0-9.]+$"                          # case 1: negative
  "n\\^-[0-9.]+$"                          # case 2: negative
  "n\\^-[0-9.]+$")                         # case 3: negative
foreach(i RANGE 5)
  list(GET rates ${i} rate)
  list(GET expected ${i} pattern)
  if(NOT rate MATCHES "${pattern}")
    message(FATAL_ERROR "rate ${i}: '${rate}' does not match '${pattern}'")
  endif()
endforeach()
foreach(measure geometric_gap geometric_normal table1 case1 case2 case3)
  if(NOT EXISTS "${OUTDIR}/trade_${measure}.csv")
    message(FATAL_ERROR "no trade_${measure}.csv")
  endif()
endforeach()
