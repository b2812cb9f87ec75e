#!/usr/bin/env python3
"""Plot columns of a yardsim timeseries.csv as an SVG line chart (standard library only).

    python3 scripts/plot_timeseries.py OUT/timeseries.csv 'pendulum.joint*.q' -o plot.svg \
        [--scale 57.29577951308232 --ylabel 'angle [deg]'] [--title T]

Columns are chosen by glob over their names without the unit. Used for the committed plots in
the examples' READMEs; the interactive HTML report replaces it in a later issue.
"""
import argparse
import csv
import fnmatch
import math

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"]


def read(path):
    meta, rows, header = {}, [], None
    with open(path) as f:
        for line in f:
            if line.startswith("# "):
                k, _, v = line[2:].strip().partition(" ")
                meta[k] = v
                continue
            cells = next(csv.reader([line]))
            if header is None:
                header = cells
            else:
                rows.append([float(c) for c in cells])
    return meta, header, rows


def nice_ticks(lo, hi, n=6):
    if hi <= lo:
        hi = lo + 1.0
    step = 10 ** math.floor(math.log10((hi - lo) / n))
    for m in (1, 2, 5, 10):
        if (hi - lo) / (step * m) <= n:
            step *= m
            break
    t = math.ceil(lo / step) * step
    out = []
    while t <= hi + 1e-12 * abs(hi):
        out.append(round(t, 12))
        t += step
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("columns", nargs="+")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--ylabel", default="")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    meta, header, rows = read(a.csv)
    names = [h.split("[")[0] for h in header]
    picked = [i for i, n in enumerate(names) if i > 0 and any(fnmatch.fnmatch(n, g) for g in a.columns)]
    if not picked:
        raise SystemExit("no column matches " + " ".join(a.columns))
    t = [r[0] for r in rows]
    ys = {i: [r[i] * a.scale for r in rows] for i in picked}
    y0 = min(min(v) for v in ys.values())
    y1 = max(max(v) for v in ys.values())
    pad = 0.05 * (y1 - y0 or 1.0)
    y0, y1 = y0 - pad, y1 + pad
    W, H, L, R, T, B = 720, 400, 70, 20, 40, 50
    sx = lambda x: L + (x - t[0]) / ((t[-1] - t[0]) or 1.0) * (W - L - R)
    sy = lambda y: H - B - (y - y0) / (y1 - y0) * (H - T - B)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    for x in nice_ticks(t[0], t[-1]):
        out.append(f'<line x1="{sx(x):.1f}" y1="{T}" x2="{sx(x):.1f}" y2="{H-B}" stroke="#ddd"/>'
                   f'<text x="{sx(x):.1f}" y="{H-B+16}" text-anchor="middle">{x:g}</text>')
    for y in nice_ticks(y0, y1):
        out.append(f'<line x1="{L}" y1="{sy(y):.1f}" x2="{W-R}" y2="{sy(y):.1f}" stroke="#ddd"/>'
                   f'<text x="{L-6}" y="{sy(y)+4:.1f}" text-anchor="end">{y:g}</text>')
    out.append(f'<rect x="{L}" y="{T}" width="{W-L-R}" height="{H-T-B}" fill="none" stroke="#333"/>')
    out.append(f'<text x="{(W+L-R)/2}" y="{H-12}" text-anchor="middle">time [s]</text>')
    out.append(f'<text x="16" y="{(H-B+T)/2}" text-anchor="middle" transform="rotate(-90 16 {(H-B+T)/2})">{a.ylabel}</text>')
    if a.title:
        out.append(f'<text x="{(W+L-R)/2}" y="22" text-anchor="middle" font-size="14">{a.title}</text>')
    for k, i in enumerate(picked):
        c = COLOURS[k % len(COLOURS)]
        pts = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in zip(t, ys[i]))
        out.append(f'<polyline fill="none" stroke="{c}" stroke-width="1.8" points="{pts}"/>')
        out.append(f'<line x1="{L+12}" y1="{T+14+16*k}" x2="{L+32}" y2="{T+14+16*k}" stroke="{c}" stroke-width="2"/>'
                   f'<text x="{L+38}" y="{T+18+16*k}">{names[i]}</text>')
    out.append("</svg>")
    with open(a.output, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
