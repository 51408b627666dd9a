#!/usr/bin/env bash
# The main job: installs what is missing, builds, and opens the walkthrough viewer on a forest (with no display
# it renders the same scene offscreen to PNG files in out/view and says so); then writes the tupelo's skeleton
# and mesh and renders close-ups with GPU tessellation (lavapipe when there is no GPU) to PNG files in out/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tools/install-deps.sh"
bash "$root/tools/build.sh"
arbor="$root/build/tools/arbor"
out="$root/out"
mkdir -p "$out"
"$arbor" view black-tupelo quaking-aspen ca-black-oak --forest 30 --seed 1 --out "$out/view"
"$arbor" generate black-tupelo --seed 1 --quiet --out "$out/black-tupelo.json"
"$arbor" generate black-tupelo --seed 1 --out "$out/black-tupelo.glb"
# The whole tree in leaf, adaptive ACC, self-shadowed; a close-up of the displaced bark; the tessellation
# itself in wireframe; an aspen against a low sun (back-lit leaves); an oak whose third level is fake branches.
"$arbor" render black-tupelo --seed 1 --mode acc --adaptive 6 --msaa 4 --size 960x1200 --leaves --shadow-leaves 250 \
  --light 25,40 --out "$out/black-tupelo.png"
"$arbor" render black-tupelo --seed 1 --mode acc --adaptive 4 --displace 0.3 --msaa 4 --size 960x1200 \
  --camera 1.5,-3.5,1.6,0,0,1.4,50 --out "$out/black-tupelo-bark.png"
"$arbor" render black-tupelo --seed 1 --mode acc --tess 6 --wireframe --size 960x1200 \
  --camera 2.5,-4,4,0,0,4.5,40 --out "$out/black-tupelo-wireframe.png"
"$arbor" render quaking-aspen --seed 1 --mode acc --adaptive 6 --msaa 4 --size 960x1200 --leaves --light 205,15 \
  --out "$out/quaking-aspen-backlit.png"
"$arbor" render ca-black-oak --seed 1 --levels 2 --impostor-levels 1 --mode acc --adaptive 6 --msaa 4 --size 960x1200 \
  --leaves --shadow-leaves 250 --light 25,40 --out "$out/ca-black-oak-fake-branches.png"
"$arbor" render palm --mode acc --adaptive 6 --msaa 4 --size 960x1200 --leaves --out "$out/palm.png"
# The aspen in a strong wind: the control cage posed before tessellation, leaves following (docs/wind.md).
"$arbor" render quaking-aspen --seed 1 --mode acc --adaptive 6 --msaa 4 --size 960x1200 --leaves --wind 2 --wind-time 1 \
  --out "$out/quaking-aspen-wind.png"
# Other growth models through the same mesh: ABOP's 3D bush (an L-system) and its 2D weed as a drawing.
"$arbor" render fig-1-25 --mode acc --adaptive 6 --msaa 4 --size 960x960 --leaves --out "$out/lsystem-bush.png"
"$arbor" lsystem fig-1-24c --out "$out/lsystem-fig-1-24c.svg"
echo "demo: walkthrough frames (when there was no display) in $out/view/"
echo "demo: skeleton $out/black-tupelo.json, mesh $out/black-tupelo.glb"
echo "demo: pictures $out/black-tupelo.png, $out/black-tupelo-bark.png, $out/black-tupelo-wireframe.png,"
echo "      $out/quaking-aspen-backlit.png, $out/quaking-aspen-wind.png, $out/ca-black-oak-fake-branches.png, $out/palm.png,"
echo "      $out/lsystem-bush.png (an L-system), $out/lsystem-fig-1-24c.svg (its 2D drawing)"
