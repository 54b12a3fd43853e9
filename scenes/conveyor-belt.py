#!/usr/bin/env python3
"""Writes scenes/conveyor-belt.stl, the troughed belt of scenes/conveyor.yaml:
the carrying side of a belt 18 in (0.4572 m) wide on three equal idler
rolls, a flat centre panel and two wing panels troughed at 35 degrees (the
Conveyor Equipment Manufacturers Association's standard three-roll idler,
CEMA, Belt Conveyors for Bulk Materials), 2 m long along x from x = 0, the
centre panel in the plane y = 0 and the belt centred on z = 0. Two
triangles a panel, in metres.

usage: conveyor-belt.py [OUT.stl]"""

import math
import sys

WIDTH = 18 * 0.0254        # the belt's width, m
LENGTH = 2.0               # along x, m
TROUGH = math.radians(35)  # the wings' angle to the horizontal


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "conveyor-belt.stl"
    b = WIDTH / 3  # each panel's width
    h = b / 2
    # the panels' edges across the belt, (z, y), from one wing's top to the other's
    edges = [(-h - b * math.cos(TROUGH), b * math.sin(TROUGH)), (-h, 0.0), (h, 0.0),
             (h + b * math.cos(TROUGH), b * math.sin(TROUGH))]
    facets = []
    for (z0, y0), (z1, y1) in zip(edges, edges[1:]):
        a, b0, c, d = (0.0, y0, z0), (LENGTH, y0, z0), (LENGTH, y1, z1), (0.0, y1, z1)
        facets += [(a, d, c), (a, c, b0)]  # normals up, into the trough
    with open(out, "w") as f:
        f.write("solid conveyor_belt\n")
        for p, q, r in facets:
            u = [q[k] - p[k] for k in range(3)]
            v = [r[k] - p[k] for k in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            s = math.sqrt(sum(x * x for x in n))
            f.write("  facet normal %.6f %.6f %.6f\n    outer loop\n" % tuple(x / s + 0.0 for x in n))
            for x in (p, q, r):
                f.write("      vertex %.6f %.6f %.6f\n" % x)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid conveyor_belt\n")


if __name__ == "__main__":
    main()
