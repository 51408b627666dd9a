#!/usr/bin/env bash
# cmake --install into a fresh prefix: the installed arbor finds its presets and textures under PREFIX/share/arbor
# (not through the source tree), grows and renders from them, and a missing assets folder is an error (exit 2).
set -euo pipefail
build="$1"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
arbor="$prefix/bin/arbor"
list="$("$arbor" species --list)"
grep -q "presets in $prefix/share/arbor/presets" <<<"$list" || { echo "presets not found under the prefix:"; echo "$list"; exit 1; }
grep -q "black-tupelo" <<<"$list" || { echo "no black-tupelo in the list"; exit 1; }
"$arbor" generate palm --out "$prefix/palm.obj" --quiet
[ -s "$prefix/palm.obj" ] || { echo "no OBJ written"; exit 1; }
"$arbor" generate palm --subdivide 1 --out "$prefix/smooth.obj" --quiet  # OpenSubdiv's module from PREFIX/lib/arbor
[ -s "$prefix/smooth.obj" ] || { echo "no subdivided OBJ written"; exit 1; }
[ -s "$prefix/share/arbor/textures/bark_color.png" ] || { echo "textures not installed"; exit 1; }
[ -s "$prefix/share/doc/arbor/README.md" ] || { echo "docs not installed"; exit 1; }
set +e
out="$(ARBOR_ASSETS="$prefix/nowhere" "$arbor" species --list 2>&1)"
code=$?
set -e
[ "$code" = 2 ] || { echo "a missing assets folder exited $code, not 2: $out"; exit 1; }
grep -q "ARBOR_ASSETS" <<<"$out" || { echo "the error does not name ARBOR_ASSETS: $out"; exit 1; }
echo "installed arbor finds its assets under $prefix/share/arbor and its subdivision module under $prefix/lib/arbor; a missing assets folder exits 2"
