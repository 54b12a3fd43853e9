"""Loading libdemill and declaring the C prototypes for ctypes.

The library is searched, in order:

1. the file named by the environment variable ``DEMILL_LIBRARY``;
2. a build tree of the source checkout this package sits in
   (``build*/libdemill.so`` beside ``python/``; the newest if several);
3. an installed library (``ctypes.util.find_library("demill")``, then
   ``libdemill.so.0``).

Every function has its ``argtypes`` and ``restype`` declared, so ctypes checks
each argument's type.  Functions newer than the oldest library this binding
supports are *optional*: when the loaded library lacks one, calling it raises
:class:`demill.Unsupported` instead of failing the import.
"""

import ctypes
import ctypes.util
import os
from ctypes import POINTER, c_char_p, c_double, c_int32, c_size_t, c_uint32, c_uint64, c_void_p
from pathlib import Path

from .constants import Status
from .errors import Unsupported


class _World(ctypes.Structure):
    """Opaque ``demill_world``."""


class _Snapshot(ctypes.Structure):
    """Opaque ``demill_snapshot``."""


class _VtkSeries(ctypes.Structure):
    """Opaque ``demill_vtk_series``."""


class _Grinding(ctypes.Structure):
    """Opaque ``demill_grinding``."""


WorldP = POINTER(_World)
SnapshotP = POINTER(_Snapshot)
VtkSeriesP = POINTER(_VtkSeries)
GrindingP = POINTER(_Grinding)
status = c_int32
id_t = c_uint64
dptr = POINTER(c_double)
idptr = POINTER(c_uint64)
sizeptr = POINTER(c_size_t)

#: typedef int32_t (*demill_progress_fn)(void *, uint64_t, uint64_t, double, double)
ProgressFn = ctypes.CFUNCTYPE(c_int32, c_void_p, c_uint64, c_uint64, c_double, c_double)

#: name: (restype, argtypes) of every function of the public API.
PROTOTYPES = {
    # common.h
    "demill_version_number": (c_uint32, ()),
    "demill_version_string": (c_char_p, ()),
    "demill_check_version": (c_int32, (c_uint32,)),
    "demill_strerror": (c_char_p, (status,)),
    "demill_id_kind": (c_int32, (id_t,)),
    "demill_param_name": (c_char_p, (c_int32,)),
    "demill_param_unit": (c_char_p, (c_int32,)),
    "demill_param_bounds": (status, (c_int32, dptr, dptr, dptr)),
    # world.h
    "demill_world_create": (status, (c_int32, POINTER(WorldP))),
    "demill_world_destroy": (None, (WorldP,)),
    "demill_world_last_error": (c_char_p, (WorldP,)),
    "demill_world_set": (status, (WorldP, c_int32, c_double)),
    "demill_world_get": (status, (WorldP, c_int32, dptr)),
    "demill_world_step": (status, (WorldP, c_uint64)),
    "demill_world_suggest_time_step": (status, (WorldP, c_double, c_double, dptr, dptr, dptr)),
    # material.h
    "demill_material_create": (status, (WorldP, idptr)),
    "demill_material_set": (status, (WorldP, id_t, c_int32, c_double)),
    "demill_material_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_pair_set": (status, (WorldP, id_t, id_t, c_int32, c_double)),
    "demill_pair_get": (status, (WorldP, id_t, id_t, c_int32, dptr)),
    # particles.h
    "demill_particle_field_size": (c_int32, (c_int32,)),
    "demill_particles_add": (status, (WorldP, id_t, c_size_t, dptr, dptr, dptr, c_uint32, idptr)),
    "demill_particles_remove": (status, (WorldP, c_size_t, idptr)),
    "demill_particles_read": (status, (WorldP, c_int32, dptr, c_size_t, sizeptr)),
    "demill_particles_read_ids": (status, (WorldP, c_int32, idptr, c_size_t, sizeptr)),
    "demill_particles_write": (status, (WorldP, c_int32, dptr, c_size_t)),
    "demill_particle_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_particle_set": (status, (WorldP, id_t, c_int32, dptr)),
    # wall.h
    "demill_wall_add_plane": (status, (WorldP, id_t, dptr, dptr, idptr)),
    "demill_wall_remove": (status, (WorldP, id_t)),
    "demill_wall_set_motion": (status, (WorldP, id_t, dptr, dptr, dptr)),
    "demill_wall_get": (status, (WorldP, id_t, c_int32, dptr)),
    # query.h
    "demill_contact_field_size": (c_int32, (c_int32,)),
    "demill_contacts_read": (status, (WorldP, c_int32, dptr, c_size_t, sizeptr)),
    "demill_contacts_read_ids": (status, (WorldP, idptr, idptr, c_size_t, sizeptr)),
    "demill_world_energy": (status, (WorldP, c_int32, dptr)),
    # drum.h
    "demill_drum_create": (status, (WorldP, id_t, idptr)),
    "demill_drum_remove": (status, (WorldP, id_t)),
    "demill_drum_set": (status, (WorldP, id_t, c_int32, c_double)),
    "demill_drum_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_drum_set_material": (status, (WorldP, id_t, c_int32, id_t)),
    "demill_drum_get_material": (status, (WorldP, id_t, c_int32, idptr)),
    "demill_drum_add_lifter": (status, (WorldP, id_t, c_double, c_double, c_double, c_double)),
    "demill_drum_lifter_get": (status, (WorldP, id_t, c_uint32, c_int32, dptr)),
    "demill_drum_fill": (status, (WorldP, id_t, id_t, c_int32, dptr, c_size_t, c_int32, c_double,
                                  c_uint64, idptr, c_size_t, sizeptr)),
    "demill_drum_spectrum_start": (status, (WorldP, id_t, c_size_t, dptr, c_uint32, c_double,
                                            c_double)),
    "demill_drum_spectrum": (status, (WorldP, id_t, POINTER(c_uint64), c_size_t, sizeptr)),
    "demill_drum_impacts_start": (status, (WorldP, id_t, id_t, c_double, c_uint32, c_uint32,
                                           c_double, c_double)),
    "demill_drum_impacts": (status, (WorldP, id_t, POINTER(c_uint64), c_size_t, sizeptr, dptr)),
    "demill_drum_impacts_particles": (status, (WorldP, id_t, POINTER(c_uint64), c_size_t,
                                               sizeptr)),
    "demill_grinding_rates_from_drum": (status, (GrindingP, WorldP, id_t)),
    "demill_world_settle": (status, (WorldP, c_double, c_double, POINTER(c_int32))),
}

