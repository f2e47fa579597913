#!/usr/bin/env python3
"""Writes data/mixed_limb.obj, the demo's cage: a limb-like tube along x (shoulder, elbow, forearm,
wrist) of about 10 000 faces, closed by two domes. Quads, except the elbow band and the end dome,
which are triangulated, so the tri/quad seam runs around the tube on both sides of the bend and
around the end dome. Three tagged creases: a ridge along the upper arm, a ring in the triangulated
elbow, and a wrist band. The two-bone skin of the demo bends it at the elbow
(docs/realtime_loop.md).

    python3 tools/make_limb.py > data/mixed_limb.obj

Deterministic (no randomness), so the committed file is exactly this script's output; the test
`limb_generator` checks that.
"""
import math
import sys

LENGTH = 6.0          # along x, the longest axis
AROUND = 64           # vertices per ring; a multiple of 4, so that a grid closes each end
RINGS = 119           # rings along the tube
ELBOW = (0.40, 0.62)  # the triangulated band, as fractions of the length
CAP_GRID = AROUND // 4


def radius(s):
    """The limb's radius at fraction s of its length: tapering, with a biceps, a narrower elbow
    and a forearm bulge."""
    bump = lambda centre, width: math.exp(-((s - centre) / width) ** 2)
    return 0.5 * (1.0 - 0.3 * s) + 0.08 * bump(0.25, 0.1) - 0.05 * bump(0.5, 0.06) + 0.06 * bump(0.68, 0.08)


def ring_point(s, j):
    """Vertex j of the ring at fraction s: an ellipse, flatter in z."""
    phi = 2.0 * math.pi * j / AROUND
    r = radius(s)
    return (s * LENGTH, r * math.cos(phi), 0.85 * r * math.sin(phi))


def boundary_of_grid(n):
    """The (i, k) grid points on the boundary of an n x n grid of quads, counter-clockwise from
    (n, n/2) (the +u side's middle, angle 0, like ring vertex 0); 4n of them."""
    h = n // 2
    walk = [(n, k) for k in range(h, n)]
    walk += [(i, n) for i in range(n, 0, -1)]
    walk += [(0, k) for k in range(n, 0, -1)]
    walk += [(i, 0) for i in range(0, n)]
    walk += [(n, k) for k in range(0, h)]
    return walk


def cap_disk(n):
    """2D positions in the unit disk of an n x n grid whose boundary lies on the circle at the
    ring's angles (boundary point j at angle 2 pi j / 4n), interior relaxed by Laplacian
    smoothing from the square's own layout."""
    pos = {(i, k): (2.0 * i / n - 1.0, 2.0 * k / n - 1.0) for i in range(n + 1) for k in range(n + 1)}
    for j, ik in enumerate(boundary_of_grid(n)):
        phi = 2.0 * math.pi * j / (4 * n)
        pos[ik] = (math.cos(phi), math.sin(phi))
    interior = [(i, k) for i in range(1, n) for k in range(1, n)]
    for _ in range(200):
        for (i, k) in interior:
            nb = [pos[(i + 1, k)], pos[(i - 1, k)], pos[(i, k + 1)], pos[(i, k - 1)]]
            pos[(i, k)] = (sum(p[0] for p in nb) / 4.0, sum(p[1] for p in nb) / 4.0)
    return pos


class Mesh:
    def __init__(self):
        self.vertices = []
        self.faces = []
        self.creases = []  # (vertex a, vertex b, sharpness), 0-based

    def add_vertex(self, p):
        self.vertices.append(p)
        return len(self.vertices) - 1

    def add_face(self, corners, outward):
        """Adds the face, its corners turned counter-clockwise seen from `outward` (a direction)."""
        p = [self.vertices[c] for c in corners]
        n = [0.0, 0.0, 0.0]
        for a, b in zip(p, p[1:] + p[:1]):  # Newell's normal
            n[0] += (a[1] - b[1]) * (a[2] + b[2])
            n[1] += (a[2] - b[2]) * (a[0] + b[0])
            n[2] += (a[0] - b[0]) * (a[1] + b[1])
        if sum(x * y for x, y in zip(n, outward)) < 0:
            corners = corners[::-1]
        self.faces.append(corners)

    def add_quad(self, a, b, c, d, outward, triangulate):
        """The quad a b c d, or its two triangles split along a-c: the same diagonal in every quad
        of a grid leaves its inner vertices with six triangles, Loop's regular valence."""
        if triangulate:
            self.add_face([a, b, c], outward)
            self.add_face([a, c, d], outward)
        else:
            self.add_face([a, b, c, d], outward)


