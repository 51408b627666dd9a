#!/usr/bin/env bash
# Self-intersection counts (arbor check) of every preset and Arbaro species file at seeds 1-3, as the
# markdown table docs/mesh.md keeps. Usage: tools/check_all.sh [SPECIES_DIR]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
species="${1:-$root/../shared/arbaro-species}"
arbor="${ARBOR:-$root/build/tools/arbor}"  # ARBOR: another build to compare
[ -x "$arbor" ] || { echo "$arbor is missing: run tools/build.sh first" >&2; exit 2; }
json="$(mktemp)"
trap 'rm -f "$json"' EXIT
inputs=$("$arbor" species --list | awk '/^presets/ {p = 1; next} p && /^  / {print $1}')
inputs="$inputs $(ls "$species"/*.xml 2>/dev/null || true)"
echo "| species (seeds 1 / 2 / 3) | quads | mesh-made | skeleton-made | folds | neck crossings | necks through their parent | mesh-made at shallow joints |"
echo "|---|---|---|---|---|---|---|---|"
for input in $inputs; do
  row=()
  for seed in 1 2 3; do
    "$arbor" check "$input" --seed "$seed" --json "$json" >/dev/null 2>&1 || [ $? -eq 1 ]
    row+=("$(python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['quads'], d['meshMade'], d['skeletonMade'], d['folds'], d['neckCrossings'], d['necksThroughParent'], d['meshMadeAtShallowJoints'])" "$json")")
  done
  python3 - "$(basename "$input")" "${row[@]}" <<'PY'
import sys
name, rows = sys.argv[1], [r.split() for r in sys.argv[2:]]
print("| " + name + " | " + " | ".join(" / ".join(r[i] for r in rows) for i in range(7)) + " |")
PY
done
