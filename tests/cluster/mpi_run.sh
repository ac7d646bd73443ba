#!/usr/bin/env bash
# mpi_run.sh MPIRUN LENSLAB OUTDIR CASE: one cluster test (cluster_tests.cmake).
#   sppm, path, whitted, photon_map, detect: the output of `mpirun -np 2` and `-np 3` is
#     byte-identical (cmp) to one process's with the same seed.
#   sppm_time: a --time budget; every rank stops after the same pass (rank 0 decides).
#   tolerance: the triplet's tolerance report (JSON, a Monte Carlo of 3 chunks of trials
#     dealt across the ranks) on 2 and 3 ranks is byte-identical to one process's.
#   optimize: the Cooke exercise's global search (8 starts, a short polish) on 2 and 3 ranks
#     writes the scene one process writes and prints its report (but the output's name).
#   sweep: 6 frames on 3 ranks: each rank renders its 2 (rank 0 reports 2), the 6 frames and
#     the table equal one process's; run again, rank 0 finds its 2 done.
#   killed_rank, failing_rank: rank 1 dies (_exit) or throws mid-render; the job exits
#     non-zero, says so, and writes no image.
# Tiny renders (48x32) so each case takes about a second.
set -euo pipefail
mpirun=$1 lenslab=$2 out=$3 case=$4
rm -rf "$out" && mkdir -p "$out"

launch=("$mpirun" --oversubscribe)
# CI runs as root, which Open MPI refuses unless told.
[ "$(id -u)" = 0 ] && launch+=(--allow-run-as-root)
export OMPI_MCA_rmaps_base_oversubscribe=1
# Shared-memory transport only: the tests run on one machine, often in a container.
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none

fail() { echo "mpi_run.sh $case: $*" >&2; exit 1; }

# same_bytes EXT ARGS...: renders ARGS alone and on 2 and 3 ranks; compares the files.
same_bytes() {
    local ext=$1; shift
    "$lenslab" "$@" -o "$out/alone.$ext" -q --threads 2 >/dev/null
    for n in 2 3; do
        "${launch[@]}" -np $n "$lenslab" "$@" -o "$out/np$n.$ext" -q --threads 1 >/dev/null
        cmp "$out/alone.$ext" "$out/np$n.$ext" || fail "-np $n differs from one process"
    done
}

