#!/usr/bin/env bash
# Ctrl-C during `lenslab render` (docs/reliability.md): the render stops within a moment,
# exits 130 saying nothing was written, and leaves neither the image nor a temporary file.
# Interrupted twice: while tracing photons, and while rendering pixels.
#
#   interrupt_render.sh LENSLAB OUT_DIR
#
# The 3 s bound is a responsiveness check, not a speed test: cancellation is polled per
# pixel and per 4096 photons, so it takes milliseconds; 3 s leaves room for a loaded machine
# and sanitizer builds.
set -u
lenslab="$1"
out_dir="$2"
mkdir -p "$out_dir"
status=0

now_us() { echo "${EPOCHREALTIME/./}"; }

# interrupt NAME WAIT ARGS...: starts the render, waits until WAIT is true, sends SIGINT.
interrupt() {
    local name="$1" wait_for="$2"
    shift 2
    local out="$out_dir/$name.png" err="$out_dir/$name.err"
    rm -f "$out_dir/$name".*
    "$lenslab" render -o "$out" "$@" 2>"$err" &
    local pid=$!
    eval "$wait_for"
    local t0
    t0=$(now_us)
    kill -INT "$pid"
    wait "$pid"
    local rc=$?
    local ms=$((($(now_us) - t0) / 1000))
    local problems=""
    [ "$rc" -eq 130 ] || problems+=" exit code $rc (expected 130);"
    grep -q "render cancelled; nothing written" "$err" || problems+=" no 'render cancelled' message;"
    [ "$ms" -lt 3000 ] || problems+=" took $ms ms to stop;"
    local left
    left=$(ls -A "$out_dir" | grep -e "$name.png" -e "^\.lenslab-" || true)
    [ -z "$left" ] || problems+=" left files: $left;"
    if [ -n "$problems" ]; then
        echo "FAIL $name:$problems"
        cat "$err"
        status=1
    else
        echo "ok   $name: stopped $ms ms after SIGINT, exit 130, nothing written"
    fi
}

# Photon tracing: 8 million photons (aimed at the glass) take seconds; interrupt after one.
interrupt photons "sleep 1" --integrator photon_map --caustic-photons 8000000 --width 64 --height 48 --spp 1 --threads 2
# Pixels: wait for the first progress line, printed once the first tile is done (few samples
# per pixel, so it comes soon; many pixels, so the render is still far from done).
interrupt pixels 'for i in $(seq 600); do grep -q rendering "$err" && break; sleep 0.05; done' \
    --integrator whitted --width 3200 --height 2400 --spp 16 --threads 2
exit $status
