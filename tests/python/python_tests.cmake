# Included from tests/CMakeLists.txt (also by the release stage's unsanitized-only build).
# The Python module (python/): Debian's pytest against the module and the `lenslab` binary of
# this build, which tests/python/conftest.py compares it with. Nothing is written to the
# source tree (no .pytest_cache, no __pycache__).
if(TARGET lenslab_python)
    add_test(NAME python.pytest
        COMMAND ${LENSLAB_PYTHON} -m pytest -q -p no:cacheprovider ${CMAKE_CURRENT_SOURCE_DIR}/python)
    set_tests_properties(python.pytest PROPERTIES TIMEOUT 300 LABELS python
        ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;LENSLAB_CLI=$<TARGET_FILE:lenslab>;PYTHONDONTWRITEBYTECODE=1")

    # The notebooks in examples/, executed as `jupyter nbconvert --execute` runs them (in
    # examples/), so they never rot. The executed copies and the figures they write go to
    # build/<preset>/tests/notebooks/NAME, never to the source tree.
    foreach(notebook singlet_bending prism_spectrum achromat_focal_shift caustic_animation)
        set(out ${CMAKE_CURRENT_BINARY_DIR}/notebooks/${notebook})
        file(MAKE_DIRECTORY ${out})
        add_test(NAME python.notebook.${notebook}
            COMMAND ${LENSLAB_PYTHON} -m nbconvert --to notebook --execute --output-dir ${out}
                    ${PROJECT_SOURCE_DIR}/examples/${notebook}.ipynb)
        set_tests_properties(python.notebook.${notebook} PROPERTIES TIMEOUT 120 LABELS python
            ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;LENSLAB_NOTEBOOK_OUT=${out};PYTHONDONTWRITEBYTECODE=1;PYDEVD_DISABLE_FILE_VALIDATION=1")
    endforeach()
endif()