#: Functions newer than the oldest library this binding supports (bodies,
#: clumps, progress, VTK output, snapshots and checkpoints, object listing,
#: mesh walls, finite walls and wall motions, wall loads, grinding): bound when
#: the library has them.
OPTIONAL_PROTOTYPES = {
    # body.h
    "demill_body_add": (status, (WorldP, c_double, dptr, c_int32, c_uint32, idptr)),
    "demill_body_remove": (status, (WorldP, id_t)),
    "demill_body_set_spring": (status, (WorldP, id_t, c_int32, c_double, c_double, c_double)),
    "demill_body_set_force": (status, (WorldP, id_t, dptr, c_double, c_double)),
    "demill_body_attach_wall": (status, (WorldP, id_t, id_t)),
    "demill_body_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_body_energy": (status, (WorldP, id_t, c_int32, dptr)),
    # clump.h
    "demill_clump_template_field_size": (c_int32, (c_int32,)),
    "demill_clump_field_size": (c_int32, (c_int32,)),
    "demill_clump_template_add": (status, (WorldP, id_t, c_size_t, dptr, dptr, idptr)),
    "demill_clump_template_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_clump_template_from_mesh": (status, (WorldP, id_t, c_size_t, dptr, c_size_t,
                                                 POINTER(c_uint32), c_size_t, c_int32, idptr)),
    "demill_clump_template_from_stl": (status, (WorldP, id_t, c_char_p, c_double, c_size_t,
                                                c_int32, idptr)),
    "demill_clump_template_spheres": (status, (WorldP, id_t, dptr, dptr, c_size_t, sizeptr)),
    "demill_clump_add": (status, (WorldP, id_t, dptr, dptr, idptr)),
    "demill_clump_remove": (status, (WorldP, id_t)),
    "demill_clump_get": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_clump_set": (status, (WorldP, id_t, c_int32, dptr)),
    "demill_clump_members": (status, (WorldP, id_t, idptr, c_size_t, sizeptr)),
    "demill_particle_clump": (status, (WorldP, id_t, idptr)),
    "demill_clump_fill_region": (status, (WorldP, c_int32, dptr, c_size_t, id_t, c_int32,
                                          c_double, c_uint64, idptr, c_size_t, sizeptr)),
    "demill_world_set_progress": (status, (WorldP, ProgressFn, c_void_p, c_uint64)),
    "demill_vtk_write_particles": (status, (WorldP, c_char_p)),
    "demill_vtk_write_walls": (status, (WorldP, c_char_p)),
    "demill_vtk_series_open": (status, (WorldP, c_char_p, POINTER(VtkSeriesP))),
    "demill_vtk_series_write": (status, (WorldP, VtkSeriesP)),
    "demill_vtk_series_close": (None, (VtkSeriesP,)),
    "demill_snapshot_take": (status, (WorldP, POINTER(SnapshotP))),
    "demill_snapshot_restore": (status, (WorldP, SnapshotP)),
    "demill_snapshot_free": (None, (SnapshotP,)),
    "demill_world_save": (status, (WorldP, c_char_p)),
    "demill_world_load": (status, (WorldP, c_char_p)),
    "demill_world_save_buffer": (status, (WorldP, c_void_p, c_size_t, sizeptr)),
    "demill_world_load_buffer": (status, (WorldP, c_void_p, c_size_t)),
    "demill_world_ids": (status, (WorldP, c_int32, idptr, c_size_t, sizeptr)),
    "demill_wall_add_mesh": (status, (WorldP, id_t, c_size_t, dptr, c_size_t, POINTER(c_uint32),
                                      idptr)),
    "demill_wall_add_stl": (status, (WorldP, id_t, c_void_p, c_size_t, c_double, dptr, idptr)),
    "demill_wall_load_stl": (status, (WorldP, id_t, c_char_p, c_double, dptr, idptr)),
    "demill_drum_attach_wall": (status, (WorldP, id_t, id_t, c_int32)),
    "demill_drum_add_profile": (status, (WorldP, id_t, id_t, c_int32, c_size_t, dptr, c_int32,
                                         c_uint32, idptr)),
    "demill_wall_add_polyline": (status, (WorldP, id_t, c_size_t, dptr, c_int32, idptr)),
    "demill_wall_mesh_info": (status, (WorldP, id_t, sizeptr, sizeptr)),
    # insert.h
    "demill_fill_region": (status, (WorldP, c_int32, dptr, c_size_t, id_t, c_int32, dptr,
                                    c_size_t, c_int32, c_double, c_uint64, idptr, c_size_t,
                                    sizeptr)),
    "demill_feed_create": (status, (WorldP, c_int32, dptr, c_size_t, id_t, c_int32, dptr,
                                    c_size_t, c_double, dptr, c_double, c_double, c_uint64,
                                    idptr)),
    "demill_feed_remove": (status, (WorldP, id_t)),
    "demill_feed_read": (status, (WorldP, id_t, dptr, POINTER(c_uint64), dptr)),
    "demill_outlet_create": (status, (WorldP, c_int32, dptr, c_size_t, c_size_t, dptr, c_double,
                                      idptr)),
    "demill_outlet_remove": (status, (WorldP, id_t)),
    "demill_outlet_read": (status, (WorldP, id_t, POINTER(c_uint64), dptr, c_size_t, sizeptr,
                                    dptr)),
    # wall.h: finite walls, harmonic motion, surface velocity
    "demill_wall_add_cylinder": (status, (WorldP, id_t, dptr, dptr, c_double, c_double, c_int32,
                                          idptr)),
    "demill_wall_add_cone": (status, (WorldP, id_t, dptr, dptr, c_double, c_double, c_double,
                                      c_int32, idptr)),
    "demill_wall_add_disc": (status, (WorldP, id_t, dptr, dptr, c_double, c_double, idptr)),
    "demill_wall_add_rectangle": (status, (WorldP, id_t, dptr, dptr, dptr, c_double, c_double,
                                           idptr)),
    "demill_wall_set_harmonic": (status, (WorldP, id_t, c_int32, dptr, c_double, c_double,
                                          c_double)),
    "demill_wall_set_surface_velocity": (status, (WorldP, id_t, dptr)),
    "demill_wall_loads_start": (status, (WorldP, id_t)),
    "demill_wall_loads_stop": (status, (WorldP, id_t)),
    "demill_wall_loads": (status, (WorldP, id_t, c_size_t, dptr, dptr, dptr, dptr, dptr)),
    # grinding.h
    "demill_grinding_create": (status, (c_double, c_uint32, POINTER(GrindingP))),
    "demill_grinding_destroy": (None, (GrindingP,)),
    "demill_grinding_last_error": (c_char_p, (GrindingP,)),
    "demill_grinding_sizes": (status, (GrindingP, dptr, c_size_t, sizeptr)),
    "demill_grinding_set_feed": (status, (GrindingP, c_size_t, dptr)),
    "demill_grinding_set_rates": (status, (GrindingP, c_size_t, dptr)),
    "demill_grinding_rates": (status, (GrindingP, dptr, c_size_t, sizeptr)),
    "demill_grinding_set_appearance": (status, (GrindingP, c_size_t, dptr)),
    "demill_grinding_appearance": (status, (GrindingP, dptr, c_size_t, sizeptr)),
    "demill_grinding_set_jk": (status, (GrindingP, c_double, c_double, c_size_t, dptr)),
    "demill_grinding_set_tavares": (status, (GrindingP, c_double, c_double, c_double, c_double,
                                             c_double, c_double, c_double, c_double, c_size_t,
                                             dptr)),
    "demill_grinding_t10": (status, (GrindingP, c_double, c_double, dptr)),
    "demill_grinding_tn": (status, (GrindingP, c_double, dptr)),
    "demill_grinding_broken_fraction": (status, (GrindingP, c_double, c_double, c_uint32, dptr)),
    "demill_grinding_set_appearance_energy": (status, (GrindingP, c_double)),
    "demill_grinding_rates_from_impacts": (status, (GrindingP, c_size_t, c_size_t, dptr, dptr,
                                                    dptr, c_double)),
    "demill_grinding_set_damage_time": (status, (GrindingP, c_double)),
    "demill_grinding_damage_time": (status, (GrindingP, dptr)),
    "demill_grinding_extend_rates": (status, (GrindingP, c_int32, c_double, c_double, c_double,
                                              dptr)),
    "demill_grinding_run": (status, (GrindingP, c_double)),
    "demill_grinding_time": (status, (GrindingP, dptr)),
    "demill_grinding_product": (status, (GrindingP, dptr, c_size_t, sizeptr)),
    "demill_grinding_passing": (status, (GrindingP, c_double, dptr)),
    "demill_grinding_size_passing": (status, (GrindingP, c_double, dptr)),
    "demill_grinding_specific_energy": (status, (GrindingP, c_double, c_double, dptr)),
}


