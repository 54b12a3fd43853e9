"""The simulation world (``demill/world.h``) and everything reached from it."""

import ctypes
import os
import weakref
from typing import NamedTuple

import numpy as np

from ._core import (Closable, Keyed, Param, VectorParam, as_id, check, configure, doubles, ptr,
                    read_counted, strerror, vector)
from ._lib import ProgressFn, WorldP, lib
from .constants import BodyFlag, Caps, Energy, Integrator, Kind, Status, WorldKey
from .clumps import Clump, Template, particle_clump
from .drum import Drum
from .errors import BufferTooSmall, WorldClosed
from .flows import Feed, Outlet
from .objects import Body, Contacts, Material, Pair, Particle, Particles, Wall, count
from .state import Snapshot, VtkSeries


class TimeStep(NamedTuple):
    """What :meth:`World.suggest_time_step` suggests, all in s."""

    suggested: float
    critical: float
    contact_time: float


class Progress(NamedTuple):
    """What a progress callback (:meth:`World.on_progress`) is told."""

    steps_done: int
    steps_total: int
    time: float
    steps_per_second: float

    @property
    def fraction(self):
        """The share of the run done, 0 to 1."""
        return self.steps_done / self.steps_total if self.steps_total else 1.0

    @property
    def eta(self):
        """Estimated wall time left, s (inf before the rate is known)."""
        left = self.steps_total - self.steps_done
        return left / self.steps_per_second if self.steps_per_second > 0 else float("inf")


def _flag(value):
    return bool(round(value))


