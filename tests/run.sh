#!/usr/bin/env bash
# The test command: set up, build, run the GoogleTest suite and the pytest suite, then the
# GoogleTest suite again under AddressSanitizer + UndefinedBehaviorSanitizer and the libFuzzer
# targets for a bounded time (CURVEBENCH_FUZZ_SECONDS each, default 45; 0 skips the
# sanitizer and fuzzing stage).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../harness/scripts/setup.sh"
curvebench_install_debian_packages clang libclang-rt-14-dev
curvebench_install_browser
curvebench_install_slurm
curvebench_build -DCURVEBENCH_BENCHMARKS=ON

echo "== C++ tests (GoogleTest via ctest)"
ctest --test-dir "$CURVEBENCH_BUILD_DIR" --output-on-failure -j 2

echo "== Python tests (pytest)"
CURVEBENCH_BIN="$CURVEBENCH_BUILD_DIR/harness/curvebench" "$CURVEBENCH_VENV/bin/python" -m pytest -q "$CURVEBENCH_ROOT/tests/python"

fuzz_seconds="${CURVEBENCH_FUZZ_SECONDS:-45}"
[ "$fuzz_seconds" -gt 0 ] || exit 0
sanitize_dir="$CURVEBENCH_BUILD_DIR-sanitize"
echo "== C++ tests under ASan + UBSan (clang), and libFuzzer targets"
CC=clang CXX=clang++ cmake -S "$CURVEBENCH_ROOT" -B "$sanitize_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCURVEBENCH_SANITIZE=ON -DCURVEBENCH_FUZZ=ON -DCURVEBENCH_BENCHMARKS=OFF >/dev/null
ninja -C "$sanitize_dir" curvebench_tests fuzz_points_file fuzz_reconstruct >&2
ctest --test-dir "$sanitize_dir" --output-on-failure -j 2

for target in points_file reconstruct; do
  work="$(mktemp -d)"
  "$sanitize_dir/tests/fuzz/fuzz_$target" -max_total_time="$fuzz_seconds" -rss_limit_mb=4096 -print_final_stats=1 \
    "$work" "$CURVEBENCH_ROOT/tests/fuzz/corpus/$target" > "$work.log" 2>&1 || { tail -40 "$work.log"; exit 1; }
  echo "fuzz_$target: $(grep -o 'Done [0-9]* runs in [0-9]* second(s)' "$work.log"), no finding"
  rm -rf "$work" "$work.log"
done
