#!/usr/bin/env python3
"""bench/output_share_pairs.py OLD NEW [-n 7] [--pin 1]: output's share of a run (the `yardsim run
--profile` line) for two yardsim builds, interleaved (old, new, new, old, ...), pinned, on the
scenes of bench/compare.py's `scenes`; medians and min-max per build."""
import argparse
import os
import re
import statistics
import subprocess
import tempfile

from compare import SCENES


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("-n", type=int, default=7, help="rounds")
    ap.add_argument("--pin", type=int, default=1, help="core for taskset -c")
    a = ap.parse_args()
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    print("| scene | old output share | new output share |\n|---|---|---|")
    for name, _, extra in SCENES:
        shares = {"old": [], "new": []}
        with tempfile.TemporaryDirectory() as out:
            for r in range(a.n):
                # (round) => both builds, the order alternating
                for side in ("old", "new") if r % 2 == 0 else ("new", "old"):
                    cmd = ["taskset", "-c", str(a.pin), getattr(a, side), "run",
                           f"{here}/examples/{name}/scene.yaml", "-o", out, "--quiet", "--profile"] + extra
                    err = subprocess.run(cmd, check=True, capture_output=True, text=True).stderr
                    line = [l for l in err.splitlines() if l.startswith("profile:")][-1]
                    shares[side].append(float(re.search(r"\(([0-9.]+) % of the run\)", line).group(1)))
        cells = [f"{statistics.median(v):.1f} % ({min(v):.1f}-{max(v):.1f})" for v in shares.values()]
        print(f"| {' '.join([name] + extra)} | {cells[0]} | {cells[1]} |", flush=True)


if __name__ == "__main__":
    main()
