#!/usr/bin/python3
"""peers.py: geometry and particle files for the peer codes (LIGGGHTS, LAMMPS)
on the canonical scenes of docs/scenes.md.  Used by bench/run; no third-party
code.

  peers.py params SCENE              print the scene's numbers as KEY=VALUE lines
  peers.py stl SCENE OUT.stl         the drum as an ASCII STL mesh (LIGGGHTS)
  peers.py data CODE SCENE PACKING OUT.data
                                     a read_data file from `demill_bench
                                     --dump-packing` (x y z r per line)
  peers.py packing SCENE OUT         the packing of docs/scenes.md written here in
                                     Python (random.Random(12345)), the same
                                     numbers as demill_bench --dump-packing;
                                     bench/run falls back on it when libdemill
                                     does not build

drum3d mesh (docs/scenes.md): the shell is a 120-gon inscribed in R = 0.15 m
(vertices at 0, 3, 6, ... degrees, flat-to-flat radius 0.14995 m) split into 4
along z, the end caps z = +-0.05 m are fans from the axis to the shell's
vertices, and the 8 lifters are their inner face (0.135 m from the axis) and
two side faces (+-7.5 mm about the radial centre line, reaching just past the
shell, to 0.1505 m along the centre line), each split into 4 along z:
4*120*2 + 2*120 + 8*3*4*2 = 1392 triangles.

drum2d mesh: the same construction for R = 0.5 m, 30 mm lifters, without end
caps; one strip z in [-0.005, 0.005] (the box is periodic and wider in z) and
a 240-gon, so that the shell's sagitta (0.04 mm) is about that of drum3d's.
"""
import math
import sys

G = 9.81
RADIUS = 0.003
DENSITY = 7800.0
DT = 1e-5
SETTLE = 0.3   # s at rest
ROTATE = 0.3   # s of rotation before the timed window

SCENES = {
    # R, half-length, lifter height = width, lifters, N, shell polygon, z segments
    "drum3d": dict(R=0.15, half=0.05, lifter=0.015, nlift=8, n=10000, poly=120, zseg=4),
    "drum2d": dict(R=0.5, half=0.005, lifter=0.03, nlift=8, n=8000, poly=240, zseg=1),
}


def params(scene):
    s = SCENES[scene]
    D = 2 * s["R"]
    wc = math.sqrt(2 * G / (D - 2 * RADIUS))
    w = 0.75 * wc
    mass = DENSITY * 4.0 / 3.0 * math.pi * RADIUS ** 3
    return {
        "particles": s["n"],
        "omega": w,
        "omega_c": wc,
        "period": 2 * math.pi / w,
        "dt": DT,
        "settle_steps": int(round(SETTLE / DT)),
        "rotate_steps": int(round(ROTATE / DT)),
        "mass": mass,
        "total_mass": mass * s["n"],
    }


def packing(scene):
    """docs/scenes.md: a square (2D) / simple-cubic (3D) lattice of spacing 2.1 r =
    6.3 mm; the sites with x^2 + y^2 <= Rs^2 sorted by (y, x, z index), the
    lowest N kept; each coordinate jittered by uniform(-0.1, 0.1) mm from
    random.Random(12345) (drum3d: 15 layers from z = -0.046 m)."""
    import random
    a, jitter = 0.0063, 1e-4
    rs, layers, z0 = (0.131, 15, -0.046) if scene == "drum3d" else (0.466, 1, 0.0)
    span = int(rs / a) + 1
    sites = [(j, i, k) for j in range(-span, span + 1) for i in range(-span, span + 1)
             if (i * a) * (i * a) + (j * a) * (j * a) <= rs * rs for k in range(layers)]
    sites.sort()
    rng = random.Random(12345)
    out = []
    for j, i, k in sites[:SCENES[scene]["n"]]:
        x = i * a + rng.uniform(-jitter, jitter)
        y = j * a + rng.uniform(-jitter, jitter)
        z = z0 + k * a + rng.uniform(-jitter, jitter) if scene == "drum3d" else 0.0
        out.append("%.17g %.17g %.17g %.17g\n" % (x, y, z, RADIUS))
    return "".join(out)


def tri(out, a, b, c):
    ux, uy, uz = (b[i] - a[i] for i in range(3))
    vx, vy, vz = (c[i] - a[i] for i in range(3))
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    ln = math.sqrt(sum(x * x for x in n)) or 1.0
    out.append("  facet normal %.9e %.9e %.9e\n    outer loop\n" % tuple(x / ln for x in n))
    for p in (a, b, c):
        out.append("      vertex %.12e %.12e %.12e\n" % p)
    out.append("    endloop\n  endfacet\n")


def quad(out, a, b, c, d):
    """a-b-c-d in order around the quadrilateral"""
    tri(out, a, b, c)
    tri(out, a, c, d)


