"""Ore breakage models and the batch-grinding population balance
(``demill/grinding.h``, docs/grinding.md): a :class:`Grinding` object needs
no world."""

import ctypes
import weakref

import numpy as np

from ._core import Closable, check, doubles, ptr, read_counted, strerror
from ._lib import GrindingP, lib
from .constants import Status
from .errors import InvalidHandle


class Grinding(Closable):
    """Size classes in a √2 series below ``top_size`` m (``classes`` of
    them, the last the sink of everything finer), a product, rates, an
    appearance function and an ore breakage model.

    ``Grinding(0.004, 16)`` creates one; use it as a context manager or
    call :meth:`close` to free it at once. Every failing call raises the
    :class:`~demill.Error` of its status with the library's message, and
    leaves the object as it was. Sizes are in m, times in s, rates in 1/s,
    specific impact energies in J/kg, t-values in %.
    """

    def __init__(self, top_size, classes):
        p = GrindingP()
        code = lib.demill_grinding_create(float(top_size), int(classes), ctypes.byref(p))
        check(code, f"demill_grinding_create({top_size}, {classes}): {strerror(code)}")
        self._ptr = p
        self._finalizer = weakref.finalize(self, lib.demill_grinding_destroy, p)

    @property
    def _handle(self):
        if self.closed:
            raise InvalidHandle(Status.INVALID_HANDLE, "the grinding object is closed")
        return self._ptr

    @property
    def last_error(self):
        """The message of the last failed call ("" if the last succeeded)."""
        return lib.demill_grinding_last_error(self._handle).decode(errors="replace")

    def _call(self, name, *args):
        code = getattr(lib, name)(self._handle, *args)
        if code != Status.OK:
            check(code, self.last_error)

    def _read(self, name):
        return read_counted(lambda buf, n, count: self._call(name, buf, n, count), 1,
                            np.float64)

    def _scalar(self, name, *args):
        out = ctypes.c_double()
        self._call(name, *args, ctypes.byref(out))
        return out.value

    # ---- classes, feed, rates, appearance ---------------------------------

    @property
    def sizes(self):
        """The n + 1 class limits, m, from the top size down to 0."""
        return self._read("demill_grinding_sizes")

    @property
    def classes(self):
        """The number of size classes."""
        return len(self.sizes) - 1

    def set_feed(self, mass):
        """Sets the feed (mass per class); the time starts again at 0."""
        arr = doubles(mass, (-1,), "mass")
        self._call("demill_grinding_set_feed", arr.size, ptr(arr))

    @property
    def rates(self):
        """The specific breakage rates S_i, 1/s (the sink's 0)."""
        return self._read("demill_grinding_rates")

    @rates.setter
    def rates(self, values):
        arr = doubles(values, (-1,), "rates")
        self._call("demill_grinding_set_rates", arr.size, ptr(arr))

    @property
    def appearance(self):
        """The appearance function as an n × n array, ``b[i, j]`` the
        fraction of class j's broken mass that lands in class i."""
        b = self._read("demill_grinding_appearance")
        n = int(round(np.sqrt(b.size)))
        return b.reshape(n, n)

    @appearance.setter
    def appearance(self, b):
        arr = doubles(b, (-1, -1), "appearance")
        self._call("demill_grinding_set_appearance", arr.size, ptr(arr))

    # ---- breakage models -------------------------------------------------

    def set_jk(self, a, b, table):
        """The JKMRC model t10 = A (1 - exp(-b E_cs)), A in %, b in t/kWh,
        with the t-family ``table``: rows of t10, t2, t4, t25, t50, t75 (%)."""
        t = doubles(table, (-1, 6), "table")
        self._call("demill_grinding_set_jk", float(a), float(b), t.shape[0], ptr(t))

    def set_tavares(self, e_inf, d0, phi, sigma, emax_ratio, gamma, a_prime, b_prime, table):
        """Tavares and King's model (docs/grinding.md has every parameter and
        its unit) with the t-family ``table``."""
        t = doubles(table, (-1, 6), "table")
        self._call("demill_grinding_set_tavares", float(e_inf), float(d0), float(phi),
                   float(sigma), float(emax_ratio), float(gamma), float(a_prime),
                   float(b_prime), t.shape[0], ptr(t))

    def t10(self, size, energy):
        """The model's t10, %, for a particle of ``size`` m broken by an
        impact of ``energy`` J/kg."""
        return self._scalar("demill_grinding_t10", float(size), float(energy))

    def tn(self, t10):
        """t2, t4, t25, t50, t75 (%) at ``t10`` from the model's table."""
        out = np.empty(5)
        self._call("demill_grinding_tn", float(t10), ptr(out))
        return out

    def broken_fraction(self, size, energy, impacts=1):
        """The fraction of particles of ``size`` broken within ``impacts``
        impacts of ``energy`` J/kg each (Tavares and King, with damage)."""
        return self._scalar("demill_grinding_broken_fraction", float(size), float(energy),
                            int(impacts))

    def set_appearance_energy(self, energy):
        """Sets the appearance function from the model at one impact energy."""
        self._call("demill_grinding_set_appearance_energy", float(energy))

    def rates_from_impacts(self, edges, counts, particles, time):
        """Sets the rates and the appearance function from an impact
        spectrum by Tavares and King's model: ``edges`` the bins' edges
        (J/kg, one more than the bins), ``counts`` an array of classes ×
        bins impacts, ``particles`` the particles of each class and
        ``time`` the time over which they were counted, s
        (``demill_grinding_rates_from_impacts``; the JKMRC model is refused)."""
        e = doubles(edges, (-1,), "edges")
        c = doubles(counts, (-1, e.size - 1), "counts")
        n = doubles(particles, (-1,), "particles")
        self._call("demill_grinding_rates_from_impacts", c.shape[0], c.shape[1], ptr(e),
                   ptr(c), ptr(n), float(time))

    @property
    def damage_time(self):
        """The damage time of :meth:`rates_from_impacts`, s: each energy bin's
        rate counts the damage of the impacts a particle receives in it (0:
        single impacts on fresh particles; ``demill_grinding_set_damage_time``)."""
        return self._scalar("demill_grinding_damage_time")

    @damage_time.setter
    def damage_time(self, time):
        self._call("demill_grinding_set_damage_time", float(time))

    def extend_rates(self, alpha=None, mu=0.0, big_lambda=0.0):
        """Extends the rates to the classes finer than the finest with a rate
        by Austin's S(x) = A (x/1 mm)^alpha / (1 + (x/mu)^Lambda), A fitted
        to the rates there are, and alpha too when ``alpha`` is None; ``mu``
        0 for a power law. Returns (A, alpha) (``demill_grinding_extend_rates``)."""
        fitted = np.empty(2)
        fit = alpha is None
        self._call("demill_grinding_extend_rates", 1 if fit else 0, 0.0 if fit else float(alpha),
                   float(mu), float(big_lambda), ptr(fitted))
        return fitted[0], fitted[1]

    def rates_from_drum(self, drum):
        """Sets the rates and the appearance function from the impacts a
        :class:`~demill.Drum` recorded (:meth:`~demill.Drum.impacts_start`),
        whose classes must be this object's
        (``demill_grinding_rates_from_drum``)."""
        world = drum.world
        code = lib.demill_grinding_rates_from_drum(self._handle, world._handle, drum.id)
        if code != Status.OK:
            check(code, self.last_error or world.last_error)

    # ---- grinding and the product ----------------------------------------

    def run(self, time):
        """Grinds for ``time`` s with the current rates and appearance."""
        self._call("demill_grinding_run", float(time))

    @property
    def time(self):
        """The grinding time since the feed was set, s."""
        return self._scalar("demill_grinding_time")

    @property
    def product(self):
        """The mass per class, in the unit of the feed."""
        return self._read("demill_grinding_product")

    def passing(self, size):
        """The fraction of the product finer than ``size`` m."""
        return self._scalar("demill_grinding_passing", float(size))

    def size_passing(self, fraction):
        """The size, m, that ``fraction`` of the product passes."""
        return self._scalar("demill_grinding_size_passing", float(fraction))

    @property
    def p80(self):
        """The size that 80 % of the product passes, m."""
        return self.size_passing(0.8)

    def specific_energy(self, power, ore_mass):
        """Power ``power`` W × the grinding time / ``ore_mass`` kg, in kWh/t."""
        return self._scalar("demill_grinding_specific_energy", float(power), float(ore_mass))
