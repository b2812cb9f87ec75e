#!/usr/bin/env python3
"""A(ka) and B(ka) of a floating hemisphere (SVG, no dependencies) from hydro_hemisphere_td's CSV,
with Hulme's (1982) surge (Table 2) and heave (Table 1) values.

Usage: python3 bench/hydro/plot_hemisphere_td.py hemisphere_td.csv > docs/hydrodynamics_hemisphere_td.svg
"""
import csv
import sys

# Hulme 1982, J. Fluid Mech. 121, 443-463, Table 2 (surge): Ka, A11 / (rho 2/3 pi a^3), B11 / (rho 2/3 pi a^3 omega)
HULME_SURGE_A = [(0.1, 0.5223), (0.2, 0.5515), (0.3, 0.5848), (0.4, 0.6175), (0.5, 0.6439), (0.6, 0.6586), (0.7, 0.6682),
                 (0.8, 0.6421), (0.9, 0.6127), (1.0, 0.5740), (1.2, 0.4860), (1.4, 0.4038), (1.6, 0.3371), (1.8, 0.2866),
                 (2.0, 0.2493), (2.5, 0.1961), (3.0, 0.1720)]
HULME_SURGE_B = [(0.1, 0.0010), (0.2, 0.0082), (0.3, 0.0255), (0.4, 0.0557), (0.5, 0.0987), (0.6, 0.1516), (0.7, 0.2092),
                 (0.8, 0.2653), (0.9, 0.3145), (1.0, 0.3535), (1.2, 0.3978), (1.4, 0.4060)]

# Hulme 1982, Table 1 (heave): Ka, A33 / (rho 2/3 pi a^3), B33 / (rho 2/3 pi a^3 omega), as transcribed in
# the reference data of symbiotic-engineering/MarineHydro.jl (test/consistency_with_analytical_solutions.jl)
HULME_HEAVE = [(0.1, 0.8627, 0.1816), (0.2, 0.7938, 0.2793), (0.3, 0.7157, 0.3254), (0.4, 0.6452, 0.3410),
               (0.5, 0.5861, 0.3391), (0.6, 0.5381, 0.3271), (0.7, 0.4999, 0.3098), (0.8, 0.4698, 0.2899),
               (0.9, 0.4464, 0.2691), (1.0, 0.4284, 0.2484), (1.2, 0.4047, 0.2096), (1.4, 0.3924, 0.1756),
               (1.6, 0.3871, 0.1469), (1.8, 0.3864, 0.1229), (2.0, 0.3884, 0.1031), (2.5, 0.3988, 0.0674),
               (3.0, 0.4111, 0.0452)]

rows = list(csv.DictReader(open(sys.argv[1])))
W, H, L, R, T, B = 760, 330, 60, 20, 30, 50
panel_w = (W - L - R - 40) / 2


def frame(ox, title, ymax):
    out = [f'<text x="{ox + panel_w / 2:.1f}" y="{T - 10}" text-anchor="middle">{title}</text>']
    for k in range(0, 6):
        y = k * ymax / 5
        py = T + (1 - y / ymax) * (H - T - B)
        out.append(f'<line x1="{ox}" y1="{py:.1f}" x2="{ox + panel_w:.1f}" y2="{py:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{ox - 5}" y="{py + 4:.1f}" text-anchor="end">{y:.2f}</text>')
    for x in (0, 0.5, 1, 1.5, 2, 2.5, 3):
        px = ox + x / 3.0 * panel_w
        out.append(f'<line x1="{px:.1f}" y1="{T}" x2="{px:.1f}" y2="{H - B}" stroke="#ddd"/>')
        out.append(f'<text x="{px:.1f}" y="{H - B + 15}" text-anchor="middle">{x}</text>')
    out.append(f'<text x="{ox + panel_w / 2:.1f}" y="{H - 15}" text-anchor="middle">ka</text>')
    return out


def series(ox, ymax, pts, colour, dots):
    def xy(x, y):
        return ox + x / 3.0 * panel_w, T + (1 - y / ymax) * (H - T - B)
    if dots:
        return [f'<circle cx="{xy(x, y)[0]:.1f}" cy="{xy(x, y)[1]:.1f}" r="3.5" fill="none" stroke="{colour}" stroke-width="1.5"/>'
                for x, y in pts]
    path = " ".join(f"{xy(x, y)[0]:.1f},{xy(x, y)[1]:.1f}" for x, y in pts)
    return [f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>']


out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
left, right = L, L + panel_w + 40
out += frame(left, "added mass A / (rho 2/3 pi a^3)", 1.0)
out += frame(right, "damping B / (rho 2/3 pi a^3 omega)", 0.5)
colours = {"surge": "#1f77b4", "heave": "#d62728"}
for mode in ("surge", "heave"):
    pts = [(float(r["ka"]), float(r["A"]), float(r["B"])) for r in rows if r["mode"] == mode]
    out += series(left, 1.0, [(x, a) for x, a, _ in pts], colours[mode], False)
    out += series(right, 0.5, [(x, b) for x, _, b in pts], colours[mode], False)
out += series(left, 1.0, HULME_SURGE_A, colours["surge"], True)
out += series(right, 0.5, HULME_SURGE_B, colours["surge"], True)
out += series(left, 1.0, [(x, a) for x, a, _ in HULME_HEAVE], colours["heave"], True)
out += series(right, 0.5, [(x, b) for x, _, b in HULME_HEAVE], colours["heave"], True)
out.append(f'<text x="{left + 10}" y="{T + 16}" fill="{colours["surge"]}">surge: line yardsim rankine_td, circles Hulme 1982</text>')
out.append(f'<text x="{left + 10}" y="{T + 32}" fill="{colours["heave"]}">heave: line yardsim rankine_td, circles Hulme 1982</text>')
out.append("</svg>")
print("\n".join(out))
