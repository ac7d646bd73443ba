#!/usr/bin/env bash
# Installs everything lenslab needs to build and test, from Debian 12 packages only.
# Idempotent: when every package is already installed it returns in about a second.
set -euo pipefail

PACKAGES=(
    cmake ninja-build g++ ccache pkg-config
    libtbb-dev nlohmann-json3-dev libcli11-dev
    libpng-dev libopenexr-dev libfftw3-dev
    libnanoflann-dev libmuparser-dev libpcg-cpp-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    gnuplot-nox colord-data
    qt6-base-dev
    clang libclang-rt-14-dev llvm clang-format
    lld
    pybind11-dev python3-dev python3-numpy python3-pytest
    jupyter-nbconvert python3-nbformat python3-ipykernel python3-matplotlib ffmpeg
    libopenmpi-dev openmpi-bin
)
# libfftw3-dev: the FFTs of the diffraction PSF and MTF (src/analysis/diffraction/fft_grid.cpp).
# clang + libclang-rt-14-dev: libFuzzer and clang's sanitizers for the fuzz targets
# (scripts/fuzz.sh); llvm: llvm-symbolizer, so sanitizer reports name files and lines;
# clang-format: scripts/check-format.sh, the first thing the test suite checks; lld: the
# linker (cmake/build_speed.cmake), several times faster than GNU ld on the test executables.
# pybind11-dev, python3-dev, python3-numpy, python3-pytest: the `lenslab` Python module (python/) and its tests.
# jupyter-nbconvert: `jupyter nbconvert --execute`, which runs the notebooks in examples/ as tests.
# python3-nbformat: reads and writes the notebooks' .ipynb files.
# python3-ipykernel: the Python 3 kernel the notebooks execute in.
# python3-matplotlib: the notebooks' plots (Agg backend) and the caustic's animation.
# ffmpeg: the animation writer matplotlib uses for the caustic notebook's MP4.
# libopenmpi-dev, openmpi-bin: Open MPI and mpirun, for renders split across ranks (docs/cluster.md).

missing=()
for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
