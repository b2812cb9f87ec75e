#!/usr/bin/env bash
# The report in a real browser: runs a scene with --report, then report/test/browser_test.mjs
# (node + puppeteer-core driving Debian's chromium) on OUTDIR/report.html.
#   browser_test.sh YARDSIM SCENE OUTDIR SCREENSHOT
# Without chromium, node or report/node_modules it fails under CI (CI=true: .ci/run installs
# them) and is skipped elsewhere (exit 77), saying what to install.
set -euo pipefail
yardsim=$1 scene=$2 out=$3 shot=$4
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
rm -rf "$out"
"$yardsim" run "$scene" -o "$out" --quiet --report
node "$js/test/browser_test.mjs" "$out/report.html" "$shot" --chromium "$chromium"
