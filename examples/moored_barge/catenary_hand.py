# The hand calculation of README.md: the elastic catenary on a frictionless sea bed (Irvine),
# solved by Newton with a finite-difference Jacobian, independent of forces/lines/catenary.cpp.
# Prints the draft, the pretension, the line and sway stiffness, and the nonlinear offset and
# line tensions under the steady load F (N, the wind and current channels at t = 0).
#   python3 examples/moored_barge/catenary_hand.py 121681.94
import math
import sys

def spans(H, V, L, w, EA):
    # Irvine with sea bed, CB = 0: fairlead tension (H, V), V = w Ls (Ls suspended length)
    Ls = V / w
    if Ls >= L:  # fully suspended
        Va = V - w*L
        x = H/w*(math.asinh(V/H) - math.asinh(Va/H)) + H*L/EA
        z = H/w*(math.sqrt(1+(V/H)**2) - math.sqrt(1+(Va/H)**2)) + (V*L - w*L*L/2)/EA
        return x, z
    x = (L - Ls) + H/w*math.asinh(V/H) + H*L/EA
    z = H/w*(math.sqrt(1+(V/H)**2) - 1) + V*V/(2*EA*w)
    return x, z
def solve(X, Z, L, w, EA):
    H, V = 1e5, w*Z*1.5
    for _ in range(100):
        x, z = spans(H, V, L, w, EA)
        r = (x - X, z - Z)
        if abs(r[0]) + abs(r[1]) < 1e-11: break
        dH, dV = H*1e-7, V*1e-7
        x1, z1 = spans(H+dH, V, L, w, EA); x2, z2 = spans(H, V+dV, L, w, EA)
        a, b, c, d = (x1-x)/dH, (x2-x)/dV, (z1-z)/dH, (z2-z)/dV
        det = a*d - b*c
        H -= (d*r[0] - b*r[1])/det; V -= (-c*r[0] + a*r[1])/det
    return H, V

L, w, EA = 314.0, 2400.0, 1.2e9
rho, g, A, m, depth, X0 = 1025.0, 9.81, 60.0 * 20.0, 2.0e6, 40.0, 300.0
FAIR = [(28, 10), (-28, 10), (-28, -10), (28, -10)]
ANCHOR = [(fx + math.copysign(X0 * math.sqrt(0.5), fx), fy + math.copysign(X0 * math.sqrt(0.5), fy))
          for fx, fy in FAIR]


def pull(y, Z):
    # (sway offset y, fairlead height ZF) => the lines' pull along +y and each line's X, H, V
    total, lines = 0.0, []
    for (fx, fy), (ax, ay) in zip(FAIR, ANCHOR):
        dx, dy = ax - fx, ay - (fy + y)
        X = math.hypot(dx, dy)
        H, V = solve(X, Z, L, w, EA)
        total += H * dy / X
        lines.append((X, H, V))
    return total, lines


if __name__ == "__main__":
    F = float(sys.argv[1]) if len(sys.argv) > 1 else 121681.94
    T = m / (rho * A)
    for _ in range(10):  # (draft) => fairlead height => vertical pull => draft
        Z = depth - T + 1.0
        H0, V0 = solve(X0, Z, L, w, EA)
        T = (m * g + 4 * V0) / (rho * g * A)
    k = (solve(X0 + 1e-4, Z, L, w, EA)[0] - solve(X0 - 1e-4, Z, L, w, EA)[0]) / 2e-4
    K = 2 * (k + H0 / X0)
    print(f"draft {T:.5f} m, ZF {Z:.5f} m, H0 {H0:.1f} N, V0 {V0:.1f} N, laid {L - V0 / w:.2f} m")
    print(f"k {k:.1f} N/m, H0/X {H0 / X0:.2f} N/m, Kyy {K:.1f} N/m, F/K {F / K:.5f} m")
    y = -F / K
    for _ in range(50):
        s, _l = pull(y, Z)
        d = (pull(y + 1e-5, Z)[0] - s) / 1e-5
        y -= (s - F) / d
    for X, H, V in pull(y, Z)[1]:
        print(f"  X {X:.3f} m: H {H:.1f} N, V {V:.1f} N, fairlead tension {math.hypot(H, V):.1f} N")
    print(f"nonlinear offset {y:.5f} m")
