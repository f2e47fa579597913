#!/usr/bin/env python3
"""Derives the catmark-butterfly rules next to the tri/quad seam (docs/catmark_butterfly/README.md)
by the method of Boumzaid, Lanquetin, Neveu and Destelle, "An approximating-interpolatory
subdivision scheme" (2011): solve  S Q f = Q sigma f  for the monomials of degree <= m
on a fixed support, in exact rationals (fractions.Fraction, Gaussian elimination).

Surface (m = 2): coordinates of tests/meshes/mixed/split_plane.obj: quads on Z^2 for x <= 0,
triangles on (k, j + k/2) for x >= 0, column 0 (x = 0) is the seam. Control values are
Q-f = f - (f_xx + f_yy)/6 on the quad side and the seam, Q+f = f on the triangle side. One level
halves the spacing, so a refined point p' must hold f(p') - (f_xx + f_yy)/24 (quad side and seam)
or f(p') (triangle side).

Curve (m = 3): the univariate analogue for boundaries and creases that cross the seam: cubic
B-spline (Q-f = f - f''/6) for x <= 0, the 4-point rule (Q+f = f) for x > 0; a refined point
holds f(p') - f''(p')/24 or f(p').

Run: python3 derive_seam_rules.py   (standard library only)
"""
from fractions import Fraction as F
from itertools import product

HALF = F(1, 2)

# --- exact linear algebra -----------------------------------------------------------------------

def solve(rows, rhs):
    """Solves rows * w = rhs exactly. Returns (w, rank, consistent); free unknowns are set to 0."""
    n = len(rows[0])
    a = [list(r) + [b] for r, b in zip(rows, rhs)]
    pivots, r = [], 0
    for c in range(n):
        p = next((i for i in range(r, len(a)) if a[i][c] != 0), None)
        if p is None:
            continue
        a[r], a[p] = a[p], a[r]
        a[r] = [x / a[r][c] for x in a[r]]
        for i in range(len(a)):
            if i != r and a[i][c] != 0:
                k = a[i][c]
                a[i] = [x - k * y for x, y in zip(a[i], a[r])]
        pivots.append(c)
        r += 1
    consistent = all(any(x != 0 for x in row[:-1]) or row[-1] == 0 for row in a)
    w = [F(0)] * n
    for i, c in enumerate(pivots):
        w[c] = a[i][-1]
    return w, len(pivots), consistent

# --- the surface ---------------------------------------------------------------------------------

MONOMIALS = [  # name, f, f_xx + f_yy
    ("1", lambda x, y: F(1), lambda x, y: F(0)),
    ("x", lambda x, y: x, lambda x, y: F(0)),
    ("y", lambda x, y: y, lambda x, y: F(0)),
    ("x^2", lambda x, y: x * x, lambda x, y: F(2)),
    ("xy", lambda x, y: x * y, lambda x, y: F(0)),
    ("y^2", lambda x, y: y * y, lambda x, y: F(2)),
]

def approximating(p):
    """Q- (quad side and seam) or Q+ (triangle side), by the abscissa."""
    return p[0] <= 0

def control_value(f, lap, p):
    return f(*p) - (lap(*p) / 6 if approximating(p) else 0)

def refined_value(f, lap, p):
    return f(*p) - (lap(*p) / 24 if approximating(p) else 0)

def derive(name, support, target, equal=(), zero=()):
    """Weights on `support` (points) for the refined point `target`; `equal` lists pairs of
    support indices with equal weights (symmetry), `zero` indices forced to 0."""
    rows, rhs = [], []
    for _, f, lap in MONOMIALS:
        rows.append([control_value(f, lap, p) for p in support])
        rhs.append(refined_value(f, lap, target))
    for i, j in equal:
        rows.append([F(1) if k == i else F(-1) if k == j else F(0) for k in range(len(support))])
        rhs.append(F(0))
    for i in zero:
        rows.append([F(1) if k == i else F(0) for k in range(len(support))])
        rhs.append(F(0))
    w, rank, consistent = solve(rows, rhs)
    assert consistent, name + ": no solution on this support"
    unique = rank == len(support)
    print(f"{name}  (target {fmt_point(target)}, {'unique' if unique else 'NOT unique'})")
    for p, x in zip(support, w):
        print(f"    {fmt_point(p):>12}  {str(x):>7}  {float(x):+.6f}")
    print(f"    sum = {sum(w)}")
    assert unique
    return w

