#!/usr/bin/env bash
# The main job: set up, build, and run the default comparison ending in a report.
# Usage: bash harness/scripts/main.sh [points-file]   (a points file of your own is reconstructed too)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
curvebench_build

out="$CURVEBENCH_ROOT/out"
mkdir -p "$out"
curvebench="$CURVEBENCH_BUILD_DIR/harness/curvebench"

# A bundled generated example: 300 random samples of the rose r = 1 + 0.3 cos 5t.
"$CURVEBENCH_VENV/bin/python" - "$out/rose.xy" <<'PY'
import math, random, sys
rng = random.Random(5)
ts = sorted(rng.uniform(0, 2 * math.pi) for _ in range(300))
with open(sys.argv[1], "w") as f:
    f.write("# 300 random samples of r = 1 + 0.3 cos(5t), seed 5\n")
    for t in ts:
        r = 1 + 0.3 * math.cos(5 * t)
        f.write(f"{r * math.cos(t)!r} {r * math.sin(t)!r}\n")
PY
inputs=("$out/rose.xy")
[ $# -ge 1 ] && inputs+=("$1")
for input in "${inputs[@]}"; do
  name="$(basename "${input%.*}")"
  "$curvebench" reconstruct --algorithm labeling --input "$input" --output "$out/$name.labeling.json" --svg "$out/$name.labeling.svg"
  echo "wrote $out/$name.labeling.json and $out/$name.labeling.svg"
done
