#!/usr/bin/env python3
"""A synthetic impulse-response file (.ysir, docs/hydrodynamics.md "The cache", format 3) for the
speed measurement of examples/floating_barge in an irregular sea (docs/performance.md): the sizes of
a real response (6 modes, 60 s of memory at 0.05 s, 8 headings, excitation windowed at w_c = 2
rad/s), numbers of the barge's order (60 x 20 m, 2,000 t), not a solved hull: A_inf diagonal,
K_ii(t) = kappa_i exp(-0.5 t) cos(1.2 t), and an excitation of heave rho g A_wp, roll and pitch
the waterplane moments times the wave slope, as a windowed pulse X0 g(t) (transfer X0 W(w)).
The run's cost does not depend on the numbers, only on the sizes.

Usage: python3 bench/hydro/synthetic_response.py OUT.ysir
"""
import math
import struct
import sys

DT, MEMORY, WC, T0 = 0.05, 60.0, 2.0, -4.0
A_INF = [2.0e5, 1.5e6, 3.0e6, 3.0e7, 4.0e8, 3.0e8]
KAPPA = [0.2 * a for a in A_INF]
RHO_G_AWP = 1025 * 9.81 * 60 * 20
HEADINGS = [i * math.pi / 4 for i in range(8)]


def fnv1a(data):
    h = 14695981039346656037
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


out = bytearray(b"YSIMIR1\n")
key = b"synthetic-floating-barge"
out += struct.pack("<II", 3, len(key)) + key + struct.pack("<d", DT)
out += struct.pack("<36d", *[A_INF[i] if i == j else 0.0 for i in range(6) for j in range(6)])
n = int(round(MEMORY / DT))
out += struct.pack("<Q", n)
for k in range(n):
    t = k * DT
    out += struct.pack("<36d", *[KAPPA[i] * math.exp(-0.5 * t) * math.cos(1.2 * t) if i == j else 0.0
                                 for i in range(6) for j in range(6)])
out += struct.pack("<Q", len(HEADINGS)) + struct.pack(f"<{len(HEADINGS)}d", *HEADINGS)
out += struct.pack("<ddI", T0, WC, 1)  # the excitation holds Froude-Krylov
m = int(round(-2 * T0 / DT)) + 1
for b in HEADINGS:
    x0 = [0.0, 0.0, RHO_G_AWP, -RHO_G_AWP * 20 ** 2 / 12 * math.sin(b) * 0.05,
          RHO_G_AWP * 60 ** 2 / 12 * math.cos(b) * 0.05, 0.0]
    out += struct.pack("<Q", m)
    for k in range(m):
        t = T0 + k * DT
        g = WC / (2 * math.sqrt(math.pi)) * math.exp(-(WC * t / 2) ** 2)  # inverse transform of W
        out += struct.pack("<6d", *[x * g for x in x0])
out += struct.pack("<Q", fnv1a(bytes(out)))
open(sys.argv[1], "wb").write(out)
