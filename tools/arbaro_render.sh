#!/usr/bin/env bash
# Arbaro's own render of an Arbaro species file, for side-by-side comparison with Arbor's presets
# (docs/generator.md, "Each preset beside Arbaro's render"). Arbaro 1.9.9 exports the tree as POV-Ray mesh2
# objects (stems and leaves); POV-Ray renders them with an orthographic side view framed on the whole tree.
#
#   ARBARO_CLASSES=/tmp/arbaro/classes tools/arbaro_render.sh [-s SEED] [-W WIDTH] [-H HEIGHT] SPECIES.xml OUT.png
#
# The commands it runs, for species weeping_willow and seed 1:
#   java -cp "$ARBARO_CLASSES" net.sourceforge.arbaro.arbaro -q -s 1 -f POV_MESH -o DIR/tree.inc weeping_willow.xml
#   povray +IDIR/scene.pov +ODIR/out.png +W480 +H600 +A0.3 -D Display=off   (scene.pov written below)
# Needs java, Arbaro's compiled classes (ARBARO_CLASSES, default /tmp/arbaro/classes) and povray
# (Debian: apt-get install -y povray).
set -euo pipefail

seed=1 width=480 height=600
while getopts "s:W:H:" opt; do
  case "$opt" in
    s) seed="$OPTARG" ;;
    W) width="$OPTARG" ;;
    H) height="$OPTARG" ;;
    *) echo "usage: $0 [-s SEED] [-W WIDTH] [-H HEIGHT] SPECIES.xml OUT.png" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
if [ $# -ne 2 ]; then
  echo "usage: $0 [-s SEED] [-W WIDTH] [-H HEIGHT] SPECIES.xml OUT.png" >&2
  exit 2
fi
species="$(realpath "$1")"
out="$(realpath -m "$2")"
classes="${ARBARO_CLASSES:-/tmp/arbaro/classes}"

command -v java > /dev/null || { echo "arbaro_render: java is missing (apt-get install -y default-jre-headless)" >&2; exit 1; }
command -v povray > /dev/null || { echo "arbaro_render: povray is missing; install it with: apt-get install -y povray" >&2; exit 1; }
[ -f "$classes/net/sourceforge/arbaro/arbaro.class" ] ||
  { echo "arbaro_render: no Arbaro classes in $classes (set ARBARO_CLASSES to Arbaro 1.9.9's compiled classes)" >&2; exit 1; }
[ -f "$species" ] || { echo "arbaro_render: no species file $species" >&2; exit 1; }

dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
java -cp "$classes" net.sourceforge.arbaro.arbaro -q -s "$seed" -f POV_MESH -o "$dir/tree.inc" "$species"

# Arbaro declares NAME_SEED_height, NAME_SEED_stems and (with leaves) NAME_SEED_leaves.
prefix="$(sed -n 's/^#declare \(.*\)_height = .*/\1/p' "$dir/tree.inc" | head -n 1)"
[ -n "$prefix" ] || { echo "arbaro_render: Arbaro's export of $species declares no tree" >&2; exit 1; }
leaves=""
if grep -q "^#declare ${prefix}_leaves" "$dir/tree.inc"; then
  leaves="object { ${prefix}_leaves texture { pigment { rgb <0.20, 0.42, 0.12> } finish { ambient 0.25 diffuse 0.75 } } }"
fi

# Arbaro's POV export has y up. The camera looks along +z at the tree's bounding box (stems and leaves), with
# 6 % margins, so the whole tree fills the frame as `arbor render` frames it; the ground below the base.
cat > "$dir/scene.pov" <<EOF
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "tree.inc"
#declare Tree = union {
  object { ${prefix}_stems texture { pigment { rgb <0.36, 0.27, 0.20> } finish { ambient 0.25 diffuse 0.75 } } }
  ${leaves}
}
#declare Lo = min_extent(Tree);
#declare Hi = max_extent(Tree);
#declare Aspect = ${width} / ${height};
#declare SpanX = (Hi.x - Lo.x) * 1.12;
#declare SpanY = (Hi.y - min(Lo.y, 0)) * 1.12;
#declare Up = max(SpanY, SpanX / Aspect);
#declare Cx = (Lo.x + Hi.x) / 2;
#declare Cy = (Hi.y + min(Lo.y, 0)) / 2;
background { rgb <0.62, 0.74, 0.88> }
light_source { <-3000, 5000, -4000> rgb 1.0 }
light_source { <3000, 2000, -1000> rgb 0.35 shadowless }
camera { orthographic location <Cx, Cy, Lo.z - 100> right <Up * Aspect, 0, 0> up <0, Up, 0> look_at <Cx, Cy, 0> }
box { <-1e5, -1e5, Lo.z - 50>, <1e5, 0, 1e5> texture { pigment { rgb <0.45, 0.40, 0.30> } finish { ambient 0.6 diffuse 0.4 } } }
object { Tree }
EOF
(cd "$dir" && povray +Iscene.pov +Oout.png +W"$width" +H"$height" +A0.3 +FN -D Display=off -GA > povray.log 2>&1) ||
  { tail -n 20 "$dir/povray.log" >&2; echo "arbaro_render: povray failed" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
cp "$dir/out.png" "$out"
echo "arbaro_render: $out ($prefix, Arbaro seed $seed)"
