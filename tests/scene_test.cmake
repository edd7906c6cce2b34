# The one driver of glissade's scene tests (glissade_scene_test in
# tests/CMakeLists.txt; doc/design.md, "Tests"): runs the program on a
# scene and judges the run by its MODE.
#
#   RUN         exit 0; every COMPARE (an output file against a reference
#               under tests/reference, by numdiff) and every OUTPUT_MATCHES
#               (a regular expression the standard output must match).
#   FAILS       a non-zero exit and a message matching EXPECT, without a
#               stack trace or the expression parser's own diagnosis.
#   TWICE       two runs, every file written identical byte for byte.
#   RESTART     stopped after increment STOP and restarted: every file as
#               the uninterrupted run's; with MISTAKES, a changed scene and
#               a damaged checkpoint refused first.
#   SIGNAL      SIGTERM during a run: checkpoint, exit 5, restart
#               (restart_after_signal.sh: CMake cannot send a signal); with
#               PROCESSES, under mpirun, the factors out of core.
#   HELD        a run in an output directory another run holds is refused.
#   CHANGED_MESH  a restart after the mesh file changed is refused (MESH).
#   PARAMETERS  `glissade --print-parameters` equals the file INPUT.
#   PROCESSES   run on one process and under mpirun on PROCESSES: the same
#               figures (tests/compare_processes.py; with STATUSES, the
#               stick/slip statuses too; to TOLERANCE of each figure's
#               scale if given, else compare_processes.py's 1e-10). With
#               STOP, the run on PROCESSES
#               stops after increment STOP and is continued by --restart on
#               PROCESSES + 1 processes.
#   EMPTY_AFTER a directory that must exist and hold no file after the runs
#               (the factors' out-of-core files, removed at a run's end).
#
# Lists (ARGS, COMPARES, OUTPUT_MATCHES) come with "@@" between items. A
# COMPARE is three items: the output file (relative to the work folder),
# the reference (relative to tests/reference) and numdiff's options, where
# --columns=a,b keeps those CSV columns and --rows=REGEX the rows that match
# before comparing.
cmake_minimum_required(VERSION 3.16)
string(REPLACE "@@" ";" args "${ARGS}")

function(run_program directory expect_status)
  execute_process(COMMAND ${PROGRAM} ${INPUT} ${args} ${ARGN}
                  RESULT_VARIABLE status
                  OUTPUT_VARIABLE out
                  ERROR_VARIABLE err
                  WORKING_DIRECTORY ${directory})
  if(NOT "${expect_status}" STREQUAL "any" AND
     NOT status EQUAL ${expect_status})
    message(FATAL_ERROR "glissade ${ARGN}: exit ${status} (expected "
                        "${expect_status})\n${out}\n${err}")
  endif()
  set(last_status "${status}" PARENT_SCOPE)
  set(last_output "${out}" PARENT_SCOPE)
  set(last_error "${err}" PARENT_SCOPE)
endfunction()

# The columns `columns` (by header name) of the rows of a CSV file that
# match `rows` (the header kept), written to `output`.
function(select_csv input output columns rows)
  file(STRINGS ${input} lines)
  list(GET lines 0 header)
  string(REPLACE "," ";" names "${header}")
  set(indices "")
  if(NOT columns)
    set(columns ${names})
  endif()
  foreach(column ${columns})
    list(FIND names ${column} index)
    if(index EQUAL -1)
      message(FATAL_ERROR "${input} has no column '${column}' (${header})")
    endif()
    list(APPEND indices ${index})
  endforeach()
  set(text "")
  set(first TRUE)
  foreach(line ${lines})
    if(NOT first AND NOT "${rows}" STREQUAL "" AND NOT line MATCHES "${rows}")
      continue()
    endif()
    string(REPLACE "," ";" fields "${line}")
    set(kept "")
    foreach(index ${indices})
      list(GET fields ${index} field)
      list(APPEND kept "${field}")
    endforeach()
    string(REPLACE ";" "," kept "${kept}")
    string(APPEND text "${kept}\n")
    set(first FALSE)
  endforeach()
  file(WRITE ${output} "${text}")
