"""Materials, material pairs, particles, walls, bodies and contacts of a world.

Every object keeps its :class:`~demill.World` alive; none owns memory of its
own (the world does), so they are cheap views that may be created at will.
"""

import ctypes
import operator
from typing import NamedTuple

import numpy as np

from ._core import (Keyed, Param, as_id, doubles, first, output, ptr, read_counted, read_field,
                    vector)
from ._lib import lib
from .errors import InvalidValue
from .constants import (AddFlag, BodyAxis, BodyField, Cohesion, ContactField, Damping, IdField,
                        Kind, MaterialKey, Normal, PairKey, ParticleField, Rolling, Tangential,
                        WallField, WorldKey)


def id_array(ids):
    """Ids (an array, a sequence of ints or handles, or one of either) as a
    C-contiguous uint64 array."""
    if isinstance(ids, np.ndarray):
        return np.ascontiguousarray(ids, dtype=np.uint64).reshape(-1)
    if not isinstance(ids, (list, tuple, range)):
        ids = [ids]
    return np.fromiter((as_id(i) for i in ids), dtype=np.uint64, count=len(ids))


def count(n, name="count"):
    """A whole number >= 0 (ctypes would wrap a negative one silently)."""
    n = operator.index(n)
    if n < 0:
        raise ValueError(f"{name} must be >= 0, got {n}")
    return n


class Handle:
    """An object named by an id in a world. Compares equal to another handle
    of the same world and id; ``int(handle)`` is the id."""

    __slots__ = ("world", "id")
    kind = Kind.NONE

    def __init__(self, world, id_):
        self.world = world
        self.id = int(id_)

    def __eq__(self, other):
        return type(self) is type(other) and self.world is other.world and self.id == other.id

    def __hash__(self):
        return hash((type(self), id(self.world), self.id))

    def __int__(self):
        return self.id

    def __repr__(self):
        return f"<demill.{type(self).__name__} {self.id:#x}>"


class Material(Handle, Keyed):
    """A material (:meth:`World.material`); its properties are the
    ``DEMILL_MATERIAL_*`` parameters."""

    __slots__ = ()
    kind = Kind.MATERIAL

    density = Param(MaterialKey.DENSITY)
    youngs_modulus = Param(MaterialKey.YOUNGS_MODULUS)
    poisson_ratio = Param(MaterialKey.POISSON_RATIO)
    stiffness = Param(MaterialKey.STIFFNESS)
    restitution = Param(MaterialKey.RESTITUTION)
    friction = Param(MaterialKey.FRICTION)
    rolling_friction = Param(MaterialKey.ROLLING_FRICTION)
    yield_stress = Param(MaterialKey.YIELD_STRESS)
    local_damping = Param(MaterialKey.LOCAL_DAMPING)
    rigid = Param(MaterialKey.RIGID, bool)
    surface_energy = Param(MaterialKey.SURFACE_ENERGY)

    _getter, _setter = "demill_material_get", "demill_material_set"