def stl(scene):
    s = SCENES[scene]
    R, half, h, npoly, nz = s["R"], s["half"], s["lifter"], s["poly"], s["zseg"]
    zs = [-half + 2 * half * k / nz for k in range(nz + 1)]
    out = ["solid %s\n" % scene]
    ring = [(R * math.cos(2 * math.pi * i / npoly), R * math.sin(2 * math.pi * i / npoly))
            for i in range(npoly)]
    # shell, normals towards the axis
    for i in range(npoly):
        (x0, y0), (x1, y1) = ring[i], ring[(i + 1) % npoly]
        for k in range(nz):
            quad(out, (x0, y0, zs[k]), (x0, y0, zs[k + 1]), (x1, y1, zs[k + 1]), (x1, y1, zs[k]))
    # end caps (3D only): fans from the axis, normals inwards
    if scene == "drum3d":
        for z, sgn in ((-half, 1), (half, -1)):
            for i in range(npoly):
                (x0, y0), (x1, y1) = ring[i], ring[(i + 1) % npoly]
                if sgn > 0:
                    tri(out, (0.0, 0.0, z), (x0, y0, z), (x1, y1, z))
                else:
                    tri(out, (0.0, 0.0, z), (x1, y1, z), (x0, y0, z))
    # lifters: inner face and two side faces
    r_in, r_out = R - h, R + 0.0005
    for k in range(s["nlift"]):
        phi = math.radians(270.0 + 45.0 * k)
        u = (math.cos(phi), math.sin(phi))
        t = (-math.sin(phi), math.cos(phi))

        def P(r, w, z):
            return (r * u[0] + w * t[0], r * u[1] + w * t[1], z)

        for j in range(nz):
            z0, z1 = zs[j], zs[j + 1]
            quad(out, P(r_in, -h / 2, z0), P(r_in, h / 2, z0), P(r_in, h / 2, z1), P(r_in, -h / 2, z1))
            quad(out, P(r_in, -h / 2, z0), P(r_in, -h / 2, z1), P(r_out, -h / 2, z1), P(r_out, -h / 2, z0))
            quad(out, P(r_in, h / 2, z0), P(r_out, h / 2, z0), P(r_out, h / 2, z1), P(r_in, h / 2, z1))
    out.append("endsolid %s\n" % scene)
    return "".join(out)


def data(code, scene, packing):
    """read_data file: atom_style granular (LIGGGHTS) / sphere (LAMMPS), both
    `id type diameter density x y z`.  LIGGGHTS in 2D takes the mass as
    density * pi r^2, so drum2d gets the areal density 4/3 r rho = 31.2 kg/m^2
    there; LAMMPS (2022) takes 4/3 pi r^3 density in 2D as in 3D."""
    s = SCENES[scene]
    pts = [list(map(float, line.split())) for line in open(packing) if line.strip()]
    if len(pts) != s["n"]:
        sys.exit("peers.py: %s has %d particles, %s needs %d" % (packing, len(pts), scene, s["n"]))
    R = s["R"] + 0.01
    if scene == "drum3d":
        zlo, zhi = -s["half"] - 0.01, s["half"] + 0.01
    else:
        zlo, zhi = -0.01, 0.01
    out = ["# %s %s: %d spheres from demill_bench --dump-packing\n\n" % (code, scene, len(pts)),
           "%d atoms\n1 atom types\n\n" % len(pts),
           "%.6f %.6f xlo xhi\n%.6f %.6f ylo yhi\n%.6f %.6f zlo zhi\n\nAtoms\n\n" % (-R, R, -R, R, zlo, zhi)]
    for i, (x, y, z, r) in enumerate(pts):
        rho = DENSITY
        if scene == "drum2d" and code == "liggghts":
            rho = DENSITY * 4.0 / 3.0 * r  # areal density: rho*pi*r^2 = sphere mass
        out.append("%d 1 %.17g %.17g %.17g %.17g %.17g\n" % (i + 1, 2 * r, rho, x, y, z))
    return "".join(out)


def main(argv):
    if len(argv) >= 2 and argv[0] == "params" and argv[1] in SCENES:
        for k, v in params(argv[1]).items():
            print("%s=%s" % (k, repr(v)))
    elif len(argv) == 3 and argv[0] == "packing" and argv[1] in SCENES:
        with open(argv[2], "w") as f:
            f.write(packing(argv[1]))
    elif len(argv) == 3 and argv[0] == "stl" and argv[1] in SCENES:
        with open(argv[2], "w") as f:
            f.write(stl(argv[1]))
    elif len(argv) == 5 and argv[0] == "data" and argv[1] in ("liggghts", "lammps") and argv[2] in SCENES:
        with open(argv[4], "w") as f:
            f.write(data(argv[1], argv[2], argv[3]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
