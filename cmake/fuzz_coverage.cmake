# libFuzzer's coverage for some targets only. The `fuzz` preset instruments everything
# through CMAKE_CXX_FLAGS; the `asan-ci` preset builds the fuzz targets beside the tests
# (scripts/test-all.sh, stage 4 runs them) and instruments only what they read: coverage
# counters and comparison tracing in the renderer's inner loops made the sanitized render
# tests about three times slower (docs/performance.md, "Test suite time").
set(LENSLAB_FUZZ_COVERAGE "" CACHE STRING
    "Layers of src/ (and `cli`, the command line) compiled with -fsanitize=fuzzer-no-link")
function(lenslab_fuzz_coverage target name)
    if(name IN_LIST LENSLAB_FUZZ_COVERAGE)
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
endfunction()
