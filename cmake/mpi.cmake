# MPI (docs/cluster.md): one lenslab runs alone or as the ranks of an mpirun / srun job.
# LENSLAB_MPI: AUTO uses MPI when find_package finds it, ON requires it, OFF never uses it
# (the sanitizer and fuzz presets: their runtimes and Open MPI's do not mix well). Without
# MPI the program is the same and every job is one process (src/cluster/).
set(LENSLAB_MPI AUTO CACHE STRING "Use MPI for multi-process jobs: AUTO, ON or OFF")
set_property(CACHE LENSLAB_MPI PROPERTY STRINGS AUTO ON OFF)
string(TOUPPER "${LENSLAB_MPI}" lenslab_mpi_mode)
set(LENSLAB_WITH_MPI OFF)
if(lenslab_mpi_mode STREQUAL "ON" OR lenslab_mpi_mode STREQUAL "AUTO")
    # FindMPI's C component needs the C compiler; only the C API is used.
    enable_language(C)
    if(lenslab_mpi_mode STREQUAL "ON")
        find_package(MPI REQUIRED COMPONENTS C)
    else()
        find_package(MPI QUIET COMPONENTS C)
    endif()
    if(MPI_C_FOUND)
        set(LENSLAB_WITH_MPI ON)
    endif()
elseif(NOT lenslab_mpi_mode STREQUAL "OFF")
    message(FATAL_ERROR "LENSLAB_MPI is '${LENSLAB_MPI}': use AUTO, ON or OFF")
endif()
message(STATUS "lenslab: MPI ${LENSLAB_WITH_MPI} (LENSLAB_MPI=${LENSLAB_MPI})")
