#!/usr/bin/env bash
# Each preset beside Arbaro's own render of the species file it comes from, seed 1, whole tree from the side:
# docs/images/arbaro-vs-arbor-PRESET.png (docs/generator.md shows them).
#
#   ARBARO_CLASSES=/tmp/arbaro/classes tools/arbaro_compare.sh [PRESET ...]
#
# Left: tools/arbaro_render.sh (Arbaro 1.9.9's POV-Ray export rendered by povray, orthographic). Right: `arbor
# render` with leaves (ACC, adaptive), its camera far away with an 8-degree field of view (nearly orthographic) on
# the tree's nodes and leaves, from -y as Arbaro's is seen. Environment: ARBOR (default build/tools/arbor),
# ARBARO_SPECIES (default ../shared/arbaro-species), OUT (default docs/images). Needs java, povray and python3
# with Pillow (apt-get install -y povray python3-pil).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
arbor="${ARBOR:-$root/build/tools/arbor}"
species_dir="${ARBARO_SPECIES:-$root/../shared/arbaro-species}"
out="${OUT:-$root/docs/images}"
width=400 height=500

declare -A file=([black-tupelo]=black_tupelo [ca-black-oak]=ca_black_oak [lombardy-poplar]=lombardy_poplar
  [palm]=palm [quaking-aspen]=quaking_aspen [weeping-willow]=weeping_willow)
presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(black-tupelo ca-black-oak lombardy-poplar palm quaking-aspen weeping-willow)

# Pillow: the python3 on PATH, else Debian's (python3-pil), which a pyenv python3 on PATH does not see.
python=python3
python3 -c "import PIL" 2> /dev/null || python=/usr/bin/python3
"$python" -c "import PIL" 2> /dev/null || { echo "arbaro_compare: Pillow is missing (apt-get install -y python3-pil)" >&2; exit 1; }
[ -x "$arbor" ] || { echo "arbaro_compare: no $arbor (build first, or set ARBOR)" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
for preset in "${presets[@]}"; do
  xml="${file[$preset]:-}"
  [ -n "$xml" ] || { echo "arbaro_compare: no Arbaro file known for preset $preset" >&2; exit 2; }
  bash "$root/tools/arbaro_render.sh" -s 1 -W "$width" -H "$height" "$species_dir/$xml.xml" "$tmp/arbaro.png" 2> "$tmp/arbaro.log" ||
    { cat "$tmp/arbaro.log" >&2; exit 1; }
  "$arbor" generate "$preset" --seed 1 --quiet --out "$tmp/skeleton.json"
  camera="$("$python" "$root/tools/arbaro_compare.py" camera "$tmp/skeleton.json" "$width" "$height")"
  "$arbor" render "$preset" --seed 1 --mode acc --adaptive 4 --msaa 4 --leaves --light 25,40 --size "${width}x${height}" \
    --camera "$camera" --quiet --out "$tmp/arbor.png"
  "$python" "$root/tools/arbaro_compare.py" compose "$tmp/arbaro.png" "$tmp/arbor.png" "$xml.xml" \
    "$out/arbaro-vs-arbor-$preset.png"
  echo "arbaro_compare: $out/arbaro-vs-arbor-$preset.png"
done
