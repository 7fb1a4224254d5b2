#!/bin/sh
# Builds LAMMPS with the MACHDYN package (Smooth Mach Dynamics) from Debian's source
# package, serial, into DIR/build/lmp, for bench/lammps/compare.sh.
#   bench/lammps/build-lammps.sh [DIR]      (default /tmp/lammps-bench; needs deb-src
#                                            in the apt sources and libeigen3-dev)
# About 20-40 minutes on 2 cores.
set -eu
dir=${1:-/tmp/lammps-bench}
mkdir -p "$dir"
cd "$dir"
if ! ls -d lammps-*/ >/dev/null 2>&1; then
  apt-get source lammps || {
    echo "build-lammps.sh: 'apt-get source lammps' failed: add 'deb-src' to the Types of" \
      "/etc/apt/sources.list.d/debian.sources, run apt-get update, and install libeigen3-dev" >&2
    exit 2
  }
fi
src=$(ls -d lammps-*/ | head -n 1)
# BUILD_MPI off and MPI not searched: Debian's partial Open MPI install otherwise
# breaks the configure step.
cmake -S "$src/cmake" -B build -D CMAKE_BUILD_TYPE=Release -D BUILD_MPI=off \
  -D CMAKE_DISABLE_FIND_PACKAGE_MPI=ON -D BUILD_OMP=off -D PKG_MACHDYN=on \
  -D DOWNLOAD_EIGEN3=off -D CMAKE_CXX_FLAGS="-O3 -march=native"
cmake --build build -j "$(nproc)"
echo "LAMMPS: $dir/build/lmp"