class Pair(Keyed):
    """The contact model of two materials (:meth:`World.pair`); its
    properties are the ``DEMILL_PAIR_*`` parameters. The order of the two
    materials does not matter."""

    __slots__ = ("world", "a", "b")

    normal = Param(PairKey.NORMAL, lambda v: Normal(int(v)))
    damping = Param(PairKey.DAMPING, lambda v: Damping(int(v)))
    tangential = Param(PairKey.TANGENTIAL, lambda v: Tangential(int(v)))
    rolling = Param(PairKey.ROLLING, lambda v: Rolling(int(v)))
    cohesion = Param(PairKey.COHESION, lambda v: Cohesion(int(v)))
    restitution = Param(PairKey.RESTITUTION)
    friction = Param(PairKey.FRICTION)
    rolling_friction = Param(PairKey.ROLLING_FRICTION)
    normal_stiffness = Param(PairKey.NORMAL_STIFFNESS)
    viscous_damping = Param(PairKey.VISCOUS_DAMPING)
    tangential_stiffness_ratio = Param(PairKey.TANGENTIAL_STIFFNESS_RATIO)
    tangential_damping_factor = Param(PairKey.TANGENTIAL_DAMPING_FACTOR)
    coulomb_regularisation = Param(PairKey.COULOMB_REGULARISATION)
    rolling_regularisation = Param(PairKey.ROLLING_REGULARISATION)
    clamp_normal = Param(PairKey.CLAMP_NORMAL, bool)
    yield_pressure = Param(PairKey.YIELD_PRESSURE)
    plastic_fit_c0 = Param(PairKey.PLASTIC_FIT_C0)
    plastic_fit_c1 = Param(PairKey.PLASTIC_FIT_C1)
    plastic_fit_c2 = Param(PairKey.PLASTIC_FIT_C2)
    plastic_fit_exponent = Param(PairKey.PLASTIC_FIT_EXPONENT)
    rolling_stiffness = Param(PairKey.ROLLING_STIFFNESS)
    rolling_damping_ratio = Param(PairKey.ROLLING_DAMPING_RATIO)
    adhesion_work = Param(PairKey.ADHESION_WORK)
    liquid_volume = Param(PairKey.LIQUID_VOLUME)
    surface_tension = Param(PairKey.SURFACE_TENSION)
    contact_angle = Param(PairKey.CONTACT_ANGLE)

    def __init__(self, world, a, b):
        self.world = world
        self.a = as_id(a)
        self.b = as_id(b)

    def __repr__(self):
        return f"<demill.Pair {self.a:#x} {self.b:#x}>"

    _getter, _setter = "demill_pair_get", "demill_pair_set"

    def _ids(self):
        return (self.a, self.b)


class Particle(Handle, Keyed):
    """One particle (:meth:`World.particle`); its properties are its fields.
    Vector fields are NumPy arrays of 3, the orientation of 4, scalar fields
    floats."""

    __slots__ = ()
    kind = Kind.PARTICLE

    position = Param(ParticleField.POSITION, None, "Centre, m (3).")
    velocity = Param(ParticleField.VELOCITY, None, "Velocity, m/s (3).")
    angular_velocity = Param(ParticleField.ANGULAR_VELOCITY, None,
                             "Angular velocity, rad/s (3; in 2D only z).")
    radius = Param(ParticleField.RADIUS, first, "Radius, m (the mass follows).")
    mass = Param(ParticleField.MASS, first, "Mass, kg (read-only).")
    force = Param(ParticleField.FORCE, None,
                  "Total force at the last force evaluation, N (3; read-only).")
    torque = Param(ParticleField.TORQUE, None,
                   "Total torque at the last force evaluation, N m (3; read-only).")
    angle = Param(ParticleField.ANGLE, first, "2D only: rotation angle about z, rad.")
    orientation = Param(ParticleField.ORIENTATION, None,
                        "3D only: orientation, a unit quaternion (w, x, y, z) from the body "
                        "frame to the world's (4; a write is normalised).")
    fixed = Param(ParticleField.FIXED, lambda v: bool(first(v)),
                  "True: the particle never moves; it touches the moving particles as an "
                  "infinitely heavy one.")

    def _get(self, field):
        return read_field(self.world, "demill_particle_get", self.id, int(field),
                          size=max(lib.demill_particle_field_size(int(field)), 1))

    def _set(self, field, value):
        arr = doubles(value).reshape(-1)
        size = lib.demill_particle_field_size(int(field))
        if size and arr.size != size:
            raise ValueError(f"field {field!r} takes {size} values, got {arr.size}")
        self.world._call("demill_particle_set", self.id, int(field), ptr(arr))



