#!/usr/bin/env python3
"""Equilibrium draft, mean heel and roll period of a floating_barge run (standard library only).

Usage: python3 examples/floating_barge/roll_period.py out/floating_barge/timeseries.csv [t_end]

The draft and heel are averaged over the 10 s before t_end (default 60 s: the end of the calm
phase); the roll period is the mean spacing of the upward crossings of the heel through that
mean heel between t = 0 and t_end - 10 s.
"""
import csv
import math
import sys


def main():
    path = sys.argv[1]
    t_end = float(sys.argv[2]) if len(sys.argv) > 2 else 60.0
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
    t, draft, heel = (head.index(c) for c in ("time[s]", "hull.draft[m]", "hull.heel[rad]"))
    calm = [r for r in data if t_end - 10.0 <= r[t] < t_end]
    mean_draft = sum(r[draft] for r in calm) / len(calm)
    mean_heel = sum(r[heel] for r in calm) / len(calm)
    ups = []
    for a, b in zip(data, data[1:]):
        if b[t] >= t_end - 10.0:
            break
        ha, hb = a[heel] - mean_heel, b[heel] - mean_heel
        if ha < 0.0 <= hb:
            ups.append(a[t] + (b[t] - a[t]) * -ha / (hb - ha))
    period = (ups[-1] - ups[0]) / (len(ups) - 1) if len(ups) > 1 else float("nan")
    print(f"equilibrium draft {mean_draft:.4f} m, mean heel {math.degrees(mean_heel):.4f} deg, "
          f"roll period {period:.4f} s ({len(ups)} crossings)")


if __name__ == "__main__":
    main()
