#!/usr/bin/env python3
"""Summarises bench_multibody's JSON output against the targets of the multibody issue.

usage: bench_multibody --benchmark_format=json --benchmark_out=mb.json --benchmark_out_format=json
       python3 bench/multibody/summarize.py mb.json
Prints a Markdown table of CPU times (the minimum over repetitions: the least disturbed run), log-log slopes of ABA
and RNEA for N = 16..256, the RK4-step/ODE ratios at N = 32 and the energy drifts.
"""
import json
import math
import sys
from collections import defaultdict


def load(path):
    with open(path) as f:
        doc = json.load(f)
    times = defaultdict(list)
    counters = {}
    for b in doc["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        name = b.get("run_name", b["name"])
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        times[name].append(b["cpu_time"] * scale)
        if "relative_energy_drift" in b:
            counters[name] = b["relative_energy_drift"]
    return doc["context"], {k: min(v) for k, v in times.items()}, counters


def slope(t, case):
    xs, ys = [], []
    for n in (16, 32, 64, 128, 256):
        key = f"{case}/{n}"
        if key in t:
            xs.append(math.log(n))
            ys.append(math.log(t[key]))
    if len(xs) < 2:
        return float("nan")
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    ctx, t, drift = load(sys.argv[1])
    print(f"host: {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz, "
          f"library build: {ctx.get('library_build_type', '?')}\n")
    cases = ["ABA", "RNEA", "CRBA", "CRBANoCholesky", "RK4Step", "ODEWorldStep", "ODEQuickStep", "ABATree", "RNEATree", "CRBATree"]
    ns = [1, 2, 4, 8, 16, 32, 64, 128, 256]
    print("| case | " + " | ".join(f"N={n}" for n in ns) + " |")
    print("| --- |" + " ---: |" * len(ns))
    for c in cases:
        if not any(f"{c}/{n}" in t for n in ns):
            continue
        cells = []
        for n in ns:
            v = t.get(f"{c}/{n}")
            if v is None:
                cells.append("")
            elif v >= 1e6:
                cells.append(f"{v / 1e6:.3g} ms")
            elif v >= 1e3:
                cells.append(f"{v / 1e3:.3g} µs")
            else:
                cells.append(f"{v:.3g} ns")
        print(f"| {c} | " + " | ".join(cells) + " |")
    print()
    for c in ("ABA", "RNEA"):
        print(f"- {c} log-log slope N=16..256: {slope(t, c):.3f}")
    if "ABA/256" in t:
        print(f"- ABA per link at N=256: {t['ABA/256'] / 256:.1f} ns")
    rk = t.get("RK4Step/32")
    for peer in ("ODEWorldStep/32", "ODEQuickStep/32"):
        if rk and peer in t:
            print(f"- {peer} / RK4Step/32 = {t[peer] / rk:.2f}")
    for k, v in sorted(drift.items()):
        print(f"- {k}: relative energy drift {v:.3g}")


if __name__ == "__main__":
    main()
