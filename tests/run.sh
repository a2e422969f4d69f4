#!/usr/bin/env bash
# The test command: set up, build, run the GoogleTest suite and the pytest suite.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../harness/scripts/setup.sh"
curvebench_build -DCURVEBENCH_BENCHMARKS=ON

echo "== C++ tests (GoogleTest via ctest)"
ctest --test-dir "$CURVEBENCH_BUILD_DIR" --output-on-failure -j 2

echo "== Python tests (pytest)"
CURVEBENCH_BIN="$CURVEBENCH_BUILD_DIR/harness/curvebench" "$CURVEBENCH_VENV/bin/python" -m pytest -q "$CURVEBENCH_ROOT/tests/python"
