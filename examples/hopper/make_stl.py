#!/usr/bin/env python3
"""make_stl.py: writes hopper.stl, the conical hopper of the hopper example
(examples/hopper/hopper.c), as a CAD program would: an ASCII STL in
millimetres with z up.

The hopper is a cone of half-angle 30 degrees from the vertical, from a
circular orifice of 42 mm diameter at z = 0 up to a diameter of 120 mm,
and above it a cylindrical bin of that diameter, 100 mm high; both open.
Each is a band of 2 n triangles between rings of n = 48 points, so the file
has 192 triangles. The facets' normals point out of the hopper (the library
does not use them). Run it from anywhere; it writes hopper.stl beside
itself:

    python3 examples/hopper/make_stl.py
"""

import math
import os

N = 48                 # points per ring
R_ORIFICE = 21.0       # mm
R_BIN = 60.0           # mm
HALF_ANGLE = 30.0      # degrees from the vertical
BIN_HEIGHT = 100.0     # mm


def ring(radius, z):
    return [(radius * math.cos(2 * math.pi * k / N), radius * math.sin(2 * math.pi * k / N), z)
            for k in range(N)]


def band(lower, upper):
    """Triangles between two rings, wound counter-clockwise seen from outside."""
    tris = []
    for k in range(N):
        a, b = lower[k], lower[(k + 1) % N]
        c, d = upper[k], upper[(k + 1) % N]
        tris += [(a, b, d), (a, d, c)]
    return tris


def normal(t):
    a, b, c = t
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    s = math.sqrt(sum(x * x for x in n))
    return [x / s for x in n]


def main():
    cone_height = (R_BIN - R_ORIFICE) / math.tan(math.radians(HALF_ANGLE))
    rings = [ring(R_ORIFICE, 0.0), ring(R_BIN, cone_height), ring(R_BIN, cone_height + BIN_HEIGHT)]
    tris = band(rings[0], rings[1]) + band(rings[1], rings[2])
    fmt = lambda p: " ".join("%.6f" % x for x in p)
    lines = ["solid hopper"]
    for t in tris:
        lines.append("  facet normal " + " ".join("%.6f" % x for x in normal(t)))
        lines.append("    outer loop")
        lines += ["      vertex " + fmt(p) for p in t]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid hopper")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "hopper.stl")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{path}: {len(tris)} triangles, cone {cone_height:.3f} mm high")


if __name__ == "__main__":
    main()