class Particles:
    """All particles of a world (``world.particles``), read and written as
    NumPy arrays in *id order* (the order of :meth:`ids`, which changes only
    when particles are added or removed). Vector fields are ``(n, 3)``
    arrays, orientations ``(n, 4)``, scalar fields ``(n,)``. The bulk properties (``positions``,
    ``radii``, ...) read into new arrays; :meth:`read` can fill a
    preallocated one."""

    __slots__ = ("world",)

    positions = Param(ParticleField.POSITION, None, "Centres, m (n x 3).")
    velocities = Param(ParticleField.VELOCITY, None, "Velocities, m/s (n x 3).")
    angular_velocities = Param(ParticleField.ANGULAR_VELOCITY, None,
                               "Angular velocities, rad/s (n x 3).")
    radii = Param(ParticleField.RADIUS, None, "Radii, m (n).")
    masses = Param(ParticleField.MASS, None, "Masses, kg (n; read-only).")
    forces = Param(ParticleField.FORCE, None, "Forces, N (n x 3; read-only).")
    torques = Param(ParticleField.TORQUE, None, "Torques, N m (n x 3; read-only).")
    angles = Param(ParticleField.ANGLE, None, "2D only: rotation angles, rad (n).")
    orientations = Param(ParticleField.ORIENTATION, None,
                         "3D only: orientations, unit quaternions (w, x, y, z) (n x 4; a "
                         "write is normalised).")
    fixed = Param(ParticleField.FIXED, None, "1 for a fixed particle, else 0 (n).")

    def __init__(self, world):
        self.world = world

    def __len__(self):
        return int(self.world._get(WorldKey.PARTICLE_COUNT))

    def __iter__(self):
        return (Particle(self.world, i) for i in self.ids())

    def add(self, material, positions, radii, velocities=None, no_overlap=False):
        """Adds particles of one material and returns their ids (uint64).

        Args:
            material: a :class:`Material` (or its id).
            positions: centres, m, ``(n, 3)`` (or one ``(3,)``).
            radii: n radii, m, or one radius for all.
            velocities: ``(n, 3)`` in m/s, or None for rest.
            no_overlap: reject the whole batch (:class:`~demill.Overlap`)
                if a new particle overlaps anything.
        """
        pos = doubles(positions, (-1, 3), "positions")
        n = pos.shape[0]
        rad = doubles(radii, (n,), "radii")
        vel = None if velocities is None else doubles(velocities, (n, 3), "velocities")
        ids = np.empty(n, dtype=np.uint64)
        flags = AddFlag.NO_OVERLAP if no_overlap else 0
        self.world._call("demill_particles_add", as_id(material), n, ptr(pos), ptr(rad),
                         ptr(vel), int(flags), ptr(ids))
        return ids

    def remove(self, ids):
        """Removes particles by id (an array, a list, or one id or handle)."""
        arr = id_array(ids)
        self.world._call("demill_particles_remove", arr.size, ptr(arr))

    def _read_ids(self, field, out):
        def call(buf, capacity, n):
            self.world._call("demill_particles_read_ids", int(field), buf, capacity, n)
        return read_counted(call, 1, np.uint64, out)

    def ids(self, out=None):
        """The particles' ids in id order (uint64 array)."""
        return self._read_ids(IdField.ID, out)

    def material_ids(self, out=None):
        """The ids of the particles' materials, in id order (uint64 array)."""
        return self._read_ids(IdField.MATERIAL, out)

    def clump_ids(self, out=None):
        """The ids of the particles' clumps, 0 for a particle of none, in id
        order (uint64 array)."""
        return self._read_ids(IdField.CLUMP, out)

    def read(self, field, out=None):
        """A field (:class:`~demill.ParticleField`) of every particle, into
        ``out`` if given (a float64 array of the right shape, no copy)."""
        width = lib.demill_particle_field_size(int(field))

        def call(buf, capacity, n):
            self.world._call("demill_particles_read", int(field), buf, capacity, n)
        return read_counted(call, width, np.float64, out)

    def write(self, field, values):
        """Writes a field of every particle from an ``(n, 3)``, ``(n, 4)``
        or ``(n,)`` array (n the number of particles)."""
        width = max(lib.demill_particle_field_size(int(field)), 1)
        arr = doubles(values, (-1, width) if width > 1 else (-1,), "values")
        self.world._call("demill_particles_write", int(field), ptr(arr), arr.shape[0])

    _get = read
    _set = write


class WallLoads(NamedTuple):
    """The loads a wall has recorded (:meth:`Wall.loads`), per element (a
    mesh's triangle, a polyline's segment, or the whole wall): the normal
    force at the last step (N), its integral over the time recorded (N s),
    the shear work (J), the element's area (m²; a segment's length, m; NaN
    for a plane), and the time recorded (s)."""

    normal: np.ndarray
    impulse: np.ndarray
    shear_work: np.ndarray
    area: np.ndarray
    interval: float

    @property
    def mean_pressure(self):
        """The mean pressure on each element over the time recorded, Pa
        (a polyline's: a load per length, N/m)."""
        return self.impulse / (self.area * self.interval)