def library_candidates():
    """The paths or names to try, in order (see the module's docstring)."""
    env = os.environ.get("DEMILL_LIBRARY")
    if env:
        return [env]
    root = Path(__file__).resolve().parent.parent.parent
    built = sorted(root.glob("build*/libdemill.so"), key=lambda p: p.stat().st_mtime,
                   reverse=True)
    names = [str(p) for p in built]
    found = ctypes.util.find_library("demill")
    if found:
        names.append(found)
    names.append("libdemill.so.0")
    return names


def _load():
    errors = []
    for name in library_candidates():
        try:
            return ctypes.CDLL(name), name
        except OSError as e:
            errors.append(f"{name}: {e}")
    raise ImportError("libdemill not found; build it (cmake --build build) or set "
                      "DEMILL_LIBRARY to the path of libdemill.so. Tried:\n  "
                      + "\n  ".join(errors))


def _missing(name, path):
    def call(*args):
        raise Unsupported(Status.UNSUPPORTED,
                          f"{name} is not in this libdemill ({path}); a newer one is needed")
    call.__name__ = name
    return call


class Library:
    """The loaded shared library with every prototype declared.

    Attributes are the C functions (``lib.demill_world_step``); ``path`` is
    the file that was loaded and :meth:`has` says whether an optional
    function is present.
    """

    def __init__(self):
        self.cdll, self.path = _load()
        self._present = set()
        for table, optional in ((PROTOTYPES, False), (OPTIONAL_PROTOTYPES, True)):
            for name, (restype, argtypes) in table.items():
                try:
                    fn = getattr(self.cdll, name)
                except AttributeError:
                    if not optional:
                        raise ImportError(f"{self.path} lacks {name}: not a libdemill of "
                                          f"this series") from None
                    setattr(self, name, _missing(name, self.path))
                    continue
                fn.restype = restype
                fn.argtypes = argtypes
                setattr(self, name, fn)
                self._present.add(name)

    def has(self, name):
        """True if the library exports the function ``name``."""
        return name in self._present


lib = Library()
