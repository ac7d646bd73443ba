#!/usr/bin/env bash
# The whole test suite, as CI runs it (README, second command; .ci/run): first the C++
# files' formatting (scripts/check-format.sh, seconds), then
#   1. release build (release-unsanitized preset: build/release-unsanitized; the library at
#      -O3 as released, the command line's own code at -O0, as in stage 2; the Python module,
#      MPI and the benchmarks) + the tests stage 2 cannot run: the Python module's (pytest,
#      the notebooks), the MPI ranks' and the statistical render checks (too slow
#      sanitized). Every other test runs in stage 2 only: running it here too doubled its
#      compile and run time and checked nothing more (`ctest --preset release-ci` still runs
#      them all unsanitized);
#   2. AddressSanitizer + UndefinedBehaviorSanitizer build, compiled by clang (asan-ci
#      preset: the library at -O1, tests and apps at -O0, the tests' own code with ASan but
#      not UBSan; the editor and the libFuzzer targets included, no benchmarks) + every test
#      but the statistical render checks, each GoogleTest suite as 4 shards.
#      The editor is built and its QTest suites run here only: compiling Qt's headers twice
#      was about a quarter of stage 1's build (docs/performance.md, "Test suite time");
#   3. ThreadSanitizer build (tsan preset: oneTBB built instrumented by scripts/tsan-tbb.sh,
#      only the suites with threaded tests) + the threaded tests: renders at several thread
#      counts and their cancellation, detectors, the optimiser, the editor's render
#      controller, detector and optimiser threads (docs/reliability.md);
#   4. the libFuzzer targets stage 2 built, all at once for 60 s (scripts/fuzz.sh). They were
#      a fourth build of the library (clang, coverage everywhere) until stage 2 moved to clang
#      with coverage in the layers the targets read: one build of the library fewer.
# Stages 1 and 3 compile with GCC and stage 2 with clang, so both compilers' warnings fail
# the run (-Werror).
# Each stage prints a banner and its time; the first failure stops the run.
#
#   scripts/test-all.sh [--fuzz-seconds N]
set -euo pipefail
cd "$(dirname "$0")/.."

fuzz_seconds=60
if [ "${1:-}" = "--fuzz-seconds" ]; then fuzz_seconds="$2"; fi

start_all=$SECONDS
stage_start=$SECONDS
banner() {
    stage_start=$SECONDS
    printf '\n==== %s ====\n' "$1"
}
finished() {
    printf '==== %s: finished clean in %d s ====\n' "$1" $((SECONDS - stage_start))
}

# UBSan: stop at the first report and say where; ASan: also report leaks.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"

scripts/check-format.sh

banner "stage 1/4: release build and the tests only it runs (Python, MPI, convergence)"
cmake --preset release-unsanitized
cmake --build --preset release-unsanitized
ctest --preset release-unsanitized
finished "stage 1/4: release build and the tests only it runs (Python, MPI, convergence)"

banner "stage 2/4: AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake --preset asan-ci
cmake --build --preset asan-ci
# The preset skips the statistical render checks (LENSLAB_RELEASE_ONLY_TESTS: tens of seconds
# under ASan).
ctest --preset asan-ci
finished "stage 2/4: AddressSanitizer + UndefinedBehaviorSanitizer build and tests"

banner "stage 3/4: ThreadSanitizer build and the threaded tests"
scripts/tsan-tbb.sh
cmake --preset tsan
cmake --build --preset tsan
ctest --preset tsan
finished "stage 3/4: ThreadSanitizer build and the threaded tests"

banner "stage 4/4: libFuzzer runs, the four targets at once, ${fuzz_seconds} s"
scripts/fuzz.sh "$fuzz_seconds" asan-ci
finished "stage 4/4: libFuzzer runs, the four targets at once, ${fuzz_seconds} s"

printf '\n==== all stages finished clean in %d s ====\n' $((SECONDS - start_all))
