#!/usr/bin/env python3
"""Log-log plot (SVG, no dependencies) of |error| against panel count from hydro_convergence's CSV.

Usage: python3 bench/hydro/plot_convergence.py convergence.csv > docs/hydrodynamics_convergence.svg
"""
import csv
import math
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
series = {}
for r in rows:
    series.setdefault(r["mesh"], []).append((int(r["panels"]), abs(float(r["error_percent"]))))

W, H, L, R, T, B = 640, 420, 70, 20, 30, 55
xs = [p for s in series.values() for p, _ in s]
ys = [e for s in series.values() for _, e in s]
x0, x1 = math.log10(min(xs) / 1.5), math.log10(max(xs) * 1.5)
y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))


def px(x):
    return L + (math.log10(x) - x0) / (x1 - x0) * (W - L - R)


def py(y):
    return T + (y1 - math.log10(y)) / (y1 - y0) * (H - T - B)


out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
for k in range(y0, y1 + 1):
    y = py(10.0 ** k)
    out.append(f'<line x1="{L}" y1="{y:.1f}" x2="{W - R}" y2="{y:.1f}" stroke="#ddd"/>')
    out.append(f'<text x="{L - 6}" y="{y + 4:.1f}" text-anchor="end">1e{k} %</text>')
for x in (100, 300, 1000, 3000, 10000):
    if x0 <= math.log10(x) <= x1:
        out.append(f'<line x1="{px(x):.1f}" y1="{T}" x2="{px(x):.1f}" y2="{H - B}" stroke="#ddd"/>')
        out.append(f'<text x="{px(x):.1f}" y="{H - B + 16}" text-anchor="middle">{x}</text>')
out.append(f'<text x="{(L + W - R) / 2}" y="{H - 12}" text-anchor="middle">panels N</text>')
out.append(f'<text x="16" y="{(T + H - B) / 2}" transform="rotate(-90 16 {(T + H - B) / 2})" '
           f'text-anchor="middle">|relative error of the added mass|</text>')
colours = {"sphere": "#1f77b4", "hemisphere": "#d62728"}
labels = {"sphere": "sphere, unbounded fluid, A11 vs 0.5 rho V",
          "hemisphere": "floating hemisphere, A33 vs 0.5 rho (2/3) pi a^3"}
for i, (name, pts) in enumerate(series.items()):
    c = colours.get(name, "black")
    path = " ".join(f"{px(p):.1f},{py(e):.1f}" for p, e in pts)
    out.append(f'<polyline points="{path}" fill="none" stroke="{c}" stroke-width="2"/>')
    for p, e in pts:
        out.append(f'<circle cx="{px(p):.1f}" cy="{py(e):.1f}" r="3.5" fill="{c}"/>')
    out.append(f'<text x="{L + 14}" y="{T + 16 + 18 * i}" fill="{c}">{labels.get(name, name)}</text>')
# slope -1 in N (second order in panel size h ~ N^-1/2)
p0, e0 = series["sphere"][0]
p1 = p0 * 16
out.append(f'<line x1="{px(p0):.1f}" y1="{py(e0 * 2):.1f}" x2="{px(p1):.1f}" y2="{py(e0 * 2 / 16):.1f}" '
           f'stroke="gray" stroke-dasharray="5,4"/>')
out.append(f'<text x="{px(p1):.1f}" y="{py(e0 * 2 / 16) - 6:.1f}" fill="gray" text-anchor="end">O(h^2) = O(1/N)</text>')
out.append("</svg>")
print("\n".join(out))