def build():
    mesh = Mesh()
    fractions = [r / (RINGS - 1) for r in range(RINGS)]
    rings = [[mesh.add_vertex(ring_point(s, j)) for j in range(AROUND)] for s in fractions]
    for r in range(RINGS - 1):
        middle = 0.5 * (fractions[r] + fractions[r + 1])
        triangulate = ELBOW[0] <= middle < ELBOW[1]
        for j in range(AROUND):
            j1 = (j + 1) % AROUND
            a, b, c, d = rings[r][j], rings[r + 1][j], rings[r + 1][j1], rings[r][j1]
            x, y, z = mesh.vertices[a]
            mesh.add_quad(a, b, c, d, (0.0, y, z), triangulate)

    disk = cap_disk(CAP_GRID)
    for end, ring, sign, triangulate in ((0.0, rings[0], -1.0, False), (1.0, rings[-1], 1.0, True)):
        grid = {ik: ring[j] for j, ik in enumerate(boundary_of_grid(CAP_GRID))}
        x0, r = end * LENGTH, radius(end)
        for (i, k), (u, v) in disk.items():
            if (i, k) in grid:
                continue
            depth = 0.8 * r * math.sqrt(max(0.0, 1.0 - u * u - v * v))
            grid[(i, k)] = mesh.add_vertex((x0 + sign * depth, r * u, 0.85 * r * v))
        for i in range(CAP_GRID):
            for k in range(CAP_GRID):
                mesh.add_quad(grid[(i, k)], grid[(i + 1, k)], grid[(i + 1, k + 1)], grid[(i, k + 1)],
                              (sign, 0.0, 0.0), triangulate)

    def ring_at(s):
        return min(range(RINGS), key=lambda r: abs(fractions[r] - s))

    # A ridge along the top of the upper arm (ring vertex AROUND/4, at phi = 90 degrees).
    top = AROUND // 4
    for r in range(ring_at(0.08), ring_at(0.30)):
        mesh.creases.append((rings[r][top], rings[r + 1][top], 1.0))
    for s, sharpness in ((0.55, 1.5), (0.86, 2.5)):  # a ring in the elbow's triangles, a wrist band
        ring = rings[ring_at(s)]
        for j in range(AROUND):
            mesh.creases.append((ring[j], ring[(j + 1) % AROUND], sharpness))
    return mesh


def number(x):
    """x with 5 decimals, trailing zeros dropped ("0.5", "-1.25", "0")."""
    text = ("%.5f" % x).rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def write(mesh, out):
    quads = sum(1 for f in mesh.faces if len(f) == 4)
    out.write("# mixed_limb: a limb along x for quadtri's real-time demo, written by tools/make_limb.py\n")
    out.write("# %d vertices, %d faces (%d quads, %d triangles), %d crease edges\n"
              % (len(mesh.vertices), len(mesh.faces), quads, len(mesh.faces) - quads, len(mesh.creases)))
    for p in mesh.vertices:
        out.write("v %s\n" % " ".join(number(c) for c in p))
    for f in mesh.faces:
        out.write("f %s\n" % " ".join(str(c + 1) for c in f))
    for a, b, s in mesh.creases:
        out.write("t crease 2/1/0 %d %d %g\n" % (a, b, s))


if __name__ == "__main__":
    write(build(), sys.stdout)
