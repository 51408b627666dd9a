#!/usr/bin/env bash
# The long checks CI has no time for (about two hours on two cores: the sanitizer build 20 minutes, the suite
# under ASan and UBSan 7 to 13, then each of the nine fuzz targets for ten minutes). Exit status: 0 only when both pass.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
status=0
bash "$root/tools/test.sh" --asan || status=1
bash "$root/tools/fuzz.sh" "${1:-600}" || status=1
exit "$status"
