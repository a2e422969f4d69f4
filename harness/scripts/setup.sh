#!/usr/bin/env bash
# Installs what is missing and builds curvebench. Sourced by the main job and by the tests.
#   Debian packages: installed with apt-get when run as root, else the exact command is printed.
#   Python packages: into .venv from reports/requirements.txt (pinned), then the project's own
#   Python package `curvebench` (pyproject.toml), built in build/python/.
#   Build: CMake + Ninja into build/ (override with CURVEBENCH_BUILD_DIR).
set -euo pipefail

CURVEBENCH_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
CURVEBENCH_BUILD_DIR="${CURVEBENCH_BUILD_DIR:-$CURVEBENCH_ROOT/build}"
CURVEBENCH_VENV="$CURVEBENCH_ROOT/.venv"

curvebench_debian_packages=(g++ cmake ninja-build libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libbenchmark-dev nlohmann-json3-dev libcli11-dev googletest libgtest-dev libnanoflann-dev libeigen3-dev python3-dev)

curvebench_install_debian_packages() {
  local missing=()
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -eq 0 ]; then
    echo "setup: installing Debian packages: ${missing[*]}" >&2
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "setup: missing Debian packages; run: sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
}

# Headless Chromium and its WebDriver: only the tests need them (the report page is opened
# and screenshotted as a person would see it), so only the test command calls this.
curvebench_install_browser() {
  curvebench_install_debian_packages chromium chromium-driver
}

# Slurm and munge: only the tests need them (a single-node cluster on localhost runs a sweep as
# a job array: tests/python/test_slurm_cluster.py), so only the test command calls this.
curvebench_install_slurm() {
  curvebench_install_debian_packages slurm-wlm munge
}

curvebench_python_env() {
  local requirements="$CURVEBENCH_ROOT/reports/requirements.txt"
  local stamp="$CURVEBENCH_VENV/.requirements.sha256"
  local wanted
  wanted="$(sha256sum "$requirements" | cut -d' ' -f1)"
  if [ ! -x "$CURVEBENCH_VENV/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$wanted" ]; then
    echo "setup: installing Python packages into $CURVEBENCH_VENV" >&2
    python3 -m venv "$CURVEBENCH_VENV"
    "$CURVEBENCH_VENV/bin/pip" install --quiet --disable-pip-version-check -r "$requirements"
    echo "$wanted" > "$stamp"
  fi
}

# The package `curvebench` into .venv, built with the venv's pinned build tools (no build
# isolation, no dependencies fetched: only the pinned packages are used). Its build
# directory persists, so running the set-up again rebuilds only what changed; ccache, where
# present, is the compiler launcher.
curvebench_python_package() {
  local settings=(--config-settings=build-dir="$CURVEBENCH_BUILD_DIR/python/{wheel_tag}")
  if command -v ccache >/dev/null; then
    settings+=(--config-settings=cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  echo "setup: building the Python package curvebench into $CURVEBENCH_VENV" >&2
  "$CURVEBENCH_VENV/bin/pip" install --quiet --disable-pip-version-check --no-build-isolation --no-deps \
    "${settings[@]}" "$CURVEBENCH_ROOT" >&2
}

# curvebench_build [extra cmake arguments...]
curvebench_build() {
  cmake -S "$CURVEBENCH_ROOT" -B "$CURVEBENCH_BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  ninja -C "$CURVEBENCH_BUILD_DIR" >&2
}

curvebench_install_debian_packages "${curvebench_debian_packages[@]}"
curvebench_python_env
curvebench_python_package
