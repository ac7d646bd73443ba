#!/usr/bin/env bash
# Builds the libFuzzer targets (clang) and runs them all at once for a bounded time. Exit
# status 0 only when none found anything.
#
#   scripts/fuzz.sh [SECONDS] [PRESET]      (defaults: 60, fuzz)
#
# PRESET: `fuzz` (every layer with libFuzzer's coverage, for long runs) or `asan-ci`, where
# the targets are built beside the sanitized tests with coverage only in the layers they read
# (CI's stage 4, after stage 2 built them: scripts/test-all.sh).
#
# SECONDS is the wall time of the whole run, whatever the number of targets: every target
# runs for SECONDS, all at the same time. With more targets than cores they share the cores
# (CI's 2 cores and 4 targets: scene, formula, obj, argv each get about half a core), so
# adding a target does not lengthen the CI stage; it splits the same CPU time more ways.
#
# Seeds: tests/fuzz/corpus/<target> and tests/fuzz/regressions/<target> (read only). Inputs
# found in this run go to build/PRESET/fuzz-run/corpus/<target>; a crash, hang, leak or huge
# allocation is written to build/PRESET/fuzz-run/findings/<target>/ -- copy it into
# tests/fuzz/regressions/<target>/ when fixing it, so the replay test (test_fuzz_replay) keeps
# it fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
preset="${2:-fuzz}"
build="build/$preset"
run="$build/fuzz-run"

cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" --target fuzz_scene fuzz_formula fuzz_obj fuzz_argv

targets=(scene formula obj argv)
# Per target: the longest input tried. A scene needs room; formulas stay at 1024 characters
# (muparser compiles long ones slowly under the sanitizers, and the 4096-character limit is
# a plain length check, tested in test_scene_limits); 8192 bytes of OBJ are a few hundred
# statements, past the fuzz entry point's small limits (fuzz/fuzz_inputs.cpp); 1024 bytes
# of command line are dozens of options, more than any command takes.
declare -A max_len=([scene]=16384 [formula]=1024 [obj]=8192 [argv]=1024)
pids=()
for target in "${targets[@]}"; do
    work="$run/corpus/$target"
    findings="$run/findings/$target"
    mkdir -p "$work" "$findings"
    # -timeout: one input taking longer is a hang; -rss_limit_mb (also the malloc limit):
    # one allocation or a process above it is a finding.
    "$build/fuzz/fuzz_$target" "$work" "tests/fuzz/corpus/$target" "tests/fuzz/regressions/$target" \
        -dict="fuzz/$target.dict" -max_len="${max_len[$target]}" -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$findings/" >"$run/$target.log" 2>&1 &
    pids+=($!)
done

status=0
i=0
for target in "${targets[@]}"; do
    if wait "${pids[$i]}"; then result="clean"; else result="FOUND A PROBLEM"; status=1; fi
    echo "---- fuzz_$target: $result (log: $run/$target.log)"
    # The summary lines: executions, speed, coverage; everything on a failure.
    if [ "$result" = "clean" ]; then
        grep -E "^(#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::average_exec_per_sec|stat::new_units_added|stat::peak_rss_mb|INFO: seed corpus)" \
            "$run/$target.log" || true
    else
        tail -n 60 "$run/$target.log"
        ls -l "$run/findings/$target/"
    fi
    i=$((i + 1))
done
exit $status
