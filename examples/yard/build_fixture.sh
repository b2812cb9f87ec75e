#!/usr/bin/env bash
# Builds the yard database fixture from the examples' own data (docs/database.md):
#   the goliath_turnover block (mass, inertia and 24 x 16 x 6 m box of examples/goliath_turnover/
#   scene.yaml; its four lower-hoist lugs), its two goliath cranes GOC201/GOC202 (model file
#   examples/yard/goliath_crane.yaml, stored relative to the database wherever it is written;
#   hoist speed 0.083 m/s from the scene), and the hoist rope (EA 2.0e8 N,
#   MBL 2.3e6 N per part from goliath_crane.yaml).
# Usage: build_fixture.sh YARDSIM_EXECUTABLE OUT.sqlite
# Figures not in the examples are marked nominal in docs/database.md: the rope's diameter and
# mass per metre, and the cranes' capacity (4 hoists x 4 parts x MBL / safety factor 5).
set -euo pipefail
yardsim="$1"
db="$2"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
rm -f "$db"
"$yardsim" db init "$db"
# (24 x 16 x 6 m box about its centre) => the block's mesh, counter-clockwise from outside
cat > "$work/block.obj" <<'OBJ'
v -12 -8 -3
v 12 -8 -3
v 12 8 -3
v -12 8 -3
v -12 -8 3
v 12 -8 3
v 12 8 3
v -12 8 3
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
OBJ
"$yardsim" db --db "$db" import-block GT-BLOCK-920 --obj "$work/block.obj" \
  --mass 9.2e5 --cog 0,0,0 --inertia 2.24e7,4.69e7,6.38e7 --project goliath_turnover --weight-status calculated \
  --lug L201F:-9,-8,0:0,0,1:3.0e6 --lug L201A:-7,-8,0:0,0,1:3.0e6 \
  --lug L202F:7,-8,0:0,0,1:3.0e6 --lug L202A:9,-8,0:0,0,1:3.0e6
"$yardsim" db --db "$db" import-rope-catalogue "$here/ropes.csv"
model="$(realpath -m --relative-to="$(dirname "$db")" "$here/goliath_crane.yaml")"
for crane in GOC201 GOC202; do
  "$yardsim" db --db "$db" add-facility "$crane" --kind goliath --model "$model" \
    --capacity 7.36e6 --hoist-speed 0.083 --curve "$here/goliath_hook_load.csv"
done
