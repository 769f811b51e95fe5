#!/usr/bin/env bash
# Whole-process time of `curvescan render` against `rsvg-convert` (librsvg on Cairo) on the same documents,
# reported as ratios of mean wall times measured by hyperfine (warm cache, 1 warm-up run, 3 timed runs). Goal: >= 2x.
#
# Documents: the Ghostscript tiger (read from ../shared/bench/tiger.svg beside the checkout, or $TIGER, never committed), at
# zoom 1 and 4, and generated ones with 10^4, 10^5 and 10^6 path segments (seeded, so every run draws the
# same document) of translucent closed paths of random lines and cubics over a 1024 x 1024 canvas: many
# small shapes (10^4, 10^5, 10^6 segments) and one tangle of large self-intersecting paths (10^4).
#
# usage: bench/render_bench.sh BUILD_DIR     (BUILD_DIR/tools/curvescan must exist; Release build advised)
set -euo pipefail
build_dir=${1:?usage: render_bench.sh BUILD_DIR}
curvescan="$build_dir/tools/curvescan"
tiger=${TIGER:-$(cd "$(dirname "$0")/../.." && pwd)/shared/bench/tiger.svg}
command -v hyperfine >/dev/null || { echo "hyperfine is needed (Debian package hyperfine)" >&2; exit 1; }
command -v rsvg-convert >/dev/null || { echo "rsvg-convert is needed (Debian package librsvg2-bin)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

generate() {  # segments style output; style "shapes": segments/20 small closed shapes of 20 segments each
  # (map- or chart-like data); style "tangle": 100 large self-intersecting random walks (a stress case:
  # every segment crosses many others).
  python3 - "$1" "$2" "$3" <<'PY'
import random, sys
segments, style, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
random.seed(20261121)
per_path = 20 if style == "shapes" else max(1, segments // 100)
paths = max(1, segments // per_path)
reach = 12.0 if style == "shapes" else 60.0
lines = ['<svg xmlns="http://www.w3.org/2000/svg" width="1024" height="1024">']
for p in range(paths):
    x, y = random.uniform(0, 1024), random.uniform(0, 1024)
    d = [f"M{x:.2f} {y:.2f}"]
    cx, cy = x, y
    for s in range(per_path):
        step = lambda v, c: min(1024.0, max(0.0, (c if style == "shapes" else v) + random.uniform(-reach, reach)))
        if s % 2:
            d.append(f"L{step(x, cx):.2f} {step(y, cy):.2f}")
        else:
            d.append("C" + " ".join(f"{step(x, cx):.2f} {step(y, cy):.2f}" for _ in range(3)))
    colour = "#%06x" % random.randrange(1 << 24)
    lines.append(f'<path d="{" ".join(d)}Z" fill="{colour}" fill-opacity="0.5" fill-rule="evenodd"/>')
lines.append("</svg>")
open(out, "w").write("\n".join(lines))
PY
}

cases=()
if [ -f "$tiger" ]; then
  cases+=("tiger|$tiger|-z 1" "tiger-x4|$tiger|-z 4")
else
  echo "note: $tiger not found, tiger skipped" >&2
fi
for n in 10000 100000 1000000; do
  generate "$n" shapes "$work/shapes$n.svg"
  cases+=("shapes-$n|$work/shapes$n.svg|-z 1")
done
generate 10000 tangle "$work/tangle10000.svg"
cases+=("tangle-10000|$work/tangle10000.svg|-z 1")

printf '%-18s %14s %14s %8s\n' document curvescan_ms rsvg_ms ratio
for entry in "${cases[@]}"; do
  IFS='|' read -r name file zoom <<<"$entry"
  hyperfine --warmup 1 --runs 3 --export-json "$work/$name.json" \
    -n curvescan "$curvescan render $zoom $file -o $work/c.png" \
    -n rsvg "rsvg-convert $zoom $file -o $work/r.png" >/dev/null
  python3 - "$work/$name.json" "$name" <<'PY'
import json, sys
results = {r["command"]: r["mean"] for r in json.load(open(sys.argv[1]))["results"]}
c, r = results["curvescan"] * 1000, results["rsvg"] * 1000
print(f"{sys.argv[2]:<18} {c:14.1f} {r:14.1f} {r / c:7.2f}x")
PY
done