endfunction()

function(compare_with_reference output reference options)
  separate_arguments(options UNIX_COMMAND "${options}")
  set(columns "")
  set(rows "")
  set(numdiff_options "")
  foreach(option ${options})
    if(option MATCHES "^--columns=(.*)$")
      string(REPLACE "," ";" columns "${CMAKE_MATCH_1}")
    elseif(option MATCHES "^--rows=(.*)$")
      set(rows "${CMAKE_MATCH_1}")
    else()
      list(APPEND numdiff_options "${option}")
    endif()
  endforeach()
  set(compared ${WORKDIR}/${output})
  if(NOT EXISTS ${compared})
    message(FATAL_ERROR "the run wrote no ${output}")
  endif()
  if(columns OR NOT "${rows}" STREQUAL "")
    get_filename_component(name ${output} NAME)
    set(compared ${WORKDIR}/compared_${name})
    select_csv(${WORKDIR}/${output} ${compared} "${columns}" "${rows}")
  endif()
  execute_process(COMMAND numdiff -s ", \\t\\n" ${numdiff_options}
                          ${REFERENCE_DIR}/${reference} ${compared}
                  RESULT_VARIABLE different
                  OUTPUT_VARIABLE report)
  if(different)
    message(FATAL_ERROR "${output} differs from tests/reference/${reference} "
                        "(numdiff ${numdiff_options}):\n${report}")
  endif()
  message("${output}: as tests/reference/${reference} "
          "(numdiff ${numdiff_options})")
endfunction()

