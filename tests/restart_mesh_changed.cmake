# A restart after the mesh file changed is refused: the checkpoint's
# fingerprint covers the content of the files the scene reads, not only
# its values. The scene is a copy of tests/input/malformed_mesh.prm's plate
# on tests/data/plate_2x1.msh, in WORKDIR.
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
file(COPY ${MESH} DESTINATION ${WORKDIR})
get_filename_component(mesh_name ${MESH} NAME)
set(common ${INPUT} --set "Body plate/Mesh/File=${WORKDIR}/${mesh_name}"
    --set "Output/Directory=${WORKDIR}/out" --set "Load program/Stage increments=4")
execute_process(COMMAND ${PROGRAM} ${common}
                        --set "Checkpoint/Stop after increment=2"
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0 OR NOT EXISTS ${WORKDIR}/out/checkpoint.bin)
  message(FATAL_ERROR "the first half did not stop with a checkpoint (${status})")
endif()
# Move one node of the mesh by 5 %.
file(READ ${WORKDIR}/${mesh_name} text)
string(REPLACE "\n3 2 0 0\n" "\n3 2.1 0 0\n" moved "${text}")
if(moved STREQUAL text)
  message(FATAL_ERROR "the test could not edit the mesh")
endif()
file(WRITE ${WORKDIR}/${mesh_name} "${moved}")
execute_process(COMMAND ${PROGRAM} ${common} --restart
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
message("restart after the mesh changed: exit ${status}\n${err}")
if(NOT status EQUAL 2 OR NOT err MATCHES "checkpoint.bin: was written for another scene: .*or a mesh file it reads has changed")
  message(FATAL_ERROR "the restart with a changed mesh was not refused")
endif()
