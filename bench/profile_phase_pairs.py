#!/usr/bin/env python3
"""bench/profile_phase_pairs.py OLD NEW SCENE [-n 31] [--pin 1] [-- extra run args]: the `yardsim run
--profile` line of two yardsim builds on one scene, interleaved (old, new, new, old, ...), pinned;
the medians and minimums of the output and total seconds and the median output share. On a
loaded host the minimums are the runs least disturbed by other work."""
import re
import statistics
import subprocess
import tempfile

from scene_pairs import pair_arguments


def main():
    a = pair_arguments(__doc__, 31)
    seen = {"old": ([], []), "new": ([], [])}
    with tempfile.TemporaryDirectory() as out:
        for r in range(a.n):
            # (pair) => both builds, the order alternating
            for side in ("old", "new") if r % 2 == 0 else ("new", "old"):
                cmd = ["taskset", "-c", str(a.pin), getattr(a, side), "run", a.scene, "-o",
                       f"{out}/{side}", "--quiet", "--profile"] + a.extra
                err = subprocess.run(cmd, check=True, capture_output=True, text=True).stderr
                line = [l for l in err.splitlines() if l.startswith("profile:")][-1]
                seen[side][0].append(float(re.search(r"output ([0-9.e+-]+) s", line).group(1)))
                seen[side][1].append(float(re.search(r"total ([0-9.e+-]+) s", line).group(1)))
    for side, (output, total) in seen.items():
        share = statistics.median(100 * o / t for o, t in zip(output, total))
        print(f"{side}: output median {1e3 * statistics.median(output):.1f} ms (min {1e3 * min(output):.1f}), "
              f"total median {1e3 * statistics.median(total):.1f} ms (min {1e3 * min(total):.1f}), "
              f"share median {share:.1f} %")
    print(f"load {open('/proc/loadavg').read().split()[0]}")


if __name__ == "__main__":
    main()
