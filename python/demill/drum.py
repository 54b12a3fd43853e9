"""The mill: a drum with lifters, its speed, its charge and what is measured
on it (``demill/drum.h``)."""

import ctypes

import numpy as np

from ._core import Keyed, Param, as_id, doubles, first, ptr, read_counted, read_field
from .constants import DrumKey, DrumPart, Kind, LifterField
from .errors import BufferTooSmall
from .objects import Handle, Material, Wall, count


class Drum(Handle, Keyed):
    """The drum of a world (:meth:`World.add_drum`; at most one per world).

    Its properties are the ``DEMILL_DRUM_*`` keys: geometry and speed can be
    set (setting a speed key sets the target speed from now on), the
    measurements (power, torque, charge angles, ...) are read-only. Angles
    are in radians; charge angles are measured from 6 o'clock, positive in
    the direction of rotation (docs/mill.md).
    """

    __slots__ = ()
    kind = Kind.DRUM

    diameter = Param(DrumKey.DIAMETER)
    length = Param(DrumKey.LENGTH)
    lifters = Param(DrumKey.LIFTERS, int)
    lifter_height = Param(DrumKey.LIFTER_HEIGHT)
    lifter_width = Param(DrumKey.LIFTER_WIDTH)
    lifter_face_angle = Param(DrumKey.LIFTER_FACE_ANGLE)
    lifter_phase = Param(DrumKey.LIFTER_PHASE)
    speed = Param(DrumKey.SPEED)
    speed_rpm = Param(DrumKey.SPEED_RPM)
    speed_fraction = Param(DrumKey.SPEED_FRACTION)
    ramp_time = Param(DrumKey.RAMP_TIME)
    critical_diameter = Param(DrumKey.CRITICAL_DIAMETER)
    fill_porosity = Param(DrumKey.FILL_POROSITY)
    sample_interval = Param(DrumKey.SAMPLE_INTERVAL, int)
    shell = Param(DrumKey.SHELL, int)
    center_x = Param(DrumKey.CENTER_X)
    center_y = Param(DrumKey.CENTER_Y)
    center_z = Param(DrumKey.CENTER_Z)
    velocity_x = Param(DrumKey.VELOCITY_X)
    velocity_y = Param(DrumKey.VELOCITY_Y)
    velocity_z = Param(DrumKey.VELOCITY_Z)
    vibration_x = Param(DrumKey.VIBRATION_X)
    vibration_y = Param(DrumKey.VIBRATION_Y)
    vibration_z = Param(DrumKey.VIBRATION_Z)
    vibration_frequency = Param(DrumKey.VIBRATION_FREQUENCY)
    vibration_phase = Param(DrumKey.VIBRATION_PHASE)
    critical_speed = Param(DrumKey.CRITICAL_SPEED)
    current_speed = Param(DrumKey.CURRENT_SPEED)
    angle = Param(DrumKey.ANGLE)
    revolutions = Param(DrumKey.REVOLUTIONS, int)
    torque = Param(DrumKey.TORQUE)
    power = Param(DrumKey.POWER)
    power_mean = Param(DrumKey.POWER_MEAN)
    power_cm = Param(DrumKey.POWER_CM)
    power_cm_mean = Param(DrumKey.POWER_CM_MEAN)
    toe_angle = Param(DrumKey.TOE_ANGLE)
    shoulder_angle = Param(DrumKey.SHOULDER_ANGLE)
    com_angle = Param(DrumKey.COM_ANGLE)
    toe_angle_mean = Param(DrumKey.TOE_ANGLE_MEAN)
    shoulder_angle_mean = Param(DrumKey.SHOULDER_ANGLE_MEAN)
    com_angle_mean = Param(DrumKey.COM_ANGLE_MEAN)
    energy_in = Param(DrumKey.ENERGY_IN)
    energy_dissipated = Param(DrumKey.ENERGY_DISSIPATED)
    dissipation_mean = Param(DrumKey.DISSIPATION_MEAN)
    lifter_count = Param(DrumKey.LIFTER_COUNT, int)
    force_x = Param(DrumKey.FORCE_X)
    force_y = Param(DrumKey.FORCE_Y)
    force_z = Param(DrumKey.FORCE_Z)
    current_velocity_x = Param(DrumKey.CURRENT_VELOCITY_X)
    current_velocity_y = Param(DrumKey.CURRENT_VELOCITY_Y)
    current_velocity_z = Param(DrumKey.CURRENT_VELOCITY_Z)

    @property
    def force(self):
        """Force of the particles on the drum at the last force evaluation,
        N: ``(x, y, z)``."""
        return np.array([self.force_x, self.force_y, self.force_z])

    _getter, _setter = "demill_drum_get", "demill_drum_set"

    def remove(self):
        """Removes the drum and its walls; its id becomes invalid."""
        self.world._call("demill_drum_remove", self.id)

    def set_material(self, part, material):
        """Gives a part of the drum (:class:`DrumPart`) its own material."""
        self.world._call("demill_drum_set_material", self.id, int(DrumPart(part)),
                         as_id(material))

    def material(self, part):
        """The :class:`Material` of a part of the drum (:class:`DrumPart`)."""
        out = ctypes.c_uint64()
        self.world._call("demill_drum_get_material", self.id, int(DrumPart(part)),
                         ctypes.byref(out))
        return Material(self.world, out.value)

    def attach_wall(self, wall, part):
        """Makes ``wall`` (a mesh, polyline, plane or finite wall of this
        world) a part (:class:`DrumPart`) of the drum: it turns with the drum
        from where it is now and counts in the drum's torque, power and
        charge shape."""
        self.world._call("demill_drum_attach_wall", self.id, as_id(wall), int(DrumPart(part)))

    def add_profile(self, material, part, points, closed=False, copies=1):
        """Adds lifters or liners from their cross-section: ``points`` (n x
        2, m) in the drum's frame at drum angle 0, joined in order (and back
        to the first if ``closed``), repeated ``copies`` times evenly about
        the axis; extruded over the drum's length in 3D. One mesh (3D) or
        polyline (2D) :class:`Wall` of ``material``, attached as ``part``
        (:class:`DrumPart`)."""
        p = doubles(points, (-1, 2), "points")
        out = ctypes.c_uint64()
        self.world._call("demill_drum_add_profile", self.id, as_id(material),
                         int(DrumPart(part)), p.shape[0], ptr(p), 1 if closed else 0,
                         int(copies), ctypes.byref(out))
        return Wall(self.world, out.value)

    def add_lifter(self, angle, height, width, face_angle=0.0):
        """Adds one lifter: centre line at polar angle ``angle`` (rad, drum
        frame at drum angle 0), ``height`` above the shell and ``width`` at
        it (m), leading face inclined by ``face_angle`` (rad)."""
        self.world._call("demill_drum_add_lifter", self.id, float(angle), float(height),
                         float(width), float(face_angle))
        return self.lifter(self.lifter_count - 1)

    def lifter(self, index):
        """Lifter ``index`` (0 to ``lifter_count - 1``)."""
        return Lifter(self, count(index, "index"))

    def fill(self, material, distribution, params, target, value, seed=0):
        """Fills the drum with particles of one material and returns their
        ids (uint64 array); the same call gives the same charge.

        Args:
            material: the particles' :class:`Material` (or id).
            distribution: :class:`~demill.Sizes`; ``params`` are its
                numbers: ``CLASSES``: pairs (diameter, mass fraction);
                ``ROSIN_RAMMLER``: d63, n, d_min, d_max; ``NORMAL``: mean,
                standard deviation, d_min, d_max (diameters in m).
            target: :class:`~demill.Fill`: ``COUNT``, ``MASS`` (kg) or
                ``FRACTION`` (bulk filling of the drum), with ``value``.
            seed: the placement's random seed.
        """
        p = doubles(params).reshape(-1)
        args = (self.id, as_id(material), int(distribution), ptr(p), p.size, int(target),
                float(value), count(seed, "seed"))
        need = ctypes.c_size_t()
        probe = np.empty(1, dtype=np.uint64)
        # capacity 0 asks for the number of particles, adding none
        try:
            self.world._call("demill_drum_fill", *args, ptr(probe), 0, ctypes.byref(need))
        except BufferTooSmall:
            pass
        ids = np.empty(need.value, dtype=np.uint64)
        added = ctypes.c_size_t()
        self.world._call("demill_drum_fill", *args, ptr(ids), ids.size, ctypes.byref(added))
        return ids[:added.value]

    def spectrum_start(self, edges, nbins, e_min, e_max):
        """Starts (or restarts) recording the collision energy spectrum:
        ``nbins`` logarithmic bins from ``e_min`` to ``e_max`` J, size
        classes split at the increasing diameters ``edges`` (m)."""
        e = doubles(edges).reshape(-1)
        self.world._call("demill_drum_spectrum_start", self.id, e.size, ptr(e),
                         count(nbins, "nbins"), float(e_min), float(e_max))

    def spectrum(self, nbins=None):
        """The spectrum's counts (uint64): rows of ``nbins`` counters, the
        particle class pairs (0,0), (0,1), ..., (1,1), ..., then each class
        against the shell, then against the lifters. Flat unless ``nbins``
        is given, then shaped ``(rows, nbins)``."""
        def call(buf, capacity, n):
            self.world._call("demill_drum_spectrum", self.id, buf, capacity, n)
        counts = read_counted(call, 1, np.uint64)
        return counts if nbins is None else counts.reshape(-1, nbins)

    def impacts_start(self, material, top_size, classes, nbins, e_min, e_max):
        """Starts (or restarts) recording the impacts on the particles of
        one ore ``material`` (the collision spectrum must be recording:
        :meth:`spectrum_start`): per size class of a grinding object
        (``classes`` in a √2 series below ``top_size`` m) and per
        logarithmic bin of specific energy, ``nbins`` from ``e_min`` to
        ``e_max`` J/kg (``demill_drum_impacts_start``)."""
        self.world._call("demill_drum_impacts_start", self.id, as_id(material),
                         float(top_size), count(classes, "classes"), count(nbins, "nbins"),
                         float(e_min), float(e_max))

    def impacts(self):
        """The impacts recorded: ``(counts, time)``, counts a uint64 array
        of one row of bins per size class, time the seconds recorded."""
        time = ctypes.c_double()

        def call(buf, capacity, n):
            self.world._call("demill_drum_impacts", self.id, buf, capacity, n,
                             ctypes.byref(time))
        counts = read_counted(call, 1, np.uint64)
        classes = self.impacts_particles().size
        return counts.reshape(classes, -1), time.value

    def impacts_particles(self):
        """The ore's particles in each size class of the impacts' recording."""
        def call(buf, capacity, n):
            self.world._call("demill_drum_impacts_particles", self.id, buf, capacity, n)
        return read_counted(call, 1, np.uint64)


class Lifter:
    """One lifter bar of a drum (:meth:`Drum.lifter`)."""

    __slots__ = ("drum", "index")

    force = Param(LifterField.FORCE, None, "Force of the particles on it, N (3).")
    force_mean = Param(LifterField.FORCE_MEAN, None,
                       "Mean force over the last revolution, N (3).")
    force_peak = Param(LifterField.FORCE_PEAK, first, "Largest force magnitude so far, N.")
    energy = Param(LifterField.ENERGY, first, "Energy dissipated on it so far, J.")
    angle = Param(LifterField.ANGLE, first, "Current polar angle of its centre line, rad.")

    def __init__(self, drum, index):
        self.drum = drum
        self.index = index

    def __repr__(self):
        return f"<demill.Lifter {self.index} of drum {self.drum.id:#x}>"

    def _get(self, field):
        return read_field(self.drum.world, "demill_drum_lifter_get", self.drum.id, self.index,
                          int(field))

    def get(self, field):
        """A field (:class:`~demill.LifterField`) as an array of 1 or 3."""
        v = self._get(field)
        return v if field in (LifterField.FORCE, LifterField.FORCE_MEAN) else v[:1]
