#!/usr/bin/env python3
"""bench/lib_pairs.py BUILD LIB_A LIB_B [-n 7] (--kernel ALGO MODEL N | --bench FILTER): one build's
benchmark executable run alternately with two copies of libyardsim_dynamics.so (LIB_A, LIB_B:
folders holding one each, of the same source tree's ABI; the executables' RUNPATH lets
LD_LIBRARY_PATH choose), pinned to core 1. --kernel times `BUILD/bench/peers/peer_multibody yardsim
ALGO MODEL N` (ns per call: median and min of its own rounds), --bench a Google Benchmark of
`BUILD/bench/multibody/bench_multibody` (cpu_time). Prints each side's median and B/A, overall and
per round. For an A/B of one kernel file: build, copy the library to LIB_A, change and rebuild the
file, copy the library to LIB_B (docs/performance_peers.md, fifteenth session)."""
import argparse
import json
import os
import statistics
import subprocess


def run_once(args, lib):
    env = dict(os.environ, LD_LIBRARY_PATH=lib)
    if args.kernel:
        exe = os.path.join(args.build, "bench/peers/peer_multibody")
        cmd = ["taskset", "-c", "1", exe, "yardsim", *args.kernel]
        out = subprocess.run(cmd, capture_output=True, text=True, env=env, check=True).stdout
        return json.loads(out.strip().splitlines()[-1])["ns"]
    exe = os.path.join(args.build, "bench/multibody/bench_multibody")
    cmd = ["taskset", "-c", "1", exe, f"--benchmark_filter={args.bench}",
           "--benchmark_min_time=0.2", "--benchmark_format=json"]
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, check=True).stdout
    return json.loads(out)["benchmarks"][0]["cpu_time"]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("build")
    p.add_argument("lib_a")
    p.add_argument("lib_b")
    p.add_argument("-n", type=int, default=7, help="rounds (each runs A then B)")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--kernel", nargs=3, metavar=("ALGO", "MODEL", "N"))
    g.add_argument("--bench", metavar="FILTER", help="e.g. '^RK4Step/32$'")
    args = p.parse_args()
    a, b = [], []
    for _ in range(args.n):
        a.append(run_once(args, args.lib_a))
        b.append(run_once(args, args.lib_b))
    ma, mb = statistics.median(a), statistics.median(b)
    rounds = " ".join(f"{y / x:.3f}" for x, y in zip(a, b))
    print(f"A {ma:.1f} ns  B {mb:.1f} ns  B/A {mb / ma:.3f}  rounds {rounds}")


if __name__ == "__main__":
    main()
