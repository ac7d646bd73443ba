# `cmake --install` puts the command line, the editor (when built), the glass catalogues, the
# scenes and the examples under a prefix: run as
#   cmake -DBUILD=<build dir> -DPREFIX=<empty dir> -DGUI=ON|OFF -P check_install.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install failed: ${err}")
endif()
set(expected bin/lenslab share/lenslab/glass share/lenslab/scenes/default.json
    share/lenslab/scenes/report_scene.json share/lenslab/examples/optimize/triplet.json)
if(GUI)
    list(APPEND expected bin/lenslab-gui)
endif()
foreach(f IN LISTS expected)
    if(NOT EXISTS ${PREFIX}/${f})
        message(FATAL_ERROR "cmake --install left out ${f}")
    endif()
endforeach()
message(STATUS "installed: ${expected}")