def expect(weights, design):
    """The weights docs/catmark_butterfly/README.md states (and far/butterfly.cpp uses) must be the
    ones derived."""
    assert list(weights) == design, (f"derived {[str(w) for w in weights]}, "
                                     f"docs/catmark_butterfly/README.md states {[str(w) for w in design]}")

def check(name, support, weights, target):
    """Prints the error of a given rule on each monomial (0 = reproduced exactly)."""
    errors = []
    for label, f, lap in MONOMIALS:
        got = sum(w * control_value(f, lap, p) for p, w in zip(support, weights))
        errors.append(f"{label}: {got - refined_value(f, lap, target)}")
    print(f"{name}: error " + ", ".join(errors))

def fmt_point(p):
    return "(" + ", ".join(str(c) for c in p) + ")"

def P(x, y):
    return (F(x), F(y))

def surface():
    print("== Surface rules at the regular seam (m = 2) ==\n")
    # Seam vertex (eq. 13): the paper's symmetry w(-1,0) = w(0,1) = w(0,-1), mirror in y.
    support = [P(-1, 1), P(-1, 0), P(-1, -1), P(0, 1), P(0, 0), P(0, -1), P(1, HALF), P(1, -HALF)]
    w = derive("seam vertex (0,0), eq. 13", support, P(0, 0), equal=[(0, 2), (1, 3), (3, 5), (6, 7)])
    expect(w, [F(3, 224), F(9, 112), F(3, 224), F(9, 112), F(5, 8), F(9, 112), F(3, 56), F(3, 56)])
    print()
    # Seam edge (eq. 14), mirror symmetric about y = 1/2.
    support = [P(0, 0), P(0, 1), P(-1, 0), P(-1, 1), P(1, HALF), P(1, -HALF), P(1, F(3, 2))]
    w = derive("seam edge (0,0)-(0,1), eq. 14", support, P(0, HALF), equal=[(0, 1), (2, 3), (5, 6)])
    expect(w, [F(11, 28), F(11, 28), F(3, 56), F(3, 56), F(13, 112), F(-1, 224), F(-1, 224)])
    print()
    # Diagonal edge seam -> column 1 (eqs. 11/12): s, t, c (seam opposite), d (other opposite),
    # wing across s-d, wing across t-d; the wing across t-c is not in the paper's support.
    support = [P(0, 0), P(1, HALF), P(0, 1), P(1, -HALF), P(0, -1), P(2, 0), P(1, F(3, 2))]
    w = derive("diagonal seam -> column 1, s=(0,0) t=(1,1/2)", support, P(HALF, F(1, 4)), zero=[6])
    expect(w, [F(31, 80), F(17, 40), F(3, 32), F(7, 40), F(-1, 32), F(-1, 20), F(0)])
    print()
    # Diagonal edge column 1 -> column 2: the half butterfly on the side away from the seam.
    support = [P(1, HALF), P(2, 1), P(2, 0), P(1, -HALF), P(3, HALF)]
    w = derive("diagonal column 1 -> column 2, u=(1,1/2) w=(2,1)", support, P(F(3, 2), F(3, 4)))
    expect(w, [HALF, HALF, F(1, 4), F(-1, 8), F(-1, 8)])
    print()
    # Why the last rule is needed, and why the other rules near the seam need nothing special.
    butterfly = [HALF, HALF, F(1, 8), F(1, 8), F(-1, 16), F(-1, 16), F(-1, 16), F(-1, 16)]
    check("plain butterfly on column 1 -> column 2 (reads the seam vertex (0,1) as a wing)",
          [P(1, HALF), P(2, 1), P(1, F(3, 2)), P(2, 0), P(0, 1), P(2, 2), P(1, -HALF), P(3, HALF)],
          butterfly, P(F(3, 2), F(3, 4)))
    check("plain butterfly on the vertical column-1 edge (1,1/2)-(1,3/2) (seam weights cancel)",
          [P(1, HALF), P(1, F(3, 2)), P(0, 1), P(2, 1), P(0, 0), P(0, 2), P(2, 0), P(2, 2)],
          butterfly, P(1, 1))
    check("plain butterfly on column 2 -> column 3, (2,1)-(3,1/2)",
          [P(2, 1), P(3, HALF), P(2, 0), P(3, F(3, 2)), P(1, HALF), P(3, -HALF), P(2, 2), P(4, 1)],
          butterfly, P(F(5, 2), F(3, 4)))
    check("Catmull-Clark vertex at (-1,0) (reads the seam column)",
          [P(-1, 0), P(-2, 0), P(0, 0), P(-1, 1), P(-1, -1), P(-2, 1), P(-2, -1), P(0, 1), P(0, -1)],
          [F(9, 16)] + [F(3, 32)] * 4 + [F(1, 64)] * 4, P(-1, 0))
    check("Catmull-Clark edge (-1,0)-(0,0)",
          [P(-1, 0), P(0, 0), P(-1, 1), P(0, 1), P(-1, -1), P(0, -1)],
          [F(3, 8), F(3, 8)] + [F(1, 16)] * 4, P(-HALF, 0))
    check("Catmull-Clark face (-1,0),(0,0),(0,1),(-1,1)",
          [P(-1, 0), P(0, 0), P(0, 1), P(-1, 1)], [F(1, 4)] * 4, P(-HALF, HALF))
    check("triangle-only vertex (1,1/2) interpolated", [P(1, HALF)], [F(1)], P(1, HALF))
    print()

