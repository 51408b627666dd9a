#!/usr/bin/env bash
# XML -> OBJ process wall time, Arbaro 1.9.9 against Arbor, for every Arbaro species file (same file, same
# seed, same machine; each the best of RUNS runs, one tool's after the other's for each file), with the CPU time
# (user + system) of those runs: on a virtual machine the same work's CPU time moves with the machine's state (Arbor's
# 0.32 to 0.62 s for the tupelo file in one evening), so a slow sitting shows as such. Arbaro is not packaged: build
# it from its public source (wdiestel/arbaro) with javac and point ARBARO_CLASSES at the classes folder.
# Usage: ARBARO_CLASSES=/path/to/classes [RUNS=3] tools/arbaro_speed.sh [SPECIES_DIR] [SEED]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
species="${1:-$root/../shared/arbaro-species}"
seed="${2:-1}"
arbor="$root/build/tools/arbor"
: "${ARBARO_CLASSES:?set ARBARO_CLASSES to the compiled classes of Arbaro 1.9.9 (javac of its src/)}"
command -v java >/dev/null || { echo "java is missing (apt-get install default-jre-headless)" >&2; exit 2; }
[ -x "$arbor" ] || { echo "$arbor is missing: run tools/build.sh first" >&2; exit 2; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# "wall cpu" of the faster of two runs given as "wall cpu".
faster() { awk -v x="$1" -v y="$2" 'BEGIN { split(x, p, " "); split(y, q, " "); print (p[1] < q[1]) ? x : y }'; }
# "wall cpu" seconds of one run, from bash's own clock: no process of its own inside the interval (date's start-up
# was a third of a small file's time).
seconds() { local TIMEFORMAT='%3R %3U %3S'; local t; t=$({ time "$@" >/dev/null 2>&1; } 2>&1); awk -v t="$t" 'BEGIN { split(t, v, " "); print v[1], v[2] + v[3] }'; }
printf '| file | Arbaro s | Arbor s | Arbaro / Arbor | Arbaro CPU s | Arbor CPU s | Arbaro OBJ MB | Arbor OBJ MB |\n'
printf '|---|---|---|---|---|---|---|---|\n'
for xml in "$species"/*.xml; do
  name="$(basename "$xml" .xml)"
  a="1e9 0"; b="1e9 0"
  # Each tool's runs back to back: right after the JVM (a gigabyte of heap) has exited, the kernel compacts memory
  # for Arbor's huge pages, which made Arbor's runs taken in turn with Arbaro's up to 1.6 times slower.
  for _ in $(seq "${RUNS:-3}"); do
    t=$(seconds java -cp "$ARBARO_CLASSES" net.sourceforge.arbaro.arbaro -q -s "$seed" -f OBJ -o "$out/$name-arbaro.obj" "$xml")
    a=$(faster "$t" "$a")
  done
  for _ in $(seq "${RUNS:-3}"); do
    t=$(seconds "$arbor" generate "$xml" --seed "$seed" --out "$out/$name-arbor.obj" --quiet)
    b=$(faster "$t" "$b")
  done
  printf '| %s | %.2f | %.3f | %.1f | %.2f | %.3f | %.1f | %.1f |\n' "$name" "${a% *}" "${b% *}" "$(echo "${a% *} / ${b% *}" | bc -l)" \
    "${a#* }" "${b#* }" "$(echo "$(stat -c %s "$out/$name-arbaro.obj") / 1048576" | bc -l)" \
    "$(echo "$(stat -c %s "$out/$name-arbor.obj") / 1048576" | bc -l)"
done
