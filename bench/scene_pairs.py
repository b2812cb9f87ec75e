#!/usr/bin/env python3
"""bench/scene_pairs.py OLD NEW SCENE [-n 5] [--pin 1] [-- extra run args]: two yardsim builds on one
scene, interleaved (old, new, new, old, ...), pinned to one core; CPU time (user + sys) of each
whole process, start-up included; medians, min-max and the ratio new/old. OLD and NEW are
yardsim executables; a copied build's libraries are found with LD_LIBRARY_PATH=DIR/lib when
DIR/lib exists beside the executable. For the CPU figures of docs/performance.md on a busy
machine (wall time there is not trustworthy)."""
import argparse
import os
import resource
import statistics
import subprocess
import tempfile


def command(exe):
    lib = os.path.join(os.path.dirname(os.path.abspath(exe)), "lib")
    return (["env", f"LD_LIBRARY_PATH={lib}"] if os.path.isdir(lib) else []) + [exe]


def pair_arguments(description, pairs):
    """(description, default pairs) => the parsed arguments OLD NEW SCENE [-n] [--pin] [-- extra]"""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("scene")
    ap.add_argument("-n", type=int, default=pairs, help="pairs")
    ap.add_argument("--pin", type=int, default=1, help="core for taskset -c")
    ap.add_argument("extra", nargs="*", help="more `yardsim run` arguments (after --)")
    return ap.parse_args()


def main():
    a = pair_arguments(__doc__, 5)
    sides = {"old": command(a.old), "new": command(a.new)}
    cpu = {"old": [], "new": []}
    with tempfile.TemporaryDirectory() as out:
        for r in range(a.n):
            for k in (("old", "new") if r % 2 == 0 else ("new", "old")):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                subprocess.run(["taskset", "-c", str(a.pin)] + sides[k] +
                               ["run", a.scene, "-o", f"{out}/{k}", "--quiet"] + a.extra, check=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu[k].append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    o, n = statistics.median(cpu["old"]), statistics.median(cpu["new"])
    print(f"{a.scene} {' '.join(a.extra)}: old {o:.3f} s ({min(cpu['old']):.3f}-{max(cpu['old']):.3f}), "
          f"new {n:.3f} s ({min(cpu['new']):.3f}-{max(cpu['new']):.3f}), new/old {n / o:.3f}, "
          f"load {open('/proc/loadavg').read().split()[0]}")


if __name__ == "__main__":
    main()
