# Build time: the whole test suite (scripts/test-all.sh) builds the project three times on
# two cores, so compile and link time is most of its budget (docs/performance.md, "Test
# suite time"). Nothing here changes what is compiled, only how fast.

# Precompiled headers (opt-in, OFF by default): json, GoogleTest and Qt's widget headers
# compiled once per build and shared (REUSE_FROM) by the targets with the same flags.
# Measured on the CI machine (docs/performance.md, "Test suite time") they do not pay: GCC's
# precompiled header is a 100-130 MB image whose loading costs about as much CPU time as
# parsing json.hpp does (2-4 s), and it is loaded by every file, json or not; clang's showed
# no difference either. Kept so the measurement can be repeated (-DLENSLAB_PCH=ON).
option(LENSLAB_PCH "Precompile the heavy third-party headers (json, GoogleTest, Qt)" OFF)

set(LENSLAB_PCH_STD <algorithm> <cmath> <cstdint> <functional> <memory> <optional> <sstream>
    <string> <string_view> <vector>)

# The core library's set: json and the standard headers most files use.
function(lenslab_precompile_core target)
    if(LENSLAB_PCH)
        target_precompile_headers(${target} PRIVATE <nlohmann/json.hpp> ${LENSLAB_PCH_STD})
    endif()
endfunction()

# The GoogleTest suites' set: the core set plus gtest.
function(lenslab_precompile_tests target)
    if(LENSLAB_PCH)
        target_precompile_headers(${target} PRIVATE <gtest/gtest.h> <nlohmann/json.hpp> ${LENSLAB_PCH_STD})
    endif()
endfunction()

# The editor's set: the Qt headers most of its files use (and <QtTest> for its tests) plus
# the core set. Unlike the others it pays (every file of the editor includes Qt's widgets:
# main_window.cpp 24.4 s of CPU without, 20.5 s with), so it has an option of its own, ON.
# Used by the editor's library and its tests, not by lenslab-gui's main.cpp: GCC takes a
# precompiled header only with the macros it was made with.
option(LENSLAB_PCH_QT "Precompile Qt's headers for the editor and its tests" ON)
set(LENSLAB_PCH_QT_HEADERS <QApplication> <QComboBox> <QDockWidget> <QDoubleSpinBox> <QFormLayout>
    <QHBoxLayout> <QImage> <QLabel> <QLineEdit> <QMainWindow> <QPainter> <QPushButton>
    <QSpinBox> <QString> <QTimer> <QVBoxLayout> <QWidget>)
function(lenslab_precompile_qt target)
    if(LENSLAB_PCH OR LENSLAB_PCH_QT)
        target_precompile_headers(${target} PRIVATE ${LENSLAB_PCH_QT_HEADERS} ${ARGN} <nlohmann/json.hpp> ${LENSLAB_PCH_STD})
    endif()
endfunction()

# Use another target's precompiled header: same compiler flags, and every macro the header
# was made with defined the same way (GCC ignores it otherwise; with -Werror, an error).
function(lenslab_reuse_pch target from)
    if(LENSLAB_PCH)
        target_precompile_headers(${target} REUSE_FROM ${from})
    endif()
endfunction()

# Optimisation of the code that only drives the library: the test suites (always) and, where a
# preset asks, the two apps. Their run time is the library's, compiled as the build type says,
# so compiling them at -O0 costs the tests little and halves their compile time (GCC 12, one
# unity batch of the scene tests: -O3 35 s, -O0 16 s; with ASan and UBSan, -O1 72 s, -O0 33 s;
# docs/performance.md, "Test suite time"). The flag comes after the build type's, so it wins.
set(LENSLAB_TEST_OPTIMIZE "-O0" CACHE STRING "Optimisation flag for the test suites' own code (empty: the build type's)")
# Sanitizers of the tests' own code: asan-ci gives -fno-sanitize=undefined, so UBSan checks the
# library, the command line and the editor, which the tests drive, and ASan everything. UBSan's
# checks on every arithmetic operation of unoptimised test code made its compile about half as
# long again (one unity batch of the scene tests, asan-ci: 25.6 s of CPU with both, 19.6 s
# with ASan alone; docs/performance.md, "Test suite time").
set(LENSLAB_TEST_SANITIZE "" CACHE STRING "Extra sanitizer flags for the test suites' own code")
set(LENSLAB_APP_OPTIMIZE "" CACHE STRING "Optimisation flag for the command line's and the editor's own code (empty: the build type's)")
function(lenslab_optimize_test target)
    target_compile_options(${target} PRIVATE ${LENSLAB_TEST_OPTIMIZE} ${LENSLAB_TEST_SANITIZE})
endfunction()
function(lenslab_optimize_app target)
    target_compile_options(${target} PRIVATE ${LENSLAB_APP_OPTIMIZE})
endfunction()

# Linking: lld (Debian package lld, scripts/install-deps.sh) links the sanitized test
# executables several times faster than GNU ld. Used when the compiler accepts it.
option(LENSLAB_LLD "Link with lld when it is installed" ON)
if(LENSLAB_LLD)
    include(CheckLinkerFlag)
    check_linker_flag(CXX "-fuse-ld=lld" LENSLAB_HAVE_LLD)
    if(LENSLAB_HAVE_LLD)
        add_link_options(-fuse-ld=lld)
    endif()
endif()

# Unity builds for the library and the command-line tool: each batch of neighbouring sources
# is one translation unit, so json's and the standard library's headers are parsed once per
# batch. Measured (docs/performance.md, "Test suite time"): the library, the CLI and the bench
# harness take 212 s of CPU instead of 539 s (release, gcc). The cost: editing one source
# recompiles its batch; -DLENSLAB_UNITY=OFF goes back to one object per file while iterating.
# Helpers at file scope (anonymous namespaces, statics) must have file-specific names.
option(LENSLAB_UNITY "Compile the library and the command-line tool as unity builds" ON)
set(LENSLAB_UNITY_BATCH 32 CACHE STRING "Sources per unity batch of the library and the CLI")
function(lenslab_unity target)
    if(LENSLAB_UNITY)
        set_target_properties(${target} PROPERTIES
            UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${LENSLAB_UNITY_BATCH})
    endif()
endfunction()