# Every file two runs wrote identical (summary.txt and checkpoints carry
# wall times).
function(compare_runs first second what)
  file(GLOB_RECURSE files RELATIVE ${first} ${first}/*)
  list(REMOVE_ITEM files summary.txt checkpoint.bin)
  list(LENGTH files n)
  if(n EQUAL 0)
    message(FATAL_ERROR "the run wrote no files")
  endif()
  foreach(f ${files})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files
                            ${first}/${f} ${second}/${f}
                    RESULT_VARIABLE different)
    if(different)
      message(FATAL_ERROR "${f} differs between ${what}")
    endif()
  endforeach()
  message("${n} files identical between ${what}")
endfunction()

file(MAKE_DIRECTORY ${WORKDIR})

if(MODE STREQUAL "RUN")
  run_program(${WORKDIR} 0)
  message("${last_output}")
  string(REPLACE "@@" ";" compares "${COMPARES}")
  list(LENGTH compares n)
  if(n GREATER 0)
    math(EXPR last "${n} - 1")
    foreach(i RANGE 0 ${last} 3)
      math(EXPR j "${i} + 1")
      math(EXPR k "${i} + 2")
      list(GET compares ${i} output)
      list(GET compares ${j} reference)
      list(GET compares ${k} options)
      compare_with_reference(${output} ${reference} "${options}")
    endforeach()
  endif()
  string(REPLACE "@@" ";" patterns "${OUTPUT_MATCHES}")
  foreach(pattern ${patterns})
    if(NOT last_output MATCHES "${pattern}")
      message(FATAL_ERROR "the output does not match '${pattern}'")
    endif()
  endforeach()

elseif(MODE STREQUAL "FAILS")
  run_program(${WORKDIR} any)
  message("exit code: ${last_status}\nstderr: ${last_error}")
  if(last_status EQUAL 0)
    message(FATAL_ERROR "glissade accepted ${INPUT}")
  endif()
  if(NOT last_error MATCHES "${EXPECT}")
    message(FATAL_ERROR "the message does not match '${EXPECT}'")
  endif()
  if(last_error MATCHES "Stacktrace|An error occurred in line")
    message(FATAL_ERROR "the message leaks a deal.II stack trace")
  endif()
  # One message, not the expression parser's own diagnosis printed before.
  if(last_error MATCHES "Errc: +<")
    message(FATAL_ERROR "muparser's diagnosis is printed besides the message")
  endif()

elseif(MODE STREQUAL "TWICE")
  # The numbers must not depend on memory addresses, thread timing or
  # anything else that changes from run to run.
  foreach(run 1 2)
    file(REMOVE_RECURSE ${WORKDIR}/run${run})
    run_program(${WORKDIR} 0 --set "Output/Directory=${WORKDIR}/run${run}")
  endforeach()
  compare_runs(${WORKDIR}/run1 ${WORKDIR}/run2 "two runs of the same scene")

elseif(MODE STREQUAL "RESTART")
  file(REMOVE_RECURSE ${WORKDIR}/whole ${WORKDIR}/split ${WORKDIR}/damaged)
  run_program(${WORKDIR} 0 --set "Output/Directory=${WORKDIR}/whole")
  set(split --set "Output/Directory=${WORKDIR}/split")
  run_program(${WORKDIR} 0 ${split}
              --set "Checkpoint/Stop after increment=${STOP}")
  # The first part did stop: a history row per increment 0..STOP.
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
    # Neither refusal touches the checkpoint, so the restart still works.
    run_program(${WORKDIR} 2 ${split} --restart
                --set "Newton/Maximum iterations=24")
    if(NOT last_error MATCHES "checkpoint.bin: was written for another scene")
      message(FATAL_ERROR "unexpected message: ${last_error}")
    endif()
    file(WRITE ${WORKDIR}/damaged/checkpoint.bin "22 serialization::archive")
    run_program(${WORKDIR} 2 --set "Output/Directory=${WORKDIR}/damaged"
                --restart)
    if(NOT last_error MATCHES
       "checkpoint.bin: (is unreadable|is not a checkpoint)")
      message(FATAL_ERROR "unexpected message: ${last_error}")
    endif()
    message("refused: a changed scene and a damaged checkpoint")
  endif()
  run_program(${WORKDIR} 0 ${split} --restart)
  compare_runs(${WORKDIR}/whole ${WORKDIR}/split
               "the uninterrupted run and the run stopped after increment "
               "${STOP} and restarted")

elseif(MODE STREQUAL "SIGNAL")
  execute_process(COMMAND bash ${SOURCE_DIR}/tests/restart_after_signal.sh
                          ${PROGRAM} ${INPUT} ${WORKDIR} ${PROCESSES}
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "restart after SIGTERM failed")
  endif()

elseif(MODE STREQUAL "HELD")
  # flock(1) stands for the first run: it holds the lock a running
  # glissade holds. Once it is gone the same run goes through.
  file(REMOVE_RECURSE ${WORKDIR})
  file(MAKE_DIRECTORY ${WORKDIR})
  file(WRITE ${WORKDIR}/.glissade-lock "")
  execute_process(COMMAND flock ${WORKDIR}/.glissade-lock
                          ${PROGRAM} ${INPUT} --set "Output/Directory=${WORKDIR}"
                  RESULT_VARIABLE status
                  ERROR_VARIABLE err)
  message("held: exit code ${status}\n${err}")
  if(NOT status EQUAL 2)
    message(FATAL_ERROR "a second run in a held directory: exit ${status}, "
                        "expected 2")
  endif()
  if(NOT err MATCHES "Output/Directory: the output directory '.*' is in use by another glissade run")
    message(FATAL_ERROR "unexpected message")
  endif()
  if(EXISTS ${WORKDIR}/history.csv)
    message(FATAL_ERROR "the refused run wrote into the held directory")
  endif()
  run_program(${WORKDIR} 0 --set "Output/Directory=${WORKDIR}")

elseif(MODE STREQUAL "CHANGED_MESH")
  # The checkpoint's fingerprint covers the content of the files the scene
  # reads, not only its values: a copy of MESH, one node moved by 5 %.
  file(REMOVE_RECURSE ${WORKDIR})
  file(MAKE_DIRECTORY ${WORKDIR})
  file(COPY ${MESH} DESTINATION ${WORKDIR})
  get_filename_component(mesh_name ${MESH} NAME)
  set(common --set "Body plate/Mesh/File=${WORKDIR}/${mesh_name}"
      --set "Output/Directory=${WORKDIR}/out"
      --set "Load program/Stage increments=4")
  run_program(${WORKDIR} 0 ${common} --set "Checkpoint/Stop after increment=2")
  if(NOT EXISTS ${WORKDIR}/out/checkpoint.bin)
    message(FATAL_ERROR "the first half did not stop with a checkpoint")
  endif()
  file(READ ${WORKDIR}/${mesh_name} text)
  string(REPLACE "\n3 2 0 0\n" "\n3 2.1 0 0\n" moved "${text}")
  if(moved STREQUAL text)
    message(FATAL_ERROR "the test could not edit the mesh")
  endif()
  file(WRITE ${WORKDIR}/${mesh_name} "${moved}")
  run_program(${WORKDIR} 2 ${common} --restart)
  message("restart after the mesh changed:\n${last_error}")
  if(NOT last_error MATCHES "checkpoint.bin: was written for another scene: .*or a mesh file it reads has changed")
    message(FATAL_ERROR "the restart with a changed mesh was not refused")
  endif()

elseif(MODE STREQUAL "PARAMETERS")
  execute_process(COMMAND ${PROGRAM} --print-parameters
                  OUTPUT_VARIABLE printed RESULT_VARIABLE status)
  file(READ ${INPUT} reference)
  if(NOT status EQUAL 0 OR NOT printed STREQUAL reference)
    message(FATAL_ERROR "${INPUT} is out of date: regenerate it with "
                        "`glissade --print-parameters > doc/parameters.prm`")
  endif()

elseif(MODE STREQUAL "PROCESSES")
  file(REMOVE_RECURSE ${WORKDIR}/one ${WORKDIR}/many ${EMPTY_AFTER})
  file(MAKE_DIRECTORY ${WORKDIR})
  run_program(${WORKDIR} 0 --set "Output/Directory=${WORKDIR}/one")
  # (as root in CI's container: Open MPI asks to be told; more processes
  # than cores: allowed, they wait for each other; in a container the
  # kernel may refuse the cross-memory copy Open MPI tries first)
  set(ENV{OMPI_MCA_btl_vader_single_copy_mechanism} none)
  # (a process waiting for the others gives up its core rather than spin:
  # 3 processes share 2 cores here)
  set(ENV{OMPI_MCA_mpi_yield_when_idle} 1)
  function(run_on_processes n)
    execute_process(
      COMMAND ${MPIEXEC} --allow-run-as-root --oversubscribe -np ${n}
              ${PROGRAM} ${INPUT} ${args}
              --set "Output/Directory=${WORKDIR}/many" ${ARGN}
      RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err
      WORKING_DIRECTORY ${WORKDIR})
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "mpirun -np ${n} glissade ${ARGN}: exit ${status}"
                          "\n${out}\n${err}")
    endif()
  endfunction()
  if(STOP)
    run_on_processes(${PROCESSES}
      --set "Checkpoint/Stop after increment=${STOP}")
    math(EXPR more "${PROCESSES} + 1")
    run_on_processes(${more} --restart)
  else()
    run_on_processes(${PROCESSES})
  endif()
  if(EMPTY_AFTER)
    file(GLOB left_behind ${EMPTY_AFTER}/*)
    if(NOT IS_DIRECTORY ${EMPTY_AFTER} OR left_behind)
      message(FATAL_ERROR "${EMPTY_AFTER}: not made, or files left in it "
                          "after the run: ${left_behind}")
    endif()
  endif()
  set(statuses "")
  if(STATUSES)
    set(statuses --statuses)
  endif()
  set(tolerance "")
  if(TOLERANCE)
    set(tolerance --tolerance=${TOLERANCE})
  endif()
  execute_process(
    COMMAND ${PYTHON} ${SOURCE_DIR}/tests/compare_processes.py
            ${WORKDIR}/one ${WORKDIR}/many ${statuses} ${tolerance}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "1 and ${PROCESSES} processes disagree")
  endif()

else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
