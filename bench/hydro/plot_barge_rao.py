#!/usr/bin/env python3
"""RAOs of the box barge (SVG, no dependencies) from hydro_barge_rao's CSV: per sea (beam, head)
the amplitude per metre of wave amplitude of each free mode against w, the frequency-domain
solve of the panels as lines and the time-domain runs as circles (roll and pitch in deg/m).

Usage: python3 bench/hydro/plot_barge_rao.py barge_rao.csv > docs/hydrodynamics_barge_rao.svg
"""
import csv
import math
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
W, H, L, R, T, B = 760, 330, 60, 20, 30, 50
panel_w = (W - L - R - 40) / 2
omegas = sorted({float(r["omega"]) for r in rows})
x0, x1 = math.floor(min(omegas) * 2) / 2, math.ceil(max(omegas) * 2) / 2
YMAX = 2.0  # m/m and 10 deg/m share one axis: rotations are shown in units of 10 deg/m


def scale(r):
    return math.degrees(1.0) / 10.0 if r["mode"] in ("roll", "pitch", "yaw") else 1.0


def frame(ox, title):
    out = [f'<text x="{ox + panel_w / 2:.1f}" y="{T - 10}" text-anchor="middle">{title}</text>']
    for k in range(0, 5):
        y = k * YMAX / 4
        py = T + (1 - y / YMAX) * (H - T - B)
        out.append(f'<line x1="{ox}" y1="{py:.1f}" x2="{ox + panel_w:.1f}" y2="{py:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{ox - 5}" y="{py + 4:.1f}" text-anchor="end">{y:.1f}</text>')
    x = x0
    while x <= x1 + 1e-9:
        px = ox + (x - x0) / (x1 - x0) * panel_w
        out.append(f'<line x1="{px:.1f}" y1="{T}" x2="{px:.1f}" y2="{H - B}" stroke="#ddd"/>')
        out.append(f'<text x="{px:.1f}" y="{H - B + 15}" text-anchor="middle">{x:g}</text>')
        x += 0.5
    out.append(f'<text x="{ox + panel_w / 2:.1f}" y="{H - 15}" text-anchor="middle">omega (rad/s)</text>')
    return out


def xy(ox, x, y):
    return ox + (x - x0) / (x1 - x0) * panel_w, T + (1 - min(y, YMAX) / YMAX) * (H - T - B)


out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
colours = {"surge": "#2ca02c", "sway": "#2ca02c", "heave": "#d62728", "roll": "#1f77b4", "pitch": "#1f77b4"}
for i, sea in enumerate(("beam", "head")):
    ox = L + i * (panel_w + 40)
    out += frame(ox, f"{sea} seas: RAO (m/m; roll, pitch in 10 deg/m)")
    modes = [m for m in ("surge", "sway", "heave", "roll", "pitch") if any(r["sea"] == sea and r["mode"] == m for r in rows)]
    for k, mode in enumerate(modes):
        pts = sorted((float(r["omega"]), float(r["reference"]) * scale(r), float(r["measured"]) * scale(r))
                     for r in rows if r["sea"] == sea and r["mode"] == mode)
        line = " ".join("%.1f,%.1f" % xy(ox, x, y) for x, y, _ in pts)
        out.append(f'<polyline points="{line}" fill="none" stroke="{colours[mode]}" stroke-width="2"/>')
        for x, _, y in pts:
            cx, cy = xy(ox, x, y)
            out.append(f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="3.5" fill="none" stroke="{colours[mode]}" stroke-width="1.5"/>')
        out.append(f'<text x="{ox + panel_w - 10}" y="{T + 16 + 16 * k}" text-anchor="end" fill="{colours[mode]}">{mode}</text>')
out.append(f'<text x="{L + 10}" y="{T + 16}" fill="#444">lines: frequency domain, circles: time domain (same panels)</text>')
out.append("</svg>")
print("\n".join(out))
