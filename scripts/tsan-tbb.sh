#!/usr/bin/env bash
# oneTBB built with ThreadSanitizer, for the tsan preset (scripts/test-all.sh, stage 3).
#
# Debian's libtbb is not instrumented: ThreadSanitizer then cannot see the hand-over between a
# parallel_for's tasks and the thread that waits for them, and reports every write a task made
# as a race with the read after the loop (about 80 reports for a ten-line parallel_for). So the
# stage builds TBB itself, from Debian's own source package of the libtbb-dev it installs
# (apt-get source onetbb), with TBB's TBB_SANITIZE=thread, into build/tsan-tbb/install, which
# the tsan preset finds first (CMAKE_PREFIX_PATH). Idempotent: with the library in place it
# returns at once. About 40 s on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."

dir=$PWD/build/tsan-tbb
if [ -f "$dir/install/lib/cmake/TBB/TBBConfig.cmake" ]; then exit 0; fi
mkdir -p "$dir"

# The source package: Debian's deb-src index, added beside the binary one the machine has.
list=/etc/apt/sources.list.d/lenslab-deb-src.sources
if ! ls "$dir"/onetbb_*.orig.tar.* >/dev/null 2>&1; then
    if [ ! -f "$list" ]; then
        SUDO=""
        if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
        suite=$(. /etc/os-release && echo "$VERSION_CODENAME")
        printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
            "$suite" | $SUDO tee "$list" >/dev/null
        $SUDO apt-get update -qq
    fi
    (cd "$dir" && apt-get source --download-only -qq onetbb 2>&1 | grep -v '^W: Download is performed unsandboxed' || true)
fi
archive=$(ls "$dir"/onetbb_*.orig.tar.* | head -1)
rm -rf "$dir/src" && mkdir -p "$dir/src"
tar xf "$archive" -C "$dir/src" --strip-components=1

cmake -S "$dir/src" -B "$dir/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DTBB_SANITIZE=thread -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF \
    -DTBBMALLOC_BUILD=OFF -DCMAKE_INSTALL_PREFIX="$dir/install" >"$dir/configure.log"
cmake --build "$dir/build" -j2 >"$dir/build.log"
cmake --install "$dir/build" >/dev/null
echo "tsan-tbb: oneTBB with ThreadSanitizer in $dir/install"
