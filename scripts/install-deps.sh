#!/usr/bin/env bash
# Installs the Debian 12 packages Rays needs to build and test, only when some are missing.
# povray-includes holds POV-Ray's include files (colors.inc, textures.inc, ...), read by POV-Ray
# scenes at run time, fonts-povray the fonts of their text objects (timrom.ttf, ...); RAYS_TEST_DEPS=1 (scripts/test.sh) adds POV-Ray's example scenes, which
# the test suite reads through the language, and Open MPI, which the MPI render's tests run under (docs/mpi.md); RAYS_BENCH_DEPS=1 adds what the benchmarks compare with.
set -euo pipefail
packages=(cmake g++ make pkg-config libspng-dev zlib1g-dev libturbojpeg0-dev libstb-dev libtinyobjloader-dev
          libcli11-dev libgtest-dev libfreetype-dev libopenexr-dev povray-includes fonts-povray)
if [ "${RAYS_TEST_DEPS:-0}" = 1 ]; then
  packages+=(povray-examples libopenmpi-dev openmpi-bin)
fi
if [ "${RAYS_BENCH_DEPS:-0}" = 1 ]; then
  packages+=(libembree-dev libbenchmark-dev libopencv-dev povray povray-includes povray-examples fonts-povray hyperfine bc)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
