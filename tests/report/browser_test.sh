#!/usr/bin/env bash
# A page of the report bundle in a real browser: runs COMMAND (which writes PAGE), then
# report/test/browser_test.mjs (node + puppeteer-core driving Debian's chromium) on PAGE, then
# the Khronos glTF validator on the replay.glb beside it, if any.
#   browser_test.sh PAGE SCREENSHOT COMMAND...
# REPORT_BODIES=a,b (environment) names bodies the page's replay must show, each moving.
# Without chromium, node or report/node_modules it fails under CI (CI=true: .ci/run installs
# them) and is skipped elsewhere (exit 77), saying what to install.
set -euo pipefail
page=$1 shot=$2
shift 2
js="$(cd "$(dirname "$0")/../../report" && pwd)"
chromium=${CHROMIUM:-$(command -v chromium || true)}
missing=()
[ -n "$chromium" ] && [ -x "$chromium" ] || missing+=("chromium (bash scripts/setup.sh)")
command -v node > /dev/null || missing+=("node (bash scripts/setup.sh)")
[ -d "$js/node_modules/puppeteer-core" ] || missing+=("report/node_modules (cd report && npm ci --ignore-scripts)")
if [ ${#missing[@]} -gt 0 ]; then
  if [ -n "${CI:-}" ]; then
    echo "browser test: missing ${missing[*]}; CI must install them (.ci/run)" >&2
    exit 1
  fi
  echo "SKIPPED: the browser test needs ${missing[*]}"
  exit 77
fi
rm -f "$page"
"$@"
node "$js/test/browser_test.mjs" "$page" "$shot" --chromium "$chromium" \
  ${REPORT_BODIES:+--bodies "$REPORT_BODIES"}
# (the run's replay.glb, when it has one) => the Khronos glTF validator finds nothing
glb="$(dirname "$page")/replay.glb"
if [ -f "$glb" ]; then node "$js/test/validate_glb.mjs" "$glb"; fi
