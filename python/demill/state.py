"""Objects that own C memory beside a world: in-memory snapshots and VTK
time series. Each is freed by ``close()``, at the end of a ``with`` block,
or when it is garbage-collected; each keeps its world alive."""

import ctypes
import os
import weakref

from ._core import Closable
from ._lib import SnapshotP, VtkSeriesP, lib


class _Owned(Closable):
    """A C object freed by ``free`` exactly once."""

    __slots__ = ("world", "_ptr", "_finalizer", "__weakref__")
    _what = "object"

    def __init__(self, world, pointer, free):
        self.world = world
        self._ptr = pointer
        self._finalizer = weakref.finalize(self, free, pointer)

    def _handle(self):
        if self.closed:
            raise ValueError(f"the {self._what} is closed")
        return self._ptr


class Snapshot(_Owned):
    """An in-memory copy of a world's whole state (:meth:`World.snapshot`),
    for going back to it with :meth:`restore`, e.g. in parameter sweeps."""

    __slots__ = ()
    _what = "snapshot"

    @classmethod
    def take(cls, world):
        """Takes a snapshot of ``world``."""
        p = SnapshotP()
        world._call("demill_snapshot_take", ctypes.byref(p))
        return cls(world, p, lib.demill_snapshot_free)

    def restore(self, world=None):
        """Puts the world (by default the one it was taken of) back into the
        snapshot's state."""
        (world or self.world)._call("demill_snapshot_restore", self._handle())


class VtkSeries(_Owned):
    """A VTK time series (:meth:`World.vtk_series`): each :meth:`write` adds
    a frame of the particles and walls to the ``.pvd`` files of ``prefix``."""

    __slots__ = ()
    _what = "VTK series"

    @classmethod
    def open(cls, world, prefix):
        """Opens a series of files named from ``prefix``."""
        p = VtkSeriesP()
        world._call("demill_vtk_series_open", os.fsencode(prefix), ctypes.byref(p))
        return cls(world, p, lib.demill_vtk_series_close)

    def write(self):
        """Writes a frame of the world's current state."""
        self.world._call("demill_vtk_series_write", self._handle())
