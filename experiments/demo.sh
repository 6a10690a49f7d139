#!/usr/bin/env bash
# The main job on the embedded collection (datasets/*.off): for every mesh,
# feature points and f_q (JSON + colored PLY + a PNG figure) in results/demo/.
# Usage: experiments/demo.sh BUILD_DIR   (bash tools/run demo calls it)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-$root/build}
reeb=$build/tools/reeb
out=$root/results/demo
mkdir -p "$out"

echo "== reeb features on the embedded collection -> $out"
printf '%-10s %8s %8s %9s %10s\n' mesh vertices faces features time_ms
for mesh in "$root"/datasets/*.off; do
  name=$(basename "$mesh" .off)
  "$reeb" features "$mesh" -o "$out/$name.features.json" --ply "$out/$name.fq.ply" > "$out/$name.log"
  /usr/bin/python3 - "$out/$name.features.json" "$name" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))["components"][0]
t = d["timings_ms"]
print(f'{sys.argv[2]:<10} {d["vertices"]:>8} {d["triangles"]:>8} {len(d["feature_points"]):>9} '
      f'{t["graph"] + t["features"] + t["quotient"]:>10.2f}')
PY
  /usr/bin/python3 "$root/tools/figures/render_mesh.py" "$out/$name.fq.ply" "$out/$name.fq.png" \
    --title "$name: f_q and feature points"
done
echo "== figures: $out/*.fq.png (f_q in viridis, feature points in red)"
