#!/usr/bin/env bash
# The main job: installs what is missing, builds, then grows the demo tree and writes it to out/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tools/install-deps.sh"
bash "$root/tools/build.sh"
mkdir -p "$root/out"
"$root/build/tools/arbor" generate black-tupelo --seed 1 --quiet --out "$root/out/black-tupelo.json"
"$root/build/tools/arbor" generate black-tupelo --seed 1 --out "$root/out/black-tupelo.glb"
echo "demo: skeleton $root/out/black-tupelo.json, mesh $root/out/black-tupelo.glb"