# --- the curve -----------------------------------------------------------------------------------

def curve_rule(points, target, approx_points, approx_target):
    """Weights on integer parameters `points` for the refined point at parameter `target`,
    reproducing every polynomial of degree < len(points)."""
    rows, rhs = [], []
    for k in range(len(points)):
        def q(x, approx, scale):
            second = k * (k - 1) * x ** (k - 2) if k >= 2 else 0
            return x ** k - (second * scale if approx else 0)
        rows.append([q(F(p), a, F(1, 6)) for p, a in zip(points, approx_points)])
        rhs.append(q(F(target), approx_target, F(1, 24)))
    w, rank, consistent = solve(rows, rhs)
    return w if consistent and rank == len(points) else None

def curve():
    print("== Curve rules where a boundary or crease crosses the seam (m = 3) ==\n")
    print("   Points are curve parameters; '-' approximating (Q-f = f - f''/6), '+' interpolated.\n")
    cases = [
        ("B-spline vertex (all '-')", [-1, 0, 1], "---", 0, True),
        ("B-spline edge (all '-')", [0, 1], "--", HALF, True),
        ("4-point edge (all '+')", [-1, 0, 1, 2], "++++", HALF, False),
        ("seam vertex 0 between curve -1 ('-') and +1, +2 ('+')", [-1, 0, 1, 2], "--++", 0, True),
        ("edge 0-1 across the seam (0 '-', 1 '+')", [-1, 0, 1, 2], "--++", HALF, False),
        ("edge 1-2 next to the seam (0 '-')", [0, 1, 2, 3], "-+++", F(3, 2), False),
        ("seam vertex with '+' on both sides", [-1, 0, 1], "+-+", 0, True),
        ("end edge, 3 points (4-point at a curve end)", [0, 1, 2], "+++", HALF, False),
    ]
    for label, points, types, target, approx_target in cases:
        w = curve_rule(points, target, [t == "-" for t in types], approx_target)
        shown = ", ".join(f"{p}{t}: {x}" for p, t, x in zip(points, types, w))
        print(f"{label}\n    target {target}: {shown}   (sum {sum(w)})")
    # The analyzer solves these systems per curve point (far/butterfly_curve.cpp); every type
    # pattern it can meet must be solvable: windows of 2-4 points around an edge or a vertex.
    windows = [([-1, 0, 1, 2], HALF), ([0, 1, 2], HALF), ([-1, 0, 1], HALF), ([0, 1], HALF),
               ([-1, 0, 1, 2], 0), ([-2, -1, 0, 1], 0), ([-1, 0, 1], 0)]
    singular = 0
    total = 0
    for points, target in windows:
        for types in product([False, True], repeat=len(points) + 1):
            total += 1
            if curve_rule(points, target, list(types[:-1]), types[-1]) is None:
                singular += 1
                print("    singular:", points, target, types)
    print(f"\nevery type pattern of every window solvable: {singular == 0} ({total} systems)")

if __name__ == "__main__":
    surface()
    curve()