class World(Closable, Keyed):
    """A simulation world of dimension 2 or 3 that owns its materials,
    particles, walls and drum.

    ``World(3, time_step=1e-5)`` creates one and sets parameters by name.
    Use it as a context manager or call :meth:`close` to free it at once
    (otherwise it is freed when garbage-collected); any use after
    :meth:`close` raises :class:`~demill.WorldClosed`. Objects reached from
    a world (materials, walls, the drum, snapshots) keep it alive.

    Its properties are the ``DEMILL_WORLD_*`` keys; those from
    ``dimension`` on are read-only measurements.
    """

    time_step = Param(WorldKey.TIME_STEP)
    gravity_x = Param(WorldKey.GRAVITY_X)
    gravity_y = Param(WorldKey.GRAVITY_Y)
    gravity_z = Param(WorldKey.GRAVITY_Z)
    gravity = VectorParam((WorldKey.GRAVITY_X, WorldKey.GRAVITY_Y, WorldKey.GRAVITY_Z),
                          "Gravity, m/s^2, as an array of 3 (default (0, -9.81, 0)).")
    integrator = Param(WorldKey.INTEGRATOR, lambda v: Integrator(int(v)))
    skin = Param(WorldKey.SKIN)
    disc_thickness = Param(WorldKey.DISC_THICKNESS)
    energy_tracking = Param(WorldKey.ENERGY_TRACKING, _flag)
    time = Param(WorldKey.TIME)
    threads = Param(WorldKey.THREADS, int)
    refine_tolerance = Param(WorldKey.REFINE_TOLERANCE)
    refine_max_iterations = Param(WorldKey.REFINE_MAX_ITERATIONS, int)
    watchdog = Param(WorldKey.WATCHDOG, _flag)
    watchdog_overlap = Param(WorldKey.WATCHDOG_OVERLAP)
    watchdog_interval = Param(WorldKey.WATCHDOG_INTERVAL, int)
    single_precision = Param(WorldKey.SINGLE_PRECISION, _flag)
    orientation_tracking = Param(WorldKey.ORIENTATION_TRACKING, _flag)
    dimension = Param(WorldKey.DIMENSION, int)
    step_count = Param(WorldKey.STEP_COUNT, int)
    particle_count = Param(WorldKey.PARTICLE_COUNT, int)
    contact_count = Param(WorldKey.CONTACT_COUNT, int)
    wall_contact_count = Param(WorldKey.WALL_CONTACT_COUNT, int)
    neighbour_rebuilds = Param(WorldKey.NEIGHBOUR_REBUILDS, int)
    refine_iterations = Param(WorldKey.REFINE_ITERATIONS, int)
    force_evaluations = Param(WorldKey.FORCE_EVALUATIONS, int)
    refine_unconverged = Param(WorldKey.REFINE_UNCONVERGED, int)

    def __init__(self, dimension=3, **params):
        p = WorldP()
        code = lib.demill_world_create(int(dimension), ctypes.byref(p))
        check(code, f"demill_world_create({dimension}): {strerror(code)}")
        self._ptr = p
        self._finalizer = weakref.finalize(self, lib.demill_world_destroy, p)
        self._progress = None        # the C callback, kept alive while set
        self._progress_error = None  # an exception raised by the Python callback
        configure(self, params)

    # ---- lifetime and calls ------------------------------------------------

    def close(self):
        """Frees the world and everything it owns (again is harmless)."""
        super().close()
        self._progress = None

    def __repr__(self):
        if self.closed:
            return "<demill.World closed>"
        return (f"<demill.World {self.dimension}D, {self.particle_count} particles, "
                f"t = {self.time:g} s>")

    @property
    def _handle(self):
        if self.closed:
            raise WorldClosed(Status.INVALID_HANDLE, "the world is closed")
        return self._ptr

    @property
    def last_error(self):
        """The message of the last error on this world ("" if none)."""
        return lib.demill_world_last_error(self._handle).decode(errors="replace")

    def _call(self, name, *args):
        """Calls ``demill_<...>(world, *args)`` and raises its error."""
        code = getattr(lib, name)(self._handle, *args)
        if code != Status.OK:
            check(code, self.last_error)

    def _run(self, name, *args):
        """As :meth:`_call`, for calls that may run the progress callback:
        an exception the callback raised is raised again here."""
        self._progress_error = None
        try:
            self._call(name, *args)
        except Exception:
            error, self._progress_error = self._progress_error, None
            if error is not None:
                raise error
            raise

    # ---- parameters ------------------------------------------------------

    _getter, _setter = "demill_world_get", "demill_world_set"

    @property
    def world(self):
        """The world itself (as for the objects of a world)."""
        return self

    def _ids(self):
        return ()

    # ---- stepping --------------------------------------------------------

    def step(self, steps=1):
        """Advances the world by ``steps`` time steps (0 only evaluates the
        forces). Raises :class:`~demill.Unstable` if the watchdog finds the
        run unstable (the world is then at its last good state)."""
        self._run("demill_world_step", count(steps, "steps"))

    def settle(self, max_time, energy_per_particle):
        """Steps until the kinetic energy per particle is below
        ``energy_per_particle`` J or ``max_time`` s have passed; True if
        the charge settled."""
        settled = ctypes.c_int32()
        self._run("demill_world_settle", float(max_time), float(energy_per_particle),
                  ctypes.byref(settled))
        return bool(settled.value)

    def suggest_time_step(self, impact_speed=0.0, steps_per_contact=0.0):
        """A time step for the scene (:class:`TimeStep`: suggested, stability
        limit, shortest contact). 0 lets the library estimate the impact
        speed and takes 50 steps per contact."""
        out = [ctypes.c_double() for _ in range(3)]
        self._call("demill_world_suggest_time_step", float(impact_speed),
                   float(steps_per_contact), *(ctypes.byref(v) for v in out))
        return TimeStep(*(v.value for v in out))

    def on_progress(self, fn, every=1000):
        """Calls ``fn(progress)`` every ``every`` steps of :meth:`step` and
        :meth:`settle` with a :class:`Progress`; ``None`` removes it.

        A true return value stops the run (:class:`~demill.Interrupted`);
        an exception raised by ``fn`` stops it too and is raised again from
        the call that was running.
        """
        if fn is None:
            self._call("demill_world_set_progress", ProgressFn(), None, 0)
            self._progress = None
            return
        ref = weakref.ref(self)

        def trampoline(user_data, done, total, time, rate):
            try:
                return 1 if fn(Progress(done, total, time, rate)) else 0
            except BaseException as e:  # noqa: B036 - stop the run, re-raise later
                world = ref()
                if world is not None:
                    world._progress_error = e
                return 1

        c_fn = ProgressFn(trampoline)
        self._call("demill_world_set_progress", c_fn, None, count(every, "every"))
        self._progress = c_fn

    # ---- objects ---------------------------------------------------------

    def material(self, **params):
        """Creates a material with parameters by name, e.g.
        ``world.material(density=7800, youngs_modulus=2e11)``."""
        m = ctypes.c_uint64()
        self._call("demill_material_create", ctypes.byref(m))
        return configure(Material(self, m.value), params)

    def pair(self, a, b, **params):
        """The contact model of materials ``a`` and ``b`` (a :class:`Pair`),
        with parameters set by name, e.g.
        ``world.pair(steel, steel, normal=Normal.HERTZ)``."""
        return configure(Pair(self, a, b), params)

    set_pair = pair

    @property
    def particles(self):
        """All particles, read and written as NumPy arrays (:class:`Particles`)."""
        return Particles(self)

    @property
    def contacts(self):
        """The contacts at the current state (:class:`Contacts`)."""
        return Contacts(self)

    def particle(self, id_):
        """The particle of an id (a :class:`Particle`)."""
        return Particle(self, id_)

    def add_plane(self, material, point, normal):
        """Adds a plane wall through ``point`` facing ``normal``; a
        :class:`Wall`."""
        out = ctypes.c_uint64()
        self._call("demill_wall_add_plane", as_id(material),
                   ptr(vector(point, "point")), ptr(vector(normal, "normal")),
                   ctypes.byref(out))
        return Wall(self, out.value)

    def add_mesh(self, material, vertices, triangles):
        """Adds a triangle-mesh wall (3D): ``vertices`` n x 3 (m),
        ``triangles`` m x 3 vertex indices from 0. Particles touch it from
        both sides. A :class:`Wall`."""
        v = doubles(vertices, (-1, 3), "vertices")
        t = np.ascontiguousarray(triangles, dtype=np.uint32)
        if t.ndim != 2 or t.shape[1] != 3:
            raise ValueError(f"triangles: expected an array of shape n x 3, got {t.shape}")
        out = ctypes.c_uint64()
        self._call("demill_wall_add_mesh", as_id(material), v.shape[0], ptr(v), t.shape[0],
                   t.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32)), ctypes.byref(out))
        return Wall(self, out.value)

    def add_stl(self, material, source, scale=1.0, transform=None):
        """Adds a triangle-mesh wall (3D) from an STL file, ASCII or binary:
        ``source`` is its path (``str`` or ``os.PathLike``) or its bytes.
        Each point x becomes A (scale x) + t with ``transform`` = (A, t), A
        3 x 3 and t of 3 (None: none); ``scale=0.001`` for a file in mm. A
        :class:`Wall`."""
        xf = None
        if transform is not None:
            a, t = transform
            xf = doubles(np.concatenate([np.ravel(doubles(a, (3, 3), "transform A")),
                                         doubles(t, (3,), "transform t")]), (12,), "transform")
        out = ctypes.c_uint64()
        xp = ptr(xf) if xf is not None else None
        if isinstance(source, (bytes, bytearray, memoryview)):
            data = bytes(source)
            self._call("demill_wall_add_stl", as_id(material), data, len(data), float(scale),
                       xp, ctypes.byref(out))
        else:
            self._call("demill_wall_load_stl", as_id(material), os.fsencode(source),
                       float(scale), xp, ctypes.byref(out))
        return Wall(self, out.value)

    def add_polyline(self, material, points, closed=False):
        """Adds a polyline wall (2D): the segments between consecutive
        ``points`` (n x 2, or n x 3 with z = 0, m), and back to the first if
        ``closed``. Particles touch it from both sides. A :class:`Wall`."""
        p = doubles(points, None, "points")
        if p.ndim == 2 and p.shape[1] == 2:
            p = np.hstack([p, np.zeros((p.shape[0], 1))])
        p = doubles(p, (-1, 3), "points")
        out = ctypes.c_uint64()
        self._call("demill_wall_add_polyline", as_id(material), p.shape[0], ptr(p),
                   1 if closed else 0, ctypes.byref(out))
        return Wall(self, out.value)

    def _add_wall(self, function, material, *args):
        out = ctypes.c_uint64()
        self._call(function, as_id(material), *args, ctypes.byref(out))
        return Wall(self, out.value)

    def add_cylinder(self, material, point, axis, radius, length, caps=Caps.NONE):
        """Adds a finite cylinder of ``radius`` about the axis from
        ``point`` over ``length`` along ``axis``, a thin surface touched
        from both sides, closed at the ends ``caps`` names
        (:class:`~demill.Caps`); a :class:`Wall`. 3D only."""
        return self._add_wall("demill_wall_add_cylinder", material,
                              ptr(vector(point, "point")), ptr(vector(axis, "axis")),
                              float(radius), float(length), int(caps))

    def add_cone(self, material, point, axis, radius_start, radius_end, length,
                 caps=Caps.NONE):
        """Adds a cone or frustum: radius ``radius_start`` at ``point`` and
        ``radius_end`` at ``length`` along ``axis`` (one may be 0), closed
        at the ends ``caps`` names; a :class:`Wall`. 3D only."""
        return self._add_wall("demill_wall_add_cone", material,
                              ptr(vector(point, "point")), ptr(vector(axis, "axis")),
                              float(radius_start), float(radius_end), float(length), int(caps))

    def add_disc(self, material, centre, normal, outer_radius, inner_radius=0.0):
        """Adds a disc, or an annulus with a hole of ``inner_radius`` (an
        orifice plate), touched from both sides; a :class:`Wall`. 3D only."""
        return self._add_wall("demill_wall_add_disc", material,
                              ptr(vector(centre, "centre")), ptr(vector(normal, "normal")),
                              float(outer_radius), float(inner_radius))

    def add_rectangle(self, material, centre, normal, direction, half_width, half_height):
        """Adds a rectangle patch about ``centre`` normal to ``normal``,
        ``half_width`` along ``direction`` (its part in the plane) and
        ``half_height`` across it, touched from both sides; a
        :class:`Wall`. 3D only."""
        return self._add_wall("demill_wall_add_rectangle", material,
                              ptr(vector(centre, "centre")), ptr(vector(normal, "normal")),
                              ptr(vector(direction, "direction")), float(half_width),
                              float(half_height))

    def add_body(self, mass, centre, free_axes, gravity=True):
        """Adds a body of ``mass`` kg at ``centre`` that moves along
        ``free_axes`` (:class:`~demill.BodyAxis`, or'ed); gravity acts on it
        unless ``gravity`` is False. A :class:`Body`."""
        out = ctypes.c_uint64()
        self._call("demill_body_add", float(mass), ptr(vector(centre, "centre")), int(free_axes),
                   0 if gravity else int(BodyFlag.NO_GRAVITY), ctypes.byref(out))
        return Body(self, out.value)

    def clump_template(self, material, centres, radii):
        """A clump template (:class:`Template`) of spheres of ``material``
        at ``centres`` (n x 3, m; z = 0 in 2D) with ``radii`` (n, m)."""
        c = doubles(centres, (-1, 3), "centres")
        r = doubles(radii, (c.shape[0],), "radii")
        out = ctypes.c_uint64()
        self._call("demill_clump_template_add", as_id(material), c.shape[0], ptr(c), ptr(r),
                   ctypes.byref(out))
        return Template(self, out.value)

    def clump_template_from_mesh(self, material, vertices, triangles, spheres, cells=64):
        """A clump template (:class:`Template`, 3D) of up to ``spheres``
        spheres of ``material`` that fill the closed triangle mesh of
        ``vertices`` (n x 3, m) and ``triangles`` (m x 3 vertex indices,
        counter-clockwise seen from outside), on a grid of ``cells`` cubes
        along its longest side; the fit is in the template's ``mesh_volume``
        and ``fit_*`` fields."""
        v = doubles(vertices, (-1, 3), "vertices")
        t = np.ascontiguousarray(triangles, dtype=np.uint32)
        if t.ndim != 2 or t.shape[1] != 3:
            raise ValueError(f"triangles: expected an array of shape n x 3, got {t.shape}")
        out = ctypes.c_uint64()
        self._call("demill_clump_template_from_mesh", as_id(material), v.shape[0], ptr(v),
                   t.shape[0], t.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32)), int(spheres),
                   int(cells), ctypes.byref(out))
        return Template(self, out.value)

    def clump_template_from_stl(self, material, path, spheres, cells=64, scale=1.0):
        """A clump template (:class:`Template`, 3D) that fills the closed
        mesh of the STL file at ``path`` (ASCII or binary; each point x at
        ``scale`` x: 0.001 for a file in mm), as
        :meth:`clump_template_from_mesh`."""
        out = ctypes.c_uint64()
        self._call("demill_clump_template_from_stl", as_id(material), os.fsencode(path),
                   float(scale), int(spheres), int(cells), ctypes.byref(out))
        return Template(self, out.value)

    def add_clump(self, template, position, orientation=None):
        """Adds a clump of ``template`` at rest, its centre of mass at
        ``position`` and its body axes turned by the unit quaternion
        ``orientation`` (w, x, y, z; None: the identity). A :class:`Clump`."""
        q = None if orientation is None else doubles(orientation, (4,), "orientation")
        out = ctypes.c_uint64()
        self._call("demill_clump_add", as_id(template), ptr(vector(position, "position")),
                   None if q is None else ptr(q), ctypes.byref(out))
        return Clump(self, out.value)

    def fill_clumps(self, region, region_params, template, target, value, seed=1):
        """Fills a region (:class:`~demill.Region` and its numbers; the drum's
        takes none) with clumps of ``template`` at random orientations, as
        :meth:`fill_region` fills one with spheres, and returns them
        (a list of :class:`Clump`)."""
        r = doubles(region_params).reshape(-1)
        args = (int(region), ptr(r), r.size, as_id(template), int(target), float(value),
                count(seed, "seed"))
        need = ctypes.c_size_t()
        probe = np.empty(1, dtype=np.uint64)
        try:  # capacity 0 asks for the number of clumps, adding none
            self._call("demill_clump_fill_region", *args, ptr(probe), 0, ctypes.byref(need))
        except BufferTooSmall:
            pass
        ids = np.empty(need.value, dtype=np.uint64)
        added = ctypes.c_size_t()
        self._call("demill_clump_fill_region", *args, ptr(ids), ids.size, ctypes.byref(added))
        return [Clump(self, int(i)) for i in ids[:added.value]]

    def clump_of(self, particle):
        """The :class:`Clump` a particle belongs to, or None."""
        return particle_clump(self, particle)

    def add_drum(self, material, **params):
        """Creates the world's drum of the given wall material with
        parameters by name, e.g. ``world.add_drum(steel, diameter=0.3)``."""
        out = ctypes.c_uint64()
        self._call("demill_drum_create", as_id(material),
                   ctypes.byref(out))
        return configure(Drum(self, out.value), params)

    def fill_region(self, region, region_params, material, distribution, params, target, value,
                    seed=1):
        """Fills a region (:class:`~demill.Region` and its numbers) with
        particles of one material, as :meth:`Drum.fill` fills the drum, and
        returns their ids (uint64 array)."""
        r = doubles(region_params).reshape(-1)
        p = doubles(params).reshape(-1)
        args = (int(region), ptr(r), r.size, as_id(material), int(distribution), ptr(p), p.size,
                int(target), float(value), count(seed, "seed"))
        need = ctypes.c_size_t()
        probe = np.empty(1, dtype=np.uint64)
        try:  # capacity 0 asks for the number of particles, adding none
            self._call("demill_fill_region", *args, ptr(probe), 0, ctypes.byref(need))
        except BufferTooSmall:
            pass
        ids = np.empty(need.value, dtype=np.uint64)
        added = ctypes.c_size_t()
        self._call("demill_fill_region", *args, ptr(ids), ids.size, ctypes.byref(added))
        return ids[:added.value]

    def add_feed(self, region, region_params, material, distribution, params, mass_rate,
                 velocity=(0, 0, 0), start=0.0, stop=float("inf"), seed=1):
        """A :class:`Feed` inserting particles of ``material`` into a region
        at ``mass_rate`` kg/s from ``start`` to ``stop`` s."""
        r = doubles(region_params).reshape(-1)
        p = doubles(params).reshape(-1)
        out = ctypes.c_uint64()
        self._call("demill_feed_create", int(region), ptr(r), r.size, as_id(material),
                   int(distribution), ptr(p), p.size, float(mass_rate),
                   ptr(vector(velocity, "velocity")), float(start), float(stop),
                   count(seed, "seed"), ctypes.byref(out))
        return Feed(self, out.value)

    def add_outlet(self, region, region_params, edges=(), interval=1.0):
        """An :class:`Outlet` removing the particles whose centre enters a
        region, counted in size classes of diameter below each of ``edges``
        (m) and above the last, with rates over ``interval`` s."""
        r = doubles(region_params).reshape(-1)
        e = doubles(edges).reshape(-1)
        out = ctypes.c_uint64()
        self._call("demill_outlet_create", int(region), ptr(r), r.size, e.size,
                   ptr(e) if e.size else None, float(interval), ctypes.byref(out))
        return Outlet(self, out.value)

    @property
    def feeds(self):
        """Every feed, as a list of :class:`Feed`."""
        return [Feed(self, i) for i in self.ids(Kind.FEED)]

    @property
    def outlets(self):
        """Every outlet, as a list of :class:`Outlet`."""
        return [Outlet(self, i) for i in self.ids(Kind.OUTLET)]

    def ids(self, kind):
        """The ids of every live object of a :class:`~demill.Kind`."""
        def call(buf, capacity, n):
            self._call("demill_world_ids", int(kind), buf, capacity, n)
        return read_counted(call, 1, np.uint64)

    @property
    def materials(self):
        """Every material, as a list of :class:`Material`."""
        return [Material(self, i) for i in self.ids(Kind.MATERIAL)]

    @property
    def walls(self):
        """Every wall (planes, meshes, polylines, finite walls), as a list of
        :class:`Wall`."""
        return [Wall(self, i) for i in self.ids(Kind.WALL)]

    @property
    def bodies(self):
        """Every body, as a list of :class:`Body`."""
        return [Body(self, i) for i in self.ids(Kind.BODY)]

    @property
    def clumps(self):
        """Every clump, as a list of :class:`Clump`."""
        return [Clump(self, i) for i in self.ids(Kind.CLUMP)]

    @property
    def drum(self):
        """The world's :class:`Drum`, or None."""
        ids = self.ids(Kind.DRUM)
        return Drum(self, ids[0]) if ids.size else None

    # ---- queries ---------------------------------------------------------

    def energy(self, term):
        """One energy term (:class:`~demill.Energy`), J."""
        v = ctypes.c_double()
        self._call("demill_world_energy", int(term), ctypes.byref(v))
        return v.value

    def energies(self):
        """Every energy term: a dict from :class:`~demill.Energy` to J."""
        return {term: self.energy(term) for term in Energy}

    # ---- state and files ---------------------------------------------------

    def snapshot(self):
        """An in-memory copy of the whole state (a :class:`Snapshot`)."""
        return Snapshot.take(self)

    def save(self, path):
        """Saves the whole world to a checkpoint file."""
        self._call("demill_world_save", os.fsencode(path))

    def load_state(self, path):
        """Replaces this world's state with a checkpoint file's."""
        self._call("demill_world_load", os.fsencode(path))

    @classmethod
    def load(cls, path):
        """A new world loaded from a checkpoint file."""
        world = cls()
        world.load_state(path)
        return world

    def to_bytes(self):
        """The whole world as a checkpoint in memory (bytes)."""
        size = ctypes.c_size_t()
        self._call("demill_world_save_buffer", None, 0, ctypes.byref(size))
        buf = ctypes.create_string_buffer(size.value)
        self._call("demill_world_save_buffer", buf, size.value, ctypes.byref(size))
        return buf.raw[:size.value]

    def load_bytes(self, data):
        """Replaces this world's state with a checkpoint from :meth:`to_bytes`."""
        data = bytes(data)
        self._call("demill_world_load_buffer", data, len(data))

    @classmethod
    def from_bytes(cls, data):
        """A new world from a checkpoint made by :meth:`to_bytes`."""
        world = cls()
        world.load_bytes(data)
        return world

    def __reduce__(self):
        return (World.from_bytes, (self.to_bytes(),))

    def write_vtk_particles(self, path):
        """Writes the particles to a VTK XML unstructured grid (.vtu)."""
        self._call("demill_vtk_write_particles", os.fsencode(path))

    def write_vtk_walls(self, path):
        """Writes the walls and the drum to a VTK XML polydata file (.vtp)."""
        self._call("demill_vtk_write_walls", os.fsencode(path))

    def vtk_series(self, prefix):
        """Opens a VTK time series (a :class:`VtkSeries`, a context manager)."""
        return VtkSeries.open(self, prefix)
