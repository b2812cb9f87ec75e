#!/usr/bin/env bash
# Refreshes examples/<name>/report.png, the screenshot each example README shows: runs the
# report browser tests (tests/report, which save build/tests/report/<name>.png) and copies them.
#   bash scripts/report_screenshots.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
ctest --test-dir "$build" -R '^report\.browser\.' --output-on-failure
for png in "$build"/tests/report/*.png; do
  name=$(basename "$png" .png)
  [ -d "examples/$name" ] && cp "$png" "examples/$name/report.png" && echo "examples/$name/report.png"
done
