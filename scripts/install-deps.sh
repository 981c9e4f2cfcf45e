#!/usr/bin/env bash
# Installs the Debian packages tide needs to build, test and benchmark. Idempotent and
# quiet when everything is present.
set -euo pipefail

# build: compiler, CMake, GLM, JSON, CLI11, tinyobjloader (OBJ obstacle meshes), Highway (SIMD
# with run-time dispatch), kissfft (the ocean's FFT grid), OpenVDB (the obj format's surface meshes; with TBB, Imath and Boost's
# headers, which its headers use); tests: GoogleTest,
# meshio (reads our VTU frames), jsonschema (checks scenes against their schema), script (a
# pseudo-terminal); benchmarks: Google Benchmark.
# Viewer and `tide render`: GLFW, GLEW, Dear ImGui (with its GLFW/OpenGL3 backends) and stb (PNG,
# ImGui's fonts); GL through Mesa (GLX for windows, EGL headless; llvmpipe, no GPU needed);
# ffmpeg for `tide render --video`; the viewer's test: Xvfb and xwd (x11-apps).
# `make check-sanitizers`: clang with its sanitizer and libFuzzer runtimes (libclang-rt-14-dev),
# LLVM's OpenMP (libomp-dev, whose Archer tool makes TSan understand OpenMP), llvm-symbolizer (llvm).
# The Python module (`import tide`): pybind11, Python's headers, numpy; its tests: pytest; its
# examples: matplotlib.
# Running a scene on several processes (`mpirun -np N tide run`, src/comm/): Open MPI.
packages=(cmake make g++ libglm-dev libkissfft-dev nlohmann-json3-dev libcli11-dev libtinyobjloader-dev libhwy-dev
          libopenvdb-dev libtbb-dev libimath-dev libboost-dev libgtest-dev libgmock-dev
          libbenchmark-dev python3-meshio python3-jsonschema bsdutils
          libglfw3-dev libglew-dev libimgui-dev libstb-dev libegl-dev libegl-mesa0 libglx-mesa0 libgl1-mesa-dri
          ffmpeg xvfb x11-apps
          clang libclang-rt-14-dev libomp-dev llvm
          python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib
          libopenmpi-dev openmpi-bin)

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  sudo=""
elif command -v sudo >/dev/null 2>&1; then
  sudo="sudo"
else
  echo "tide: missing Debian packages: ${missing[*]} (run as root or install them yourself)" >&2
  exit 1
fi
echo "tide: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
