#!/usr/bin/env bash
# Installs the Debian 12 packages hvsph needs to build, test and plot.
# Safe to run repeatedly: it only calls apt-get when something is missing.
#   tools/install-deps.sh          build + test dependencies
#   tools/install-deps.sh --docs   also python3-matplotlib/scipy for the doc plots
#                                  and study tools (tools/*.py)
#   tools/install-deps.sh --analyze   also clang-tools-14 (scan-build) for `make analyze`
set -euo pipefail
# git: the commit in the version baked into the binary and its outputs (cmake/version.cmake);
# unit.test_cli fails on "unknown". python3: tests/consistency/test_restart.sh.
# zlib1g-dev: checkpoints' CRC-32 and compressed snapshots (output.compress).
# python3-numpy, python3-meshio, python3-vtk9: unit.test_tool_readers reads the snapshots
# with meshio and vtk and runs docs/output-files.md's numpy recipe (skipped without them).
pkgs=(build-essential cmake pkg-config libfyaml-dev libpng-dev zlib1g-dev python3 git
      python3-numpy python3-meshio python3-vtk9)
for arg in "$@"; do
  case "$arg" in
    --docs) pkgs+=(python3-matplotlib python3-scipy) ;;
    --analyze) pkgs+=(clang-tools-14) ;;
    *) echo "install-deps: unknown option '$arg' (--docs, --analyze)" >&2; exit 1 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    echo "install-deps: not root: using sudo" >&2; SUDO=(sudo)
  else
    echo "install-deps: not root and no sudo: run as root (or install ${missing[*]})" >&2; exit 1
  fi
else SUDO=(); fi
# sudo drops the environment: DEBIAN_FRONTEND is passed on the command line
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
