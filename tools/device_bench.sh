#!/usr/bin/env bash
# Every GPU figure of docs/PERFORMANCE.md in one run, for a lent GPU machine whose minutes are few:
# tessellation cells against the ceiling, a forest in the tessellation bench, the walkthrough's tour and its
# 200-tree forest with leaves, leaves with self-shadowing, and wind. Each step has its own time limit, so one
# that hangs costs only its own minutes. Progress goes to stdout; everything lands in $OUT (a handful of files).
#   ARBOR=build/tools/arbor OUT=out/device bash tools/device_bench.sh [quick]
# (carry arbor-engine beside ARBOR: arbor hands it the render, view and bench commands)
# 'quick' runs each step small (a check on lavapipe that the script works before a GPU is spent on it).
set -u
arbor=${ARBOR:-build/tools/arbor}
out=${OUT:-out/device}
quick=${1:-}
mkdir -p "$out"
export ARBOR_ASSETS=${ARBOR_ASSETS:-$(cd "$(dirname "$0")/.." && pwd)/assets}
log="$out/log.txt"
: > "$log"

# step NAME LIMIT_S COMMAND...: runs one measurement into the shared log and says how it went.
step() {
  local name=$1 limit=$2
  shift 2
  local start=$SECONDS
  echo "== $name: $*" | tee -a "$log"
  timeout "$limit" "$@" >> "$log" 2>&1
  local rc=$?
  echo "== $name: exit $rc after $((SECONDS - start)) s" | tee -a "$log"
}

if [ "$quick" = quick ]; then
  frames=1 factors=1,4 adaptive=8 size=320x180 big=320x180 forest=3 view_frames=3 sub=2 counts=1000
else
  frames=5 factors=1,2,4,8,16,32,64 adaptive=8,4,2,1 size=1280x720 big=1920x1080 forest=200 view_frames=60 sub=8 counts=10000,50000,200000
fi

{ date -u; uname -a; nvidia-smi -L 2>/dev/null; "$arbor" --version; } | tee -a "$log"
step tess 200 "$arbor" bench tess black-tupelo --modes flat,pn,acc,acc+disp --factors "$factors" --adaptive "$adaptive" \
  --size "$size" --frames "$frames" --subdivide-up-to "$sub" --csv "$out/tess.csv" --plot "$out/tess.png"
step view-forest 100 "$arbor" view black-tupelo quaking-aspen ca-black-oak --forest "$forest" --offscreen \
  --frames "$view_frames" --size "$big" --out "$out/forest"
step view-tour 60 "$arbor" view --offscreen --frames "$view_frames" --size "$size" --out "$out/tour"
step tess-forest 120 "$arbor" bench tess --scene forest "$forest" --modes flat,acc --factors 1,4 --adaptive 8,4 \
  --size "$big" --frames "$frames" --no-ceiling --subdivide-up-to 0 --csv "$out/tess-forest.csv"
step leaves 60 "$arbor" bench leaves --size "$big" --frames "$frames" --counts "$counts" --csv "$out/leaves.csv"
for wind in 0 1; do
  step "wind-$wind" 45 "$arbor" render black-tupelo --frames 4 --size "$size" --wind "$wind" --out "${TMPDIR:-/tmp}/arbor-wind-$wind.png"
done
# The last frame of each walk is enough to see what was drawn; the PNG series stays behind.
for walk in tour forest; do
  last=$(ls "$out/$walk"/frame-*.png 2>/dev/null | tail -n 1)
  [ -n "$last" ] && mv "$last" "$out/$walk.png"
  rm -rf "${out:?}/$walk"
done
echo "device_bench: done; $(ls "$out" | tr '\n' ' ')"