class Wall(Handle, Keyed):
    """A wall: a plane (:meth:`World.add_plane`), a triangle mesh
    (:meth:`World.add_mesh`), a polyline (:meth:`World.add_polyline`) or a
    finite wall (:meth:`World.add_cylinder` and the others). Its fields are
    read-only 3-vectors; :meth:`set_motion` and :meth:`set_harmonic` move
    it."""

    __slots__ = ()
    kind = Kind.WALL

    point = Param(WallField.POINT, None, "A point on the plane, m.")
    normal = Param(WallField.NORMAL, None, "Unit normal, towards the particles' side.")
    centre = Param(WallField.CENTRE, None, "Centre of rotation, m.")
    velocity = Param(WallField.VELOCITY, None, "Velocity of the centre, m/s.")
    angular_velocity = Param(WallField.ANGULAR_VELOCITY, None,
                             "Angular velocity about the centre, rad/s.")
    force = Param(WallField.FORCE, None, "Force of the particles on the wall, N.")
    torque = Param(WallField.TORQUE, None, "Torque of the particles about the centre, N m.")
    surface_velocity = Param(WallField.SURFACE_VELOCITY, None,
                             "Velocity of the surface along itself, m/s.")

    def _get(self, field):
        return read_field(self.world, "demill_wall_get", self.id, int(field))

    def set_motion(self, velocity=None, angular_velocity=None, centre=None):
        """Sets the rigid motion from now on: the centre of rotation
        (None keeps it) moves with ``velocity`` and the wall turns about it
        with ``angular_velocity`` (None: zero)."""
        v, w, c = (vector(x, n) for x, n in ((velocity, "velocity"),
                                             (angular_velocity, "angular_velocity"),
                                             (centre, "centre")))
        self.world._call("demill_wall_set_motion", self.id, ptr(v), ptr(w), ptr(c))

    @property
    def mesh_size(self):
        """A mesh's or polyline's (vertices, triangles or segments)."""
        nv, ne = ctypes.c_size_t(), ctypes.c_size_t()
        self.world._call("demill_wall_mesh_info", self.id, ctypes.byref(nv), ctypes.byref(ne))
        return nv.value, ne.value

    def set_harmonic(self, mode, axis, amplitude, frequency, phase=0.0):
        """Sets a harmonic motion from now on (:class:`~demill.Harmonic`):
        the wall moves along ``axis`` by, or turns about it through its
        centre by, ``amplitude`` sin(2π ``frequency`` t + ``phase``), t
        from now; its pose now is the pose at zero."""
        self.world._call("demill_wall_set_harmonic", self.id, int(mode),
                         ptr(vector(axis, "axis")), float(amplitude), float(frequency),
                         float(phase))

    def set_surface_velocity(self, velocity):
        """Moves the wall's surface along itself at ``velocity`` (a belt;
        None: 0), the geometry staying put."""
        v = vector(velocity, "velocity")
        self.world._call("demill_wall_set_surface_velocity", self.id, ptr(v))

    def loads_start(self):
        """Starts recording the loads on the wall from zero, after every
        step (docs/geometry.md, Wall loads); :meth:`loads` reads them."""
        self.world._call("demill_wall_loads_start", self.id)

    def loads_stop(self):
        """Stops recording the wall's loads and forgets them."""
        self.world._call("demill_wall_loads_stop", self.id)

    def loads(self):
        """The loads recorded since :meth:`loads_start`, a
        :class:`WallLoads` of arrays with one value per element."""
        try:
            n = self.mesh_size[1]
        except InvalidValue:  # not a mesh or a polyline: one patch
            n = 1
        arrays = [np.empty(n) for _ in range(4)]
        interval = ctypes.c_double()
        self.world._call("demill_wall_loads", self.id, n, *(ptr(a) for a in arrays),
                         ctypes.byref(interval))
        return WallLoads(*arrays, interval.value)

    def remove(self):
        """Removes the wall; its id becomes invalid."""
        self.world._call("demill_wall_remove", self.id)


