#!/usr/bin/env bash
# Installs the Debian 12 packages Arbor builds, tests and runs with; skips what is already there.
set -euo pipefail

# --fuzz: also clang and its libFuzzer runtime (tools/fuzz.sh).
packages=(
  build-essential cmake pkg-config libjemalloc-dev
  mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers vulkan-tools glslang-tools spirv-tools
  libglfw3-dev libglm-dev libosd-dev libstb-dev catch2
  nlohmann-json3-dev libnanoflann-dev libtinyxml2-dev libtinygltf-dev libcli11-dev libimgui-dev
  xvfb xauth xdotool
  # the Python module (python/) and its tests; Blender runs the add-on's headless test (tools/blender)
  python3-dev python3-pybind11 python3-numpy python3-pytest blender
)
[[ "${1:-}" == "--fuzz" ]] && packages+=(clang-14 libclang-rt-14-dev)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# node and npm may come from elsewhere (nodesource bundles npm); only ask Debian when the commands are absent
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)

if ((${#missing[@]})); then
  echo "arbor: installing ${#missing[@]} missing packages: ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "arbor: all system packages present"
fi

# The Khronos glTF validator the export tests run; pinned by tools/node/package-lock.json.
node_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/node"
if [[ -d "$node_dir/node_modules/gltf-validator" ]]; then
  echo "arbor: glTF validator present"
elif [[ -f "$node_dir/package-lock.json" ]]; then
  echo "arbor: installing the glTF validator: npm ci in $node_dir"
  (cd "$node_dir" && npm ci --no-audit --no-fund)
else
  echo "arbor: installing the glTF validator: npm install in $node_dir (no lock file yet)"
  (cd "$node_dir" && npm install --no-audit --no-fund)
fi
