#!/usr/bin/env python3
"""make_stl.py: writes rock.stl, the rock-like shape of the mesh_clump
example (examples/mesh_clump.c, docs/shapes.md, Shapes from a mesh), as a
scanner's software might: an ASCII STL in millimetres.

The rock is an icosphere (an icosahedron's faces split in four 3 times,
1280 triangles, 642 vertices) whose vertices are moved along their
directions u from the centre to the radius

    r(u) = min(1 + sum_k a_k exp(-(1 - u.d_k) / 0.2),  min over the cuts
               with u.n_j > 0 of h_j / (u.n_j))

smooth bumps and dents (8 random directions d_k, amplitudes a_k in
[-0.12, 0.12]) cut flat by 6 random planes at distances h_j in [0.72,
0.9] from the centre, as a crushed stone's faces, then stretched to
semi-axes 30, 21 and 15 mm. Every vertex stays on its own ray from the
centre, so the surface stays closed and never crosses itself; the
triangles keep the icosphere's winding, counter-clockwise seen from
outside. The random numbers come from Python's Mersenne Twister seeded with
SEED, so the file is the same on every run. It prints the triangles and the
volume the mesh encloses (the sum of the signed tetrahedra from the origin
to each triangle, computed from the coordinates as written). Run it from
anywhere; it writes rock.stl beside itself:

    python3 examples/rock/make_stl.py
"""

import math
import os
import random

SEED = 2024
LEVEL = 3
SEMI_AXES = (30.0, 21.0, 15.0)  # mm
BUMPS, CUTS = 8, 6


def unit(p):
    s = math.sqrt(sum(x * x for x in p))
    return tuple(x / s for x in p)


def icosphere(level):
    """Unit vertices and triangles (counter-clockwise seen from outside)."""
    g = (1 + math.sqrt(5)) / 2
    verts = [unit(p) for p in [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g),
                               (0, 1, g), (0, -1, -g), (0, 1, -g), (g, 0, -1), (g, 0, 1),
                               (-g, 0, -1), (-g, 0, 1)]]
    tris = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
            (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
            (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        mid = {}

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                verts.append(unit([(verts[a][i] + verts[b][i]) / 2 for i in range(3)]))
                mid[key] = len(verts) - 1
            return mid[key]

        new = []
        for a, b, c in tris:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            new += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        tris = new
    return verts, tris


def direction(rng):
    while True:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        s = sum(x * x for x in p)
        if 0.01 < s <= 1:
            return unit(p)


def main():
    rng = random.Random(SEED)
    bumps = [(direction(rng), rng.uniform(-0.12, 0.12)) for _ in range(BUMPS)]
    cuts = [(direction(rng), rng.uniform(0.72, 0.9)) for _ in range(CUTS)]
    verts, tris = icosphere(LEVEL)
    points = []
    for u in verts:
        r = 1 + sum(a * math.exp(-(1 - sum(u[i] * d[i] for i in range(3))) / 0.2)
                    for d, a in bumps)
        for n, h in cuts:
            c = sum(u[i] * n[i] for i in range(3))
            if c > 0:
                r = min(r, h / c)
        points.append(tuple(float("%.6f" % (SEMI_AXES[i] * r * u[i])) for i in range(3)))
    fmt = lambda p: " ".join("%.6f" % x for x in p)
    lines = ["solid rock"]
    volume = 0.0
    for t in tris:
        a, b, c = (points[k] for k in t)
        e, f = [b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)]
        n = unit([e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]])
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
        lines.append("  facet normal " + fmt(n))
        lines.append("    outer loop")
        lines += ["      vertex " + fmt(p) for p in (a, b, c)]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid rock")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rock.stl")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{path}: {len(tris)} triangles, {len(points)} vertices, volume {volume:.1f} mm^3")


if __name__ == "__main__":
    main()
