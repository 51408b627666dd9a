#!/usr/bin/env bash
# The L-system presets (assets/lsystems/, ABOP figs. 1.24a-2.8a) as Arbor meshes and renders them, one grid:
# docs/images/lsystem-gallery.png (docs/lsystem-format.md shows it).
#
#   tools/lsystem_gallery.sh [OUT.png]
#
# Each: `arbor render` (lavapipe where no other Vulkan device is set, ACC at tessellation factor 4, leaves, fake
# branches for the twigs not meshed) framed on the whole plant, from -y (the planar figures' plane faces the camera).
# Environment: ARBOR (default build/tools/arbor). Needs python3 with Pillow (apt-get install -y python3-pil).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
arbor="${ARBOR:-$root/build/tools/arbor}"
out="${1:-$root/docs/images/lsystem-gallery.png}"
width=240 height=320

# Pillow: the python3 on PATH, else Debian's (python3-pil), which a pyenv python3 on PATH does not see.
python=python3
python3 -c "import PIL" 2> /dev/null || python=/usr/bin/python3
"$python" -c "import PIL" 2> /dev/null || { echo "lsystem_gallery: Pillow is missing (apt-get install -y python3-pil)" >&2; exit 1; }
[ -x "$arbor" ] || { echo "lsystem_gallery: no $arbor (build first, or set ARBOR)" >&2; exit 1; }
lavapipe=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
[ -n "${VK_DRIVER_FILES:-}" ] || [ ! -f "$lavapipe" ] || export VK_DRIVER_FILES="$lavapipe"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$(dirname "$out")"
entries=()
plants=("$root"/assets/lsystems/*.lsys)
for i in "${!plants[@]}"; do
  name="$(basename "${plants[$i]}" .lsys)"
  echo "lsystem_gallery: $((i + 1))/${#plants[@]} $name" >&2
  "$arbor" render "$name" --mode acc --tess 4 --leaves --size "${width}x${height}" --quiet --out "$tmp/$name.png"
  # The caption: the file's name, then what its `name:` says past "ABOP <figure>" ("bush", "Honda monopodial").
  rest="$(sed -n 's/^name: *ABOP [^ ]* *//p' "${plants[$i]}" | head -1)"
  entries+=("$name${rest:+ $rest}=$tmp/$name.png")
done
"$python" "$root/tools/gallery.py" "$out" 6 "${entries[@]}"
echo "lsystem_gallery: wrote $out"
