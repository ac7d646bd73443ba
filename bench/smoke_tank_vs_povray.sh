#!/usr/bin/env bash
# lenslab and POV-Ray 3.7 on the smoke tank (scenes/smoke_tank.json, bench/smoke_tank.pov),
# alternately, in one run: the wall time of each whole process (scene read, photons, render,
# PNG written) and the two pictures, for docs/performance.md.
# Usage: bench/smoke_tank_vs_povray.sh LENSLAB OUT_DIR [WIDTH HEIGHT PASSES REPEATS]
set -euo pipefail
lenslab=${1:?path to the lenslab executable}
out=${2:?output folder}
width=${3:-480}
height=${4:-270}
passes=${5:-64}
repeats=${6:-1}
here=$(cd "$(dirname "$0")/.." && pwd)
command -v povray >/dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 1; }
mkdir -p "$out"
seconds() { local t0=$EPOCHREALTIME; "$@" >/dev/null 2>&1; awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }
for ((i = 1; i <= repeats; ++i)); do
    l=$(seconds "$lenslab" render "$here/scenes/smoke_tank.json" --width "$width" --height "$height" \
        --passes "$passes" --threads 2 -q -o "$out/smoke_tank_lenslab.png")
    p=$(seconds povray "$here/bench/smoke_tank.pov" +W"$width" +H"$height" -D +WT2 \
        +O"$out/smoke_tank_povray.png")
    echo "run $i: lenslab ${l} s, POV-Ray ${p} s ($(cut -d' ' -f1 /proc/loadavg) load)"
done
