"""Feeds and outlets of a world (demill/insert.h): particles inserted over
time at a mass rate, and particles removed and counted where they leave."""

import ctypes
from typing import NamedTuple

import numpy as np

from ._core import ptr
from .constants import Kind
from .objects import Handle


class FeedTotals(NamedTuple):
    """What a feed has inserted: mass (kg), count, and the mass owed but not
    inserted (kg)."""

    mass: float
    count: int
    deficit: float


class OutletTotals(NamedTuple):
    """What an outlet has removed per size class (counts, masses in kg), and
    over its last completed interval: mass (kg), count, and the interval's
    end time (s)."""

    counts: np.ndarray
    masses: np.ndarray
    last_mass: float
    last_count: int
    last_end: float


class Feed(Handle):
    """A feed (:meth:`World.add_feed`)."""

    __slots__ = ()
    kind = Kind.FEED

    @property
    def totals(self):
        """A :class:`FeedTotals`."""
        mass, deficit, n = ctypes.c_double(), ctypes.c_double(), ctypes.c_uint64()
        self.world._call("demill_feed_read", self.id, ctypes.byref(mass), ctypes.byref(n),
                         ctypes.byref(deficit))
        return FeedTotals(mass.value, n.value, deficit.value)

    def remove(self):
        """Removes the feed (its particles stay); its id becomes invalid."""
        self.world._call("demill_feed_remove", self.id)


class Outlet(Handle):
    """An outlet (:meth:`World.add_outlet`)."""

    __slots__ = ()
    kind = Kind.OUTLET

    @property
    def totals(self):
        """An :class:`OutletTotals`."""
        n = ctypes.c_size_t()
        self.world._call("demill_outlet_read", self.id, None, None, 0, ctypes.byref(n), None)
        counts = np.zeros(n.value, dtype=np.uint64)
        masses = np.zeros(n.value)
        last = np.zeros(3)
        self.world._call("demill_outlet_read", self.id,
                         ptr(counts), ptr(masses),
                         n.value, ctypes.byref(n), ptr(last))
        return OutletTotals(counts, masses, float(last[0]), int(last[1]), float(last[2]))

    def remove(self):
        """Removes the outlet; its id becomes invalid."""
        self.world._call("demill_outlet_remove", self.id)
