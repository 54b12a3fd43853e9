"""vtk_readback: the library's VTK files, read back with VTK's own readers.

Runs io_vtk_scene (its path in the environment variable DEMILL_VTK_SCENE)
into a temporary directory and reads what it wrote with
vtkXMLUnstructuredGridReader and vtkXMLPolyDataReader (Debian's
python3-vtk9), and the .pvd with xml.etree. Every expected value is derived
here from the scenes' definitions (the formulas at the top of
io_vtk_scene.c, repeated below), not taken from the library: positions,
velocities, spins, radii and materials as set; 3D orientations as set,
normalised; masses 4/3 pi r^3 rho;
forces m g (nothing touches); the shell's points on the circle of radius
D/2; lifters at their polar angle plus the drum's angle (speed times the
world's time); the plane's patch on the plane, facing its normal, as wide as
the scene's box; the finite walls' points on their surfaces; the series'
frames at increasing times and in free fall between them; the clumps'
members named by their clump, at their template's place, with its
orientation and the mass of the union of its spheres. Without the vtk module the test fails: CI installs it.
"""
import math
import os
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ET

try:
    import vtk
except ImportError as e:  # a failure, not a skip: .ci/deps installs python3-vtk9
    raise ImportError("vtk_readback needs VTK's Python module (apt-get install python3-vtk9) "
                      "and the Python it belongs to (/usr/bin/python3): %s" % e)

G = -9.81
DT = 1e-5
KIND_PARTICLE, KIND_WALL, KIND_DRUM = 2, 3, 4  # bits 51..48 of an id (docs/design.md)


def kind(ident):
    return (int(ident) >> 48) & 0xF


def sphere_mass(r, rho):
    return 4.0 / 3.0 * math.pi * r ** 3 * rho


# ---- the scenes (io_vtk_scene.c) ----
def particles3d():
    out = []
    for k in range(16):
        out.append(dict(
            x=(-0.09 + 0.012 * k, 0.02 * (k % 4) - 0.03, 0.01 * (k % 3 - 1)),
            r=0.004 + 0.0001 * k,
            v=(0.1 * k, -0.2, 0.05 * (k % 2)),
            w=(1.0 + k, -k, 0.5 * k),
            q=(1.0, 0.1 * k, -0.2, 0.05 * k),
            material=0 if k < 10 else 1,
            rho=7800.0 if k < 10 else 2500.0))
    return out


def particles2d():
    return [dict(x=(-0.07 + 0.02 * k, 0.01 * (k % 2), 0.0), r=0.006, v=(0.05 * k, 0.1, 0.0),
                 w=(0.0, 0.0, 2.0 * k), material=0, rho=7800.0) for k in range(8)]


DRUM3 = dict(R=0.15, L=0.1, lifters=4, h=0.02, width=0.03, speed=2.0, phase=1.5 * math.pi)
DRUM2 = dict(R=0.2, L=0.1, lifters=6, h=0.03, width=0.04, speed=-1.5, phase=1.5 * math.pi)
PLANE3 = dict(p=(0.0, -0.25, 0.0), n=(0.2, 1.0, -0.1))
PLANE2 = dict(p=(0.0, -0.3, 0.0), n=(0.3, 1.0, 0.0))
SEGMENTS = 120


# ---- reading ----
def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu") \
        else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode():
        raise AssertionError("VTK could not read %s (error %d)" % (path, reader.GetErrorCode()))
    return reader.GetOutput()


def array(data, name, where="point"):
    arrays = data.GetPointData() if where == "point" else \
        data.GetCellData() if where == "cell" else data.GetFieldData()
    a = arrays.GetAbstractArray(name)
    if a is None:
        raise AssertionError("no %s array %r" % (where, name))
    n, c = a.GetNumberOfTuples(), a.GetNumberOfComponents()
    return [tuple(a.GetComponent(i, j) for j in range(c)) if c > 1 else a.GetValue(i)
            for i in range(n)]


