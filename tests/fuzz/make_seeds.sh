#!/usr/bin/env bash
# (examples/) => seed inputs of the fuzz targets in OUT/scene and OUT/mesh (tests/fuzz/README.md):
# every example YAML file as a root, followed by the YAML, OBJ, STL and CSV files of its folder
# ("#@ file NAME" sections, fuzz_files.hpp); every OBJ and STL file behind its format byte.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:?usage: make_seeds.sh OUTDIR}"
mkdir -p "$out/scene" "$out/mesh"
n=0
while IFS= read -r yaml; do
  dir="$(dirname "$yaml")"
  seed="$out/scene/$(echo "${yaml#"$root"/}" | tr '/' '_')"
  # (lumped lines) => 2 segments in the seed: with 20 the stiffness guard's dense eigenproblem
  # (hundreds of node states) takes longer than the 10 s hang limit in the instrumented -O1
  # build, while the reader is exercised just the same
  { echo "#@ file $(basename "$yaml")"; sed -E 's/segments: [0-9]+/segments: 2/' "$yaml"
    for f in "$dir"/*.yaml "$dir"/*.obj "$dir"/*.stl "$dir"/*.csv; do
      [ -f "$f" ] && [ "$f" != "$yaml" ] && { echo; echo "#@ file $(basename "$f")"; cat "$f"; }
    done; } > "$seed"
  n=$((n + 1))
done < <(find "$root/examples" -name '*.yaml' | sort)
m=0
while IFS= read -r mesh; do
  case "$mesh" in *.obj|*.OBJ) byte='\x00' ;; *) byte='\x01' ;; esac
  { printf "$byte"; cat "$mesh"; } > "$out/mesh/$(echo "${mesh#"$root"/}" | tr '/' '_')"
  m=$((m + 1))
done < <(find "$root/examples" "$root/tests" -iname '*.obj' -o -iname '*.stl' | grep -v '/corpus/' | sort)
echo "seeds: $n scenes, $m meshes in $out"