class Body(Handle):
    """A rigid body the particles move (:meth:`World.add_body`): it
    translates along its free axes, pushed by the particles on its walls,
    held by a spring and a damper per axis and driven by an external force.
    Its fields are read-only 3-vectors."""

    __slots__ = ()
    kind = Kind.BODY

    position = Param(BodyField.POSITION, None, "Centre, m.")
    velocity = Param(BodyField.VELOCITY, None, "Velocity, m/s.")
    force_particles = Param(BodyField.FORCE_PARTICLES, None,
                            "Force of the particles on its walls, N.")
    force_spring = Param(BodyField.FORCE_SPRING, None, "Force of its springs, N.")
    force_damper = Param(BodyField.FORCE_DAMPER, None, "Force of its dampers, N.")
    force_external = Param(BodyField.FORCE_EXTERNAL, None, "The external force now, N.")

    def _get(self, field):
        return read_field(self.world, "demill_body_get", self.id, int(field))

    def set_spring(self, axis, stiffness, damping=0.0, rest=None):
        """Ties the body to the ground along a free ``axis``
        (:class:`~demill.BodyAxis`): a force -stiffness (x - rest) -
        damping v; ``rest`` None: the body's current position."""
        axis = BodyAxis(axis)
        if rest is None:
            rest = float(self.position[axis.bit_length() - 1])
        self.world._call("demill_body_set_spring", self.id, int(axis), float(stiffness),
                         float(damping), float(rest))

    def set_force(self, amplitude, frequency, phase=0.0):
        """The external force amplitude sin(2π frequency t + phase), N."""
        self.world._call("demill_body_set_force", self.id, ptr(vector(amplitude, "amplitude")),
                         float(frequency), float(phase))

    def attach(self, wall):
        """Attaches a wall at rest: it moves with the body from now on."""
        self.world._call("demill_body_attach_wall", self.id, as_id(wall))

    def energy(self, term):
        """One of the body's energy terms (``Energy.BODY_*``), J."""
        v = ctypes.c_double()
        self.world._call("demill_body_energy", self.id, int(term), ctypes.byref(v))
        return v.value

    def remove(self):
        """Removes the body; its walls stay where they are, at rest."""
        self.world._call("demill_body_remove", self.id)


class Contacts:
    """The contacts of a world at its current state (``world.contacts``):
    particle-particle first, then particle-wall; forces are those the
    second body exerts on the first."""

    __slots__ = ("world",)

    points = Param(ContactField.POINT, None, "Contact points, m (n x 3).")
    normals = Param(ContactField.NORMAL, None, "Unit normals from a to b (n x 3).")
    overlaps = Param(ContactField.OVERLAP, None, "Overlaps, m (n).")
    normal_forces = Param(ContactField.NORMAL_FORCE, None, "Normal forces on a, N (n x 3).")
    tangential_forces = Param(ContactField.TANGENTIAL_FORCE, None,
                              "Tangential forces on a, N (n x 3).")
    rolling_torques = Param(ContactField.ROLLING_TORQUE, None,
                            "Rolling-resistance torques on a, N m (n x 3).")

    def __init__(self, world):
        self.world = world

    def __len__(self):
        n = ctypes.c_size_t()
        self.world._call("demill_contacts_read_ids", None, None, 0, ctypes.byref(n))
        return n.value

    def read(self, field, out=None):
        """A field (:class:`~demill.ContactField`) of every contact."""
        width = lib.demill_contact_field_size(int(field))

        def call(buf, capacity, n):
            self.world._call("demill_contacts_read", int(field), buf, capacity, n)
        return read_counted(call, width, np.float64, out)

    _get = read

    def ids(self):
        """The ids of both bodies of every contact: arrays ``(a, b)``; a is a
        particle, b a particle, a wall or the drum."""
        n = len(self)
        a, b = output((n,), np.uint64, None), output((n,), np.uint64, None)
        got = ctypes.c_size_t()
        self.world._call("demill_contacts_read_ids", ptr(a), ptr(b), n, ctypes.byref(got))
        return a, b
