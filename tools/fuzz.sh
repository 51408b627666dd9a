#!/usr/bin/env bash
# Fuzzes every parser with libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer.
#   bash tools/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     (default 60 s each, every target)
# Starts from the kept corpus (tests/fuzz/corpus/<target>/); new interesting inputs collect in
# build-fuzz/corpus/<target>/, findings (crashes, sanitizer reports, inputs past 60 s, memory past 2 GB) in
# build-fuzz/findings/<target>/. 60 s: the sanitizers and coverage slow growth and meshing 7 to 60 times, so trees
# are held to the fuzz limits (tests/fuzz/fuzz_limits.hpp), under which the slowest known tree takes 13 s (a real
# hang never ends).
# Exit status 1 when anything was found: copy the input into the kept corpus once it is fixed.
#   bash tools/fuzz.sh --ci     what CI runs: a fixed seed and a fixed number of runs per target (about a minute
#                               each here), so that the same code always gives the same verdict
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
limit=()
if [[ "${1:-}" == "--ci" ]]; then
  shift
  limit=(-seed=1)
  ci=1
else
  ci=0
  seconds="${1:-60}"
  shift || true
  limit=(-max_total_time="$seconds")
fi
targets=("$@")
((${#targets[@]})) || targets=(species_json species_xml graph_json skeleton_json lsystem space_colonization camera_path events cli_values)

bash "$root/tools/install-deps.sh" --fuzz
cmake -S "$root" -B "$root/build-fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DARBOR_FUZZ=ON -DARBOR_BUILD_TESTS=OFF -DARBOR_WERROR=OFF > /dev/null
targets_to_build=()
for t in "${targets[@]}"; do targets_to_build+=(--target "fuzz_$t"); done
cmake --build "$root/build-fuzz" -j"$(nproc)" "${targets_to_build[@]}"

found=0
for t in "${targets[@]}"; do
  work="$root/build-fuzz/corpus/$t" findings="$root/build-fuzz/findings/$t"
  mkdir -p "$work" "$findings"
  # CI: runs sized to about a minute each on two cores; growing trees makes the species targets slower per input.
  if ((ci)); then
    case "$t" in species_json | species_xml | graph_json | skeleton_json) runs=20000 ;; lsystem) runs=1000 ;; space_colonization) runs=50000 ;; *) runs=1000000 ;; esac
    limit=(-seed=1 -runs="$runs")
    rm -rf "$work" && mkdir -p "$work"  # the same start every time
  fi
  echo "arbor fuzz: $t: ${limit[*]} (kept corpus: $(ls "$root/tests/fuzz/corpus/$t" | wc -l) inputs)"
  # A finding stops its target: it is to be looked at, not counted.
  if ! ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
      "$root/build-fuzz/tests/fuzz/fuzz_$t" "${limit[@]}" -timeout=60 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
      -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" "$work" "$root/tests/fuzz/corpus/$t" \
      > "$root/build-fuzz/fuzz-$t.log" 2>&1; then
    found=1
    echo "arbor fuzz: $t: FINDING, see build-fuzz/fuzz-$t.log and $findings/"
    grep -E "ERROR|SUMMARY|Test unit written" "$root/build-fuzz/fuzz-$t.log" | head -5 || true
  else
    runs=$(grep -oE "stat::number_of_executed_units: *[0-9]+" "$root/build-fuzz/fuzz-$t.log" | grep -oE "[0-9]+$" || echo "?")
    echo "arbor fuzz: $t: no finding in $runs runs"
  fi
done
exit "$found"
