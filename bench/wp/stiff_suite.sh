#!/bin/sh
# Work-precision of the stiff suite (docs/numerics.md): `yardsim wp` on every scene of
# examples/stiff/ that has a `wp:` block. Long sweeps live here, not in the tests.
#   sh bench/wp/stiff_suite.sh [build/cli/yardsim] [out/wp]
set -e
exe=${1:-build/cli/yardsim}
out=${2:-out/wp}
for scene in block_920t hook_hoist_920t block_3500t slack_snap; do
  echo "== $scene"
  "$exe" wp "examples/stiff/$scene.yaml" -o "$out/$scene" --quiet
done