def points(data):
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def time_of(data):
    return array(data, "TimeValue", "field")[0]


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def unit(v):
    n = norm(v)
    return tuple(c / n for c in v)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def cells(data):
    """Every cell as (kind, [point ids]): lines first, then polygons (VTK's order)."""
    out = []
    for name, arr in (("line", data.GetLines()), ("poly", data.GetPolys())):
        ids = vtk.vtkIdList()
        arr.InitTraversal()
        while arr.GetNextCell(ids):
            out.append((name, [ids.GetId(i) for i in range(ids.GetNumberOfIds())]))
    return out


def angle_diff(a, b):
    return abs(math.remainder(a - b, 2 * math.pi))


class ReadBack(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        exe = os.environ.get("DEMILL_VTK_SCENE")
        if not exe:
            raise AssertionError("DEMILL_VTK_SCENE must name the io_vtk_scene program")
        cls.tmp = tempfile.TemporaryDirectory(prefix="demill-vtk-")
        cls.dir = cls.tmp.name
        os.mkdir(os.path.join(cls.dir, "series"))
        subprocess.run([exe, cls.dir], check=True)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def close(self, got, want, tol, what):
        self.assertLessEqual(abs(got - want), tol, "%s: %.17g, expected %.17g" % (what, got, want))

    def close_vec(self, got, want, tol, what):
        for c in range(3):
            self.close(got[c], want[c], tol, "%s[%d]" % (what, c))

    # ---- particles ----
    def check_particles(self, data, want, dim):
        n = len(want)
        self.assertEqual(data.GetNumberOfPoints(), n)
        self.assertEqual(data.GetNumberOfCells(), n)
        for i in range(n):
            self.assertEqual(data.GetCellType(i), vtk.VTK_VERTEX)
            self.assertEqual(data.GetCell(i).GetPointId(0), i)
        ids = array(data, "id")
        self.assertEqual(len(set(ids)), n, "ids are not unique")
        self.assertTrue(all(kind(i) == KIND_PARTICLE for i in ids), "not particle ids")
        self.assertEqual(sorted(ids, key=lambda i: int(i) & 0xFFFFFFFF), ids, "not in id order")
        x, r, m = points(data), array(data, "radius"), array(data, "mass")
        v, w = array(data, "velocity"), array(data, "angular_velocity")
        f, t, mat = array(data, "force"), array(data, "torque"), array(data, "material")
        for k, p in enumerate(want):
            self.close_vec(x[k], p["x"], 1e-15, "position of %d" % k)
            self.close(r[k], p["r"], 1e-15, "radius of %d" % k)
            self.close_vec(v[k], p["v"], 1e-15, "velocity of %d" % k)
            self.close_vec(w[k], p["w"], 1e-15, "angular velocity of %d" % k)
            self.assertEqual(mat[k], p["material"])
            mass = sphere_mass(p["r"], p["rho"])
            self.close(m[k], mass, 1e-12 * mass, "mass of %d" % k)
            self.close_vec(f[k], (0, mass * G, 0), 1e-12 * mass, "force on %d" % k)
            self.close_vec(t[k], (0, 0, 0), 0, "torque on %d" % k)
            if dim == 2:
                self.assertEqual(x[k][2], 0.0)
        if dim == 2:
            self.assertEqual(array(data, "angle"), [0.0] * n)
            self.assertIsNone(data.GetPointData().GetAbstractArray("orientation"))
        else:
            self.assertIsNone(data.GetPointData().GetAbstractArray("angle"))
            self.assertEqual(data.GetPointData().GetArray("orientation").GetNumberOfComponents(), 4)
            q = array(data, "orientation")
            for k, p in enumerate(want):
                norm = math.sqrt(sum(c * c for c in p["q"]))
                for c in range(4):
                    self.close(q[k][c], p["q"][c] / norm, 1e-15, "orientation of %d" % k)

    def test_particles_3d(self):
        data = read(self.path("3d_particles.vtu"))
        self.check_particles(data, particles3d(), 3)
        self.close(time_of(data), 1000 * DT, 1e-15, "time")

    def test_particles_2d(self):
        data = read(self.path("2d_particles.vtu"))
        self.check_particles(data, particles2d(), 2)
        self.close(time_of(data), 500 * DT, 1e-15, "time")

    def test_clumps(self):
        """The clumps scene: the clump array names each member's clump by
        the index of its id (clumps 0 and 2, clump 1 removed), -1 for the
        free spheres; members sit at X +- R(q) (d/2, 0, 0), d = 5 mm apart
        along the dumbbell's axis (its principal axis of least inertia, of
        either sign), with the clump's orientation and mass: rho times the
        union of two spheres of radius r at distance d, 2 (4/3 pi r^3)
        minus the lens pi (4 r + d) (2 r - d)^2 / 12 (Weisstein,
        "Sphere-Sphere Intersection", MathWorld)."""
        data = read(self.path("clumps_particles.vtu"))
        self.assertEqual(data.GetNumberOfPoints(), 6)
        self.assertEqual(array(data, "clump"), [-1, 0, 0, 2, 2, -1])
        r, d, rho = 0.004, 0.005, 7800.0
        mass = rho * (2 * 4.0 / 3.0 * math.pi * r ** 3 -
                      math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12)
        x, q, m, rad = points(data), array(data, "orientation"), array(data, "mass"), \
            array(data, "radius")
        self.close_vec(x[0], (-0.05, 0, 0), 0, "free sphere")
        self.close_vec(x[5], (0.2, 0, 0), 0, "free sphere")
        for k, pair in ((0, (1, 2)), (2, (3, 4))):
            want = (1.0, 0.2 * k, -0.1, 0.3)
            n = math.sqrt(sum(c * c for c in want))
            w_, i, j, l = (c / n for c in want)
            # the body x axis in the world frame: the first column of R(q)
            axis = (1 - 2 * (j * j + l * l), 2 * (i * j + w_ * l), 2 * (i * l - w_ * j))
            centre = (0.05 * k, 0.1, 0.0)
            ends = [tuple(centre[c] + s * 0.5 * d * axis[c] for c in range(3)) for s in (-1, 1)]
            got = [x[p] for p in pair]
            if norm(sub(got[0], ends[0])) > norm(sub(got[0], ends[1])):
                ends.reverse()
            for p, e in zip(got, ends):
                self.close_vec(p, e, 1e-15, "member of clump %d" % k)
            for p in pair:
                for c in range(4):
                    self.close(q[p][c], (w_, i, j, l)[c], 1e-15, "orientation of member %d" % p)
                self.close(m[p], mass, 1e-12 * mass, "mass of member %d" % p)
                self.close(rad[p], r, 0, "radius of member %d" % p)

    def test_empty(self):
        data = read(self.path("empty_particles.vtu"))
        self.assertEqual(data.GetNumberOfPoints(), 0)
        self.assertEqual(data.GetNumberOfCells(), 0)
        self.assertEqual(array(data, "radius"), [])
        walls = read(self.path("empty_walls.vtp"))
        self.assertEqual(walls.GetNumberOfPoints(), 0)
        self.assertEqual(walls.GetNumberOfCells(), 0)

    # ---- walls ----
    def scene_box(self, parts, drum, plane, dim):
        lo, hi = [math.inf] * 3, [-math.inf] * 3
        for p in parts:
            for c in range(3):
                lo[c] = min(lo[c], p["x"][c] - p["r"])
                hi[c] = max(hi[c], p["x"][c] + p["r"])
        if drum:
            half_length = drum["L"] / 2 if dim == 3 else 0.0
            for c, e in enumerate((drum["R"], drum["R"], half_length)):
                lo[c], hi[c] = min(lo[c], -e), max(hi[c], e)
        for c in range(3):
            lo[c], hi[c] = min(lo[c], plane["p"][c]), max(hi[c], plane["p"][c])
        if dim == 2:
            lo[2] = hi[2] = 0.0
        centre = tuple((a + b) / 2 for a, b in zip(lo, hi))
        return centre, norm(sub(hi, lo)) / 2 or 0.5

    def check_plane(self, pts, cell_list, plane, box, dim):
        n = unit(plane["n"])
        centre, half = box
        self.assertEqual(len(cell_list), 1)
        ids = cell_list[0][1]
        corners = [pts[i] for i in ids]
        for q in corners:
            self.close(dot(sub(q, plane["p"]), n), 0.0, 1e-12, "distance from the plane")
        mid = tuple(sum(q[c] for q in corners) / len(corners) for c in range(3))
        foot = sub(centre, tuple(dot(sub(centre, plane["p"]), n) * c for c in n))
        self.close_vec(mid, foot, 1e-12, "patch centre")
        if dim == 2:
            self.assertEqual(cell_list[0][0], "line")
            self.close(norm(sub(corners[1], corners[0])), 2 * half, 1e-12, "segment length")
            return
        self.assertEqual(cell_list[0][0], "poly")
        self.assertEqual(len(corners), 4)
        for k in range(4):
            self.close(norm(sub(corners[(k + 1) % 4], corners[k])), 2 * half, 1e-12, "side")
        normal = unit(cross(sub(corners[1], corners[0]), sub(corners[2], corners[0])))
        self.close_vec(normal, n, 1e-12, "patch normal")

    def check_walls(self, data, dim, drum, plane, parts):
        pts = points(data)
        part, lifter, wall = array(data, "part", "cell"), array(data, "lifter", "cell"), \
            array(data, "wall", "cell")
        cl = cells(data)
        self.assertEqual(len(cl), len(part))
        by_part = {p: [c for c, q in zip(cl, part) if q == p] for p in range(4)}
        self.assertEqual(set(part), {0, 1, 3} if dim == 2 else {0, 1, 2, 3})
        for c, p, l, i in zip(cl, part, lifter, wall):
            self.assertEqual(kind(i), KIND_WALL if p == 0 else KIND_DRUM)
            self.assertEqual(l >= 0, p == 3)
        self.assertEqual(len({i for i, p in zip(wall, part) if p}), 1, "one drum id")
        time = time_of(data)
        theta = drum["speed"] * time
        R, L = drum["R"], drum["L"] / 2

        # the plane's patch
        self.check_plane(pts, by_part[0], plane, self.scene_box(parts, drum, plane, dim), dim)

        # the shell: 2D a closed line, 3D quadrilaterals facing the axis
        shell = by_part[1]
        if dim == 2:
            self.assertEqual([c[0] for c in shell], ["line"])
            ids = shell[0][1]
            self.assertEqual(len(ids), SEGMENTS + 1)
            self.assertEqual(ids[0], ids[-1])
        else:
            self.assertEqual(len(shell), SEGMENTS)
            for _, ids in shell:
                q = [pts[i] for i in ids]
                normal = cross(sub(q[1], q[0]), sub(q[2], q[0]))
                mid = tuple(sum(p[c] for p in q) / 4 for c in range(3))
                self.assertLess(dot(normal, (mid[0], mid[1], 0)), 0, "shell faces away")
        shell_ids = {i for _, ids in shell for i in ids}
        for i in shell_ids:
            self.close(math.hypot(pts[i][0], pts[i][1]), R, 1e-14, "shell radius")
            self.assertIn(pts[i][2], (-L, L) if dim == 3 else (0.0,))
        # its vertices turn with the drum: one at the drum's angle
        self.assertTrue(any(angle_diff(math.atan2(pts[i][1], pts[i][0]), theta) < 1e-9
                            for i in shell_ids), "no shell vertex at the drum angle")

        # the end caps (3D): discs of the shell's radius facing into the drum
        if dim == 3:
            caps = by_part[2]
            self.assertEqual(len(caps), 2)
            for _, ids in caps:
                q = [pts[i] for i in ids]
                self.assertEqual(len(q), SEGMENTS)
                z = q[0][2]
                self.assertIn(z, (-L, L))
                for p in q:
                    self.close(math.hypot(p[0], p[1]), R, 1e-14, "cap radius")
                    self.assertEqual(p[2], z)
                normal = cross(sub(q[1], q[0]), sub(q[2], q[0]))
                self.assertLess(normal[2] * z, 0, "cap faces away from the particles")

        # lifters: inside the shell, reaching D/2 - h (at their top corners),
        # centred on their polar angle turned by the drum's angle
        lifters = by_part[3]
        got = sorted({l for l, p in zip(lifter, part) if p == 3})
        self.assertEqual(got, list(range(drum["lifters"])))
        top = math.hypot(R - drum["h"], drum["width"] / 2)
        for k in range(drum["lifters"]):
            ids = sorted({i for (c, l, p) in zip(cl, lifter, part) if p == 3 and l == k
                          for i in c[1]})
            q = [pts[i] for i in ids]
            radii = [math.hypot(p[0], p[1]) for p in q]
            self.assertLessEqual(max(radii), R + 1e-14)
            self.close(max(radii), R, 1e-14, "lifter %d reaches the shell" % k)
            self.close(min(radii), top, 1e-14, "lifter %d top" % k)
            mid = (sum(p[0] for p in q), sum(p[1] for p in q))
            want = drum["phase"] + 2 * math.pi * k / drum["lifters"] + theta
            self.assertLess(angle_diff(math.atan2(mid[1], mid[0]), want), 1e-9,
                            "lifter %d is not at its angle" % k)
            for p in q:
                self.assertIn(p[2], (-L, L) if dim == 3 else (0.0,))
            n_cells = sum(1 for l, p in zip(lifter, part) if p == 3 and l == k)
            if dim == 2:
                self.assertEqual(n_cells, 1)
            else:  # a side per edge of the section, and its two ends
                self.assertEqual(n_cells, len(q) // 2 + 2)

    def test_walls_3d(self):
        data = read(self.path("3d_walls.vtp"))
        self.close(time_of(data), 1000 * DT, 1e-15, "time")
        self.check_walls(data, 3, DRUM3, PLANE3, particles3d())

    def test_walls_2d(self):
        data = read(self.path("2d_walls.vtp"))
        self.close(time_of(data), 500 * DT, 1e-15, "time")
        self.check_walls(data, 2, DRUM2, PLANE2, particles2d())

    def test_plane_alone(self):
        data = read(self.path("plane_walls.vtp"))
        self.assertEqual(array(data, "part", "cell"), [0])
        # a scene of one point has no extent: the patch is 1 m wide
        self.check_plane(points(data), cells(data), PLANE3, (PLANE3["p"], 0.5), 3)

    def test_finite_walls(self):
        """Every point of a finite wall's cells lies on its surface: the
        cylinder's at radius 0.1 from its axis between heights 0 and 0.2
        (its caps' at height 0 or 0.2 and radius 0 or 0.1), the cone's at
        radius h from its axis (apex at h = 0), the annulus's in its plane
        at radius 0.04 or 0.1, the rectangle's at its 4 corners; 120 cells
        for each surface of revolution (side, caps, cone, annulus) and one
        for the rectangle; all of part 0, one wall id per wall."""
        data = read(self.path("finite_walls.vtp"))
        pts, cl = points(data), cells(data)
        part, wall = array(data, "part", "cell"), array(data, "wall", "cell")
        self.assertEqual(set(part), {0})
        ids = sorted(set(wall), key=wall.index)
        self.assertEqual(len(ids), 4)
        self.assertTrue(all(kind(i) == KIND_WALL for i in ids), "not wall ids")
        by_wall = [[c for c, i in zip(cl, wall) if i == w] for w in ids]
        self.assertEqual([len(c) for c in by_wall], [360, 120, 120, 1])

        def on(k, test, what):
            for name, c in by_wall[k]:
                self.assertEqual(name, "poly")
                for q in c:
                    self.assertTrue(test(pts[q]), "%s: point %s" % (what, pts[q]))

        def near(a, b):
            return abs(a - b) <= 1e-12

        on(0, lambda p: (near(math.hypot(p[0], p[2]), 0.1) and -1e-12 <= p[1] <= 0.2 + 1e-12)
           or ((near(p[1], 0) or near(p[1], 0.2)) and math.hypot(p[0], p[2]) <= 0.1 + 1e-12),
           "cylinder")
        on(1, lambda p: near(math.hypot(p[0] - 0.5, p[1]), p[2]) and -1e-12 <= p[2] <= 0.1 + 1e-12,
           "cone")
        on(2, lambda p: near(p[0], -0.5) and (near(math.hypot(p[1], p[2]), 0.1) or
                                              near(math.hypot(p[1], p[2]), 0.04)), "annulus")
        corners = {(sx * 0.2, 0.0, 0.5 + sz * 0.1) for sx in (-1, 1) for sz in (-1, 1)}
        got = {tuple(round(c, 12) + 0.0 for c in pts[q]) for q in by_wall[3][0][1]}
        self.assertEqual(got, corners)

    def test_loads(self):
        """The floor's two triangles record a ball of mass m at rest on
        triangle 0 at its equilibrium overlap: normal force m g, mean
        pressure m g over the triangle's area 0.02 m², no shear work;
        triangle 1 nothing; the rectangle, which records nothing, NaN. A
        scene where no wall records has no such arrays."""
        data = read(self.path("loads_walls.vtp"))
        wall = array(data, "wall", "cell")
        normal, pressure, shear = (array(data, name, "cell") for name in
                                   ("normal_force", "mean_pressure", "shear_work"))
        ids = sorted(set(wall), key=wall.index)
        self.assertEqual([wall.count(i) for i in ids], [2, 1])
        mg = sphere_mass(0.01, 7800.0) * -G
        self.close(normal[0], mg, 1e-9 * mg, "normal force")
        self.close(pressure[0], mg / 0.02, 1e-9 * mg / 0.02, "mean pressure")
        self.assertEqual((normal[1], pressure[1]), (0.0, 0.0))
        self.assertLessEqual(abs(shear[0]) + abs(shear[1]), 1e-15)
        self.assertTrue(all(math.isnan(a[2]) for a in (normal, pressure, shear)))
        plane = read(self.path("plane_walls.vtp"))
        self.assertIsNone(plane.GetCellData().GetAbstractArray("normal_force"))

    # ---- the series ----
    def test_series(self):
        pvd = self.path("series/mill.pvd")
        root = ET.parse(pvd).getroot()
        self.assertEqual(root.get("type"), "Collection")
        sets = root.findall("./Collection/DataSet")
        self.assertEqual(len(sets), 6)
        times = sorted({float(d.get("timestep")) for d in sets})
        self.assertEqual(len(times), 3)
        for f, t in enumerate(times):
            self.close(t, (1000 + 100 * f) * DT, 1e-15, "time of frame %d" % f)
        frames = []
        for f, t in enumerate(times):
            here = {d.get("part"): d.get("file") for d in sets if float(d.get("timestep")) == t}
            self.assertEqual(here, {"0": "mill_particles_%06d.vtu" % f,
                                    "1": "mill_walls_%06d.vtp" % f})
            for name in here.values():
                self.assertTrue(os.path.isfile(self.path("series/" + name)), name)
            data = read(self.path("series/" + here["0"]))
            self.assertEqual(time_of(data), t)  # exactly: the .pvd has 17 digits
            self.assertEqual(time_of(read(self.path("series/" + here["1"]))), t)
            frames.append(data)
        self.assertEqual(sorted(os.listdir(self.path("series"))),
                         sorted(["mill.pvd"] + [d.get("file") for d in sets]))
        # frame 0 is the scene as set; then free fall: x + v t + g t^2 / 2
        self.check_particles(frames[0], particles3d(), 3)
        ids0 = array(frames[0], "id")
        for f in (1, 2):
            self.assertEqual(array(frames[f], "id"), ids0)
            tau = times[f] - times[0]
            x, v, w = points(frames[f]), array(frames[f], "velocity"), \
                array(frames[f], "angular_velocity")
            for k, p in enumerate(particles3d()):
                fall = (p["x"][0] + p["v"][0] * tau, p["x"][1] + p["v"][1] * tau +
                        0.5 * G * tau * tau, p["x"][2] + p["v"][2] * tau)
                self.close_vec(x[k], fall, 1e-12, "frame %d position of %d" % (f, k))
                self.close_vec(v[k], (p["v"][0], p["v"][1] + G * tau, p["v"][2]), 1e-12,
                               "frame %d velocity of %d" % (f, k))
                self.close_vec(w[k], p["w"], 0, "frame %d spin of %d" % (f, k))


if __name__ == "__main__":
    unittest.main()
