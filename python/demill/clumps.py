"""Clumps, rigid bodies of overlapping spheres (``demill/clump.h``): their
templates and the clumps placed in a world (docs/shapes.md, Clumps)."""

import ctypes

import numpy as np

from ._core import Param, doubles, first, ptr, read_counted, read_field
from ._lib import lib
from .constants import ClumpField, Kind, TemplateField
from .objects import Handle


class Template(Handle):
    """A clump template (:meth:`World.clump_template`): the shape of n
    spheres of one material, with the mass properties of their union. Its
    fields are read-only."""

    __slots__ = ()
    kind = Kind.TEMPLATE

    mass = Param(TemplateField.MASS, first, "Mass, kg.")
    volume = Param(TemplateField.VOLUME, first, "The mass over the density, m³.")
    centre = Param(TemplateField.CENTRE, None,
                   "Centre of mass in the frame of the centres given, m (3).")
    principal_moments = Param(TemplateField.PRINCIPAL_MOMENTS, None,
                              "Principal moments of inertia, increasing, kg m² (3; 2D: 0, 0, "
                              "I_z).")
    principal_axes = Param(TemplateField.PRINCIPAL_AXES, lambda v: v.reshape(3, 3),
                           "The principal axes, one per row, in the frame of the centres "
                           "given (3 x 3): the clump's body axes.")
    count = Param(TemplateField.COUNT, lambda v: int(first(v)), "The number of spheres.")
    mesh_volume = Param(TemplateField.MESH_VOLUME, first,
                        "The mesh's volume, m³ (a template from a mesh; else "
                        ":class:`~demill.InvalidValue`, as for the other fit fields).")
    fit_volume_error = Param(TemplateField.FIT_VOLUME_ERROR, first,
                             "(V_mesh - V_union) / V_mesh: the fraction of the mesh the "
                             "spheres leave out.")
    fit_deviation_out = Param(TemplateField.FIT_DEVIATION_OUT, first,
                              "The largest distance from the mesh's surface to the union, m.")
    fit_deviation_in = Param(TemplateField.FIT_DEVIATION_IN, first,
                             "The largest distance from the union's surface to the mesh's, m.")
    fit_cell = Param(TemplateField.FIT_CELL, first, "The side of the fit's grid cubes, m.")

    def spheres(self):
        """The spheres in the body frame (the principal frame clumps carry
        them in): centres (n x 3, m) and radii (n, m). A body-frame point b
        is at ``centre + b @ principal_axes`` in the frame the template was
        made in."""
        n = ctypes.c_size_t()
        self.world._call("demill_clump_template_spheres", self.id, None, None, 0,
                         ctypes.byref(n))
        centres, radii = np.empty((n.value, 3)), np.empty(n.value)
        self.world._call("demill_clump_template_spheres", self.id, ptr(centres), ptr(radii),
                         n.value, ctypes.byref(n))
        return centres, radii

    def _get(self, field):
        size = lib.demill_clump_template_field_size(int(field))
        return read_field(self.world, "demill_clump_template_get", self.id, int(field),
                          size=max(size, 1))


class Clump(Handle):
    """A clump (:meth:`World.add_clump`): a rigid body whose spheres, its
    members, are particles. Position, orientation (a unit quaternion w, x,
    y, z), velocity and angular velocity are read and written; angular
    momentum, force, torque and mass are read-only."""

    __slots__ = ()
    kind = Kind.CLUMP

    position = Param(ClumpField.POSITION, None, "Centre of mass, m (3).")
    orientation = Param(ClumpField.ORIENTATION, None,
                        "Unit quaternion (w, x, y, z) turning the body axes onto the world's.")
    velocity = Param(ClumpField.VELOCITY, None, "Velocity of the centre of mass, m/s (3).")
    angular_velocity = Param(ClumpField.ANGULAR_VELOCITY, None,
                             "Angular velocity, world frame, rad/s (3; in 2D only z).")
    angular_momentum = Param(ClumpField.ANGULAR_MOMENTUM, None,
                             "Angular momentum about the centre of mass, world frame, kg m²/s "
                             "(3; read-only).")
    force = Param(ClumpField.FORCE, None,
                  "Total force at the last force evaluation, N (3; read-only).")
    torque = Param(ClumpField.TORQUE, None,
                   "Total torque about the centre of mass at the last force evaluation, N m "
                   "(3; read-only).")
    mass = Param(ClumpField.MASS, first, "Mass, kg (read-only).")

    def _get(self, field):
        size = lib.demill_clump_field_size(int(field))
        return read_field(self.world, "demill_clump_get", self.id, int(field), size=max(size, 1))

    def _set(self, field, value):
        arr = doubles(value).reshape(-1)
        size = lib.demill_clump_field_size(int(field))
        if size and arr.size != size:
            raise ValueError(f"field {field!r} takes {size} values, got {arr.size}")
        self.world._call("demill_clump_set", self.id, int(field), ptr(arr))

    def members(self):
        """The ids of its spheres' particles, in the template's order (uint64
        array)."""
        def call(buf, capacity, n):
            self.world._call("demill_clump_members", self.id, buf, capacity, n)
        return read_counted(call, 1, np.uint64)

    def remove(self):
        """Removes the clump and its members."""
        self.world._call("demill_clump_remove", self.id)


def particle_clump(world, particle):
    """The clump a particle belongs to, or None."""
    out = ctypes.c_uint64()
    world._call("demill_particle_clump", int(particle), ctypes.byref(out))
    return Clump(world, out.value) if out.value else None