small=(--width 48 --height 32 --seed 7)
case $case in
    sppm)
        # 20000 photons a pass: 7 chunks of 4096 with the aimed ones, dealt to every rank.
        same_bytes exr render scenes/caustic_room.json --integrator sppm --passes 3 \
            --pass-photons 20000 "${small[@]}" ;;
    sppm_time)
        # A budget of a few passes: rank 0's clock decides, so the job ends and writes.
        "${launch[@]}" -np 2 "$lenslab" render scenes/caustic_room.json --integrator sppm \
            --passes 0 --time 0.5 "${small[@]}" -o "$out/time.png" --threads 1 \
            >"$out/stdout.txt" 2>"$out/stderr.txt" || fail "the timed job failed: $(cat "$out/stderr.txt")"
        [ -s "$out/time.png" ] || fail "no image"
        grep -q "passes" "$out/stdout.txt" || fail "no 'wrote' line: $(cat "$out/stdout.txt")" ;;
    path)
        same_bytes exr render scenes/caustic_room.json --integrator path --spp 2 "${small[@]}" ;;
    whitted)
        same_bytes exr render scenes/caustic_room.json --integrator whitted --spp 2 "${small[@]}" ;;
    photon_map)
        same_bytes exr render scenes/caustic_room.json --integrator photon_map --spp 1 \
            --photons 20000 "${small[@]}" ;;
    detect)
        "$lenslab" detect scenes/detector_focus.json --photons 100000 --seed 7 \
            -o "$out/alone" -q --threads 2 >/dev/null
        for n in 2 3; do
            "${launch[@]}" -np $n "$lenslab" detect scenes/detector_focus.json --photons 100000 \
                --seed 7 -o "$out/np$n" -q --threads 1 >/dev/null
            for f in "$out"/alone/*.csv "$out"/alone/*.exr; do
                cmp "$f" "$out/np$n/$(basename "$f")" || fail "-np $n: $(basename "$f") differs"
            done
        done ;;
    tolerance)
        tolerance=(tolerance examples/optimize/triplet.tolerance.json --trials 150 --json -q)
        "$lenslab" "${tolerance[@]}" >"$out/alone.json"
        for n in 2 3; do
            "${launch[@]}" -np $n "$lenslab" "${tolerance[@]}" >"$out/np$n.json"
            cmp "$out/alone.json" "$out/np$n.json" || fail "-np $n differs from one process"
        done ;;
    optimize)
        optimize=(optimize examples/optimize/cooke.design.json --global-starts 8 --iterations 20
                  --json -q)
        "$lenslab" "${optimize[@]}" -o "$out/alone.json" | grep -v '"output"' >"$out/alone.txt"
        for n in 2 3; do
            "${launch[@]}" -np $n "$lenslab" "${optimize[@]}" -o "$out/np$n.json" |
                grep -v '"output"' >"$out/np$n.txt"
            cmp "$out/alone.json" "$out/np$n.json" || fail "-np $n: the scene differs"
            cmp "$out/alone.txt" "$out/np$n.txt" || fail "-np $n: the report differs"
        done ;;
    sweep)
        sweep=(sweep scenes/lens_caustic.json --set /objects/1/center/1=1.5:3:6 --integrator whitted
               --spp 1 "${small[@]}" --threads 1)
        "$lenslab" "${sweep[@]}" -o "$out/alone" -q >/dev/null
        "${launch[@]}" -np 3 "$lenslab" "${sweep[@]}" -o "$out/np3" >"$out/stdout.txt" \
            2>"$out/stderr.txt" || fail "the sweep failed: $(cat "$out/stderr.txt")"
        [ "$(grep -c '^frame ' "$out/stderr.txt")" = 2 ] ||
            fail "rank 0 did not render 2 frames: $(cat "$out/stderr.txt")"
        [ "$(ls "$out/np3/frames" | wc -l)" = 6 ] || fail "not 6 frames: $(ls "$out/np3/frames")"
        for f in "$out"/alone/frames/*.png "$out/alone/sweep.json"; do
            cmp "$f" "$out/np3/${f#"$out"/alone/}" || fail "$(basename "$f") differs"
        done
        "${launch[@]}" -np 3 "$lenslab" "${sweep[@]}" -o "$out/np3" >"$out/again.txt" 2>&1
        grep -q "^skipped 2 of 2 frames" "$out/again.txt" ||
            fail "rank 0 did not find its 2 frames done: $(cat "$out/again.txt")" ;;
    killed_rank|failing_rank)
        if [ "$case" = killed_rank ]; then var=LENSLAB_TEST_KILL_RANK; else var=LENSLAB_TEST_FAIL_RANK; fi
        set +e
        env "$var=1" "${launch[@]}" -np 2 "$lenslab" render scenes/caustic_room.json \
            --integrator sppm --passes 3 "${small[@]}" -o "$out/image.png" --threads 1 \
            >"$out/stdout.txt" 2>"$out/stderr.txt"
        status=$?
        set -e
        [ "$status" != 0 ] || fail "the job exited 0"
        [ ! -e "$out/image.png" ] || fail "a partial image was written"
        [ "$(ls -A "$out")" = "$(printf 'stderr.txt\nstdout.txt')" ] ||
            fail "a file was left: $(ls -A "$out")"
        if [ "$case" = failing_rank ]; then
            grep -q "^lenslab: error (rank 1 of 2): rank 1 failed on purpose" "$out/stderr.txt" ||
                fail "no message from the failing rank: $(cat "$out/stderr.txt")"
        fi ;;
    *) fail "unknown case" ;;
esac
echo "mpi_run.sh $case: ok"
