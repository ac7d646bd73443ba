# Renders split across MPI ranks (mpirun on this machine) against one process: the same
# bytes; a rank that dies or fails ends the job with no output. Included from
# tests/CMakeLists.txt; only in a build with MPI (cmake/mpi.cmake). Test names: cluster.mpi.*
if(NOT LENSLAB_WITH_MPI)
    return()
endif()
find_program(LENSLAB_MPIRUN NAMES mpirun mpiexec)
if(NOT LENSLAB_MPIRUN)
    message(STATUS "lenslab: no mpirun, so no cluster.mpi tests")
    return()
endif()
foreach(case sppm sppm_time path whitted photon_map detect sweep tolerance optimize killed_rank failing_rank)
    add_test(NAME cluster.mpi.${case}
        COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/mpi_run.sh ${LENSLAB_MPIRUN}
                $<TARGET_FILE:lenslab> ${CMAKE_CURRENT_BINARY_DIR}/cluster_out/${case} ${case}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(cluster.mpi.${case} PROPERTIES TIMEOUT 120 LABELS "cluster")
endforeach()
