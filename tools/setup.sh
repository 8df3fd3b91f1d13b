#!/usr/bin/env bash
# Installs every Debian 12 package the IG needs to build, run and test.
# Idempotent: only missing packages are installed; uses sudo when not root.
set -euo pipefail

packages=(
  # toolchain
  cmake g++ make pkg-config
  # libraries (found by CMake)
  libglfw3-dev libglm-dev libepoxy-dev libegl-dev libopenimageio-dev libgdal-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev zlib1g-dev
  libcli11-dev libgeographiclib-dev
  # the sun's position from date, time and place (ERFA: the IAU SOFA routines)
  liberfa-dev
  # the EGM96 geoid grid (terrain.vertical_datum "ellipsoid"; also pulled in by GDAL's PROJ)
  proj-data
  # headless OpenGL (Mesa llvmpipe through EGL) and the windowed path under Xvfb
  libegl-mesa0 libgl1-mesa-dri xvfb xauth
  # glTF 2.0 entity models (visual/models): TinyGLTF; the public glTF test corpus
  libtinygltf-dev assimp-testmodels
  # frame-time plots
  gnuplot-nox
  # test helpers (gdal_fillnodata.py: GDAL's own void fill, the reference for ours)
  python3 gdal-bin python3-gdal
  # fuzzing
  clang libclang-rt-14-dev
  # Modbus TCP status/control
  libmodbus-dev mbpoll
  # vcan integration tests: a small VM (the host kernel has no SocketCAN) with
  # Debian's kernel (fetched by the test harness), busybox, can-utils as a peer
  qemu-system-x86 busybox-static can-utils iproute2 xz-utils
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
