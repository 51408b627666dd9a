#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test (CTest, 2 jobs).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tools/install-deps.sh"
bash "$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)"
