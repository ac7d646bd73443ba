#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, the `fuzz` preset) and runs them all at once for a
# bounded time. Exit status 0 only when none found anything.
#
#   scripts/fuzz.sh [SECONDS]      (default 60)
#
# SECONDS is the wall time of the whole run, whatever the number of targets: every target
# runs for SECONDS, all at the same time. With more targets than cores they share the cores
# (CI's 2 cores and 4 targets: scene, formula, obj, argv each get about half a core), so
# adding a target does not lengthen the CI stage; it splits the same CPU time more ways.
# (Before the third target, fuzz_obj, there was one target per core and SECONDS read "per
# target"; the stage took the same time.)
#
# Seeds: tests/fuzz/corpus/<target> and tests/fuzz/regressions/<target> (read only). Inputs
# found in this run go to build/fuzz/corpus/<target>; a crash, hang, leak or huge allocation
# is written to build/fuzz/findings/<target>/ -- copy it into tests/fuzz/regressions/<target>/
# when fixing it, so the replay test (test_fuzz_replay) keeps it fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

targets=(scene formula obj argv)
# Per target: the longest input tried. A scene needs room; formulas stay at 1024 characters
# (muparser compiles long ones slowly under the sanitizers, and the 4096-character limit is
# a plain length check, tested in test_scene_limits); 8192 bytes of OBJ are a few hundred
# statements, past the fuzz entry point's small limits (fuzz/fuzz_inputs.cpp); 1024 bytes
# of command line are dozens of options, more than any command takes.
declare -A max_len=([scene]=16384 [formula]=1024 [obj]=8192 [argv]=1024)
pids=()
for target in "${targets[@]}"; do
    work="build/fuzz/corpus/$target"
    findings="build/fuzz/findings/$target"
    mkdir -p "$work" "$findings"
    # -timeout: one input taking longer is a hang; -rss_limit_mb (also the malloc limit):
    # one allocation or a process above it is a finding.
    "build/fuzz/fuzz/fuzz_$target" "$work" "tests/fuzz/corpus/$target" "tests/fuzz/regressions/$target" \
        -dict="fuzz/$target.dict" -max_len="${max_len[$target]}" -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$findings/" >"build/fuzz/$target.log" 2>&1 &
    pids+=($!)
done

status=0
i=0
for target in "${targets[@]}"; do
    if wait "${pids[$i]}"; then result="clean"; else result="FOUND A PROBLEM"; status=1; fi
    echo "---- fuzz_$target: $result (log: build/fuzz/$target.log)"
    # The summary lines: executions, speed, coverage; everything on a failure.
    if [ "$result" = "clean" ]; then
        grep -E "^(#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::average_exec_per_sec|stat::new_units_added|stat::peak_rss_mb|INFO: seed corpus)" \
            "build/fuzz/$target.log" || true
    else
        tail -n 60 "build/fuzz/$target.log"
        ls -l "build/fuzz/findings/$target/"
    fi
    i=$((i + 1))
done
exit $status
