#!/usr/bin/env bash
# The main job: set up, build, run the default comparison and a short scaling benchmark, and
# write the report (HTML page and figures); prints the page's path at the end.
#
# Usage: bash harness/scripts/main.sh [FILE ...]
#   FILE.json  a sweep configuration (harness/configs/ shows the format) run instead of
#              harness/configs/default.json
#   any other  a points file of your own, reconstructed by every algorithm and shown in the
#              report's gallery beside the bundled shapes
# Everything goes to out/ (override with CURVEBENCH_OUT): results.jsonl, scaling.json,
# gallery/ (points files and reconstruction JSONs) and report/index.html.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

config="$CURVEBENCH_ROOT/harness/configs/default.json"
own_points=()
for argument in "$@"; do
  [ -f "$argument" ] || { echo "main: $argument: no such file" >&2; exit 1; }
  case "$argument" in
    *.json) config="$(realpath "$argument")" ;;
    *) own_points+=("$(realpath "$argument")") ;;
  esac
done

started=$SECONDS
step() { echo "== [$((SECONDS - started)) s] $*" >&2; }

step "build (curvebench, curvebench_benchmark)"
cmake -S "$CURVEBENCH_ROOT" -B "$CURVEBENCH_BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCURVEBENCH_BENCHMARKS=ON >/dev/null
ninja -C "$CURVEBENCH_BUILD_DIR" curvebench curvebench_benchmark >&2
curvebench="$CURVEBENCH_BUILD_DIR/harness/curvebench"
benchmark="$CURVEBENCH_BUILD_DIR/harness/bench/curvebench_benchmark"

out="${CURVEBENCH_OUT:-$CURVEBENCH_ROOT/out}"
mkdir -p "$out"
rm -rf "$out/results.jsonl" "$out/results.jsonl.inputs" "$out/results-outlines.jsonl" "$out/results-outlines.jsonl.inputs" "$out/gallery" "$out/report"

step "sweep $config"
"$curvebench" sweep "$config" --out "$out/results.jsonl" --jobs 2

# Figure 16 on real outlines: glyphs of the DejaVu font matplotlib ships, made here, never
# stored in the repository. The config names them relative to the repository root.
if [ "$config" = "$CURVEBENCH_ROOT/harness/configs/default.json" ]; then
  step "real outlines (DejaVu Sans glyphs) and their sweep"
  (cd "$CURVEBENCH_ROOT" && "$CURVEBENCH_VENV/bin/python" generators/real_outlines.py glyphs --out out/outlines >/dev/null &&
    "$curvebench" sweep harness/configs/main_outlines.json --out "$out/results-outlines.jsonl" --jobs 2)
  cat "$out/results-outlines.jsonl" >> "$out/results.jsonl"
  rm -f "$out/results-outlines.jsonl"
fi

# Short: n = 10^3 ... 10^5, and a run predicted to take over 2 s is skipped (its row says so).
# The full suite: curvebench_benchmark --max_n=10000000 (see harness/bench/scaling_benchmark.cpp).
step "scaling benchmark (short)"
"$benchmark" --max_n=100000 --max_run_seconds=2 --benchmark_min_time=0.05 \
  --benchmark_out="$out/scaling.json" --benchmark_out_format=json >&2

step "gallery reconstructions"
mkdir -p "$out/gallery"
gallery_shape() {  # name, then `curvebench generate` options
  local name="$1"
  shift
  "$curvebench" generate "$@" --points "$out/gallery/$name.xy" >/dev/null
}
gallery_shape rose --family rose --epsilon 0.3 --seed 2
gallery_shape three-curves --family disjoint --epsilon 0.25 --seed 3
gallery_shape star --family star --epsilon 0.2 --seed 1
gallery_shape concavities --family concavities --epsilon 0.25 --seed 1
gallery_shape noisy-ellipse --family ellipse --epsilon 0.15 --noise 0.05 --seed 1
gallery_shape rose-20pct-outliers --family rose --epsilon 0.2 --outliers 0.2 --seed 4
for points in "${own_points[@]}"; do
  cp "$points" "$out/gallery/"
done
# The configuration's external algorithms (if it declares any) are catalogued and drawn too.
"$curvebench" list --json --external "$config" > "$out/catalogue.json"
algorithms=$("$curvebench" list --external "$config" | grep -v '^ ')
for points in "$out"/gallery/*; do
  for algorithm in $algorithms; do
    # A failed reconstruction still writes its error record, which the gallery shows; the SVG
    # beside the JSON is the full-size picture the report links.
    name="$out/gallery/$(basename "${points%.*}").$algorithm"
    "$curvebench" reconstruct --external "$config" --algorithm "$algorithm" --input "$points" \
      --output "$name.json" --svg "$name.svg" 2>/dev/null || true
  done
done

step "report"
page=$(PYTHONPATH="$CURVEBENCH_ROOT" "$CURVEBENCH_VENV/bin/python" -m reports --out "$out/report" \
  --results "$out/results.jsonl" --benchmark "$out/scaling.json" --reconstructions "$out/gallery" \
  --catalogue "$out/catalogue.json")
step "done"
echo "$page"
