"""libdemill for Python: discrete element simulation of grinding mills.

A thin, complete binding of the C library over ctypes, with NumPy arrays for
bulk data::

    import demill
    with demill.World(3) as w:
        steel = w.material(density=7800)
        w.pair(steel, steel, normal=demill.Normal.HERTZ,
               damping=demill.Damping.RESTITUTION)
        w.add_plane(steel, (0, 0, 0), (0, 1, 0))
        ids = w.particles.add(steel, [(0, 0.1, 0)], 0.01)
        w.step(20000)
        print(w.particles.positions)

Every failing call raises a :class:`demill.Error` subclass carrying the
status code and the library's message. See docs/getting-started-python.md.
"""

import ctypes
from typing import NamedTuple

from . import constants, errors
from ._core import check, strerror
from ._lib import lib
from .constants import *  # noqa: F403 - the constants and enums
from .constants import VERSION_NUMBER, VERSION_STRING, Kind, Status
from .clumps import Clump, Template
from .drum import Drum, Lifter
from .errors import *  # noqa: F403 - the exceptions
from .flows import Feed, FeedTotals, Outlet, OutletTotals
from .grinding import Grinding
from .objects import Body, Contacts, Material, Pair, Particle, Particles, Wall, WallLoads
from .scene import SceneError, run_scene, scene_program
from .state import Snapshot, VtkSeries
from .world import Progress, TimeStep, World

__version__ = VERSION_STRING
__all__ = (constants.__all__ + errors.__all__ + [
    "World", "Material", "Pair", "Particle", "Particles", "Wall", "WallLoads", "Body", "Clump",
    "Template", "Contacts",
    "Drum", "Lifter", "Feed", "FeedTotals", "Outlet", "OutletTotals",
    "Snapshot", "VtkSeries", "Grinding", "Progress", "TimeStep", "ParamInfo", "library_path",
    "version", "version_number", "check_version", "id_kind", "param_info", "particle_field_size",
    "contact_field_size", "strerror", "SceneError", "run_scene", "scene_program"])


def library_path():
    """The path or name of the shared library that was loaded."""
    return lib.path


def version():
    """The version of the loaded library, "MAJOR.MINOR.PATCH"."""
    return lib.demill_version_string().decode()


def version_number():
    """The version of the loaded library as MAJOR * 10000 + MINOR * 100 + PATCH."""
    return lib.demill_version_number()


def check_version(number=VERSION_NUMBER):
    """Raises :class:`VersionError` unless the loaded library can serve a
    program written for version ``number`` (by default this binding's)."""
    code = lib.demill_check_version(number)
    check(code, f"libdemill {version()} cannot serve version {number} "
                f"(this binding is {VERSION_STRING}): {strerror(code)}")


def id_kind(id_):
    """The :class:`Kind` encoded in an id (or handle), without checking it."""
    return Kind(lib.demill_id_kind(int(getattr(id_, "id", id_))))


class ParamInfo(NamedTuple):
    """What the library says of a parameter key (:func:`param_info`)."""

    key: int
    name: str
    unit: str
    lo: float
    hi: float
    default: float


def param_info(key):
    """Name, unit, bounds and default of a parameter key (world 1xx,
    material 2xx, pair 3xx, drum 4xx); :class:`UnknownKey` if none."""
    lo, hi, default = ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
    check(lib.demill_param_bounds(int(key), ctypes.byref(lo), ctypes.byref(hi),
                                  ctypes.byref(default)),
          f"parameter key {int(key)}: {strerror(Status.UNKNOWN_KEY)}")
    return ParamInfo(key, lib.demill_param_name(int(key)).decode(),
                     lib.demill_param_unit(int(key)).decode(), lo.value, hi.value,
                     default.value)


def particle_field_size(field):
    """Doubles per particle of a particle field (1, 3 or 4; 0 if unknown)."""
    return lib.demill_particle_field_size(int(field))


def contact_field_size(field):
    """Doubles per contact of a contact field (1 or 3; 0 if unknown)."""
    return lib.demill_contact_field_size(int(field))


check_version()
