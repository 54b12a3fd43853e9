"""Small generic helpers the classes share: status checks, parameter
properties and NumPy buffers."""

import ctypes

import numpy as np

from ._lib import dptr, idptr, lib
from .constants import Status
from .errors import error_for


class Closable:
    """A C object freed exactly once, by ``self._finalizer``: ``closed``,
    ``close()`` (again is harmless) and ``with`` blocks that close it."""

    __slots__ = ()

    @property
    def closed(self):
        """True once the C object is freed."""
        return not self._finalizer.alive

    def close(self):
        """Frees the C object (again is harmless)."""
        self._finalizer()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def strerror(code):
    """The library's generic text of a status code (``demill_strerror``)."""
    return lib.demill_strerror(int(code)).decode()


def check(code, message=None):
    """Raises the :class:`~demill.Error` of a status code unless it is OK.

    ``message`` is the text to carry (a world's last error); when it is
    empty or missing the generic text of the code is used.
    """
    if code != Status.OK:
        raise error_for(code, message or strerror(code))


def doubles(values, shape=None, name="values"):
    """``values`` as a C-contiguous float64 array, copied only if needed.

    With ``shape``, the array must have that shape after broadcasting a
    scalar or a (3,) vector; -1 in the shape stands for any length.
    """
    arr = np.asarray(values, dtype=np.float64)
    if shape is not None:
        if arr.ndim == 0 and -1 not in shape:
            arr = np.full(shape, float(arr))
        if len(shape) == 2 and arr.ndim == 1 and arr.shape[0] == shape[1]:
            arr = arr.reshape(1, shape[1])
        if arr.ndim != len(shape) or any(s not in (-1, a) for s, a in zip(shape, arr.shape)):
            want = " x ".join("n" if s == -1 else str(s) for s in shape)
            raise ValueError(f"{name}: expected an array of shape {want}, got {arr.shape}")
    return np.ascontiguousarray(arr)


def vector(value, name="vector"):
    """A 3-vector as a float64 array of 3 (or None for None)."""
    return None if value is None else doubles(value, (3,), name)


def ptr(arr):
    """A ctypes pointer to a float64 or uint64 array's data, or None."""
    if arr is None:
        return None
    return arr.ctypes.data_as(idptr if arr.dtype == np.uint64 else dptr)


def output(shape, dtype, out, name="out"):
    """``out`` checked to be a writable C-contiguous array of ``shape`` and
    ``dtype``, or a new empty one when ``out`` is None."""
    if out is None:
        return np.empty(shape, dtype)
    if (not isinstance(out, np.ndarray) or out.dtype != dtype or out.shape != shape
            or not out.flags.c_contiguous or not out.flags.writeable):
        raise ValueError(f"{name}: expected a writable C-contiguous {np.dtype(dtype)} "
                         f"array of shape {shape}")
    return out


def read_counted(call, width, dtype, out=None):
    """Reads a variable-length array through a C function of the pattern
    ``f(..., out, capacity, &count)``: ``call(buffer, capacity, count_ptr)``
    is called first with no buffer to learn the count, then with the array
    (``(count, width)``, or ``(count,)`` for width 1)."""
    count = ctypes.c_size_t()
    call(None, 0, ctypes.byref(count))
    n = count.value
    arr = output((n, width) if width > 1 else (n,), dtype, out)
    call(ptr(arr), n, ctypes.byref(count))
    return arr


def param_doc(key):
    """A one-line description of a parameter key from the library's metadata."""
    name = lib.demill_param_name(int(key))
    if name is None:
        return None
    lo, hi, default = ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
    lib.demill_param_bounds(int(key), ctypes.byref(lo), ctypes.byref(hi), ctypes.byref(default))
    unit = lib.demill_param_unit(int(key)).decode()
    return (f"{name.decode()} ({unit}): in [{lo.value:g}, {hi.value:g}], "
            f"default {default.value:g}. Key {key!r}.")


class Param:
    """A property backed by a key: reads ``obj._get(key)`` through
    ``convert`` and writes ``obj._set(key, value)``.

    The owner defines ``_get`` and ``_set`` (a world, material, pair or drum
    parameter; a particle field); an owner without ``_set`` makes the
    property read-only. Errors are the library's, e.g. assigning a
    read-only world key raises :class:`~demill.ReadOnly`.
    """

    def __init__(self, key, convert=float, doc=None):
        self.key = key
        self.convert = convert
        self.__doc__ = doc or param_doc(key)

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, obj, objtype=None):
        if obj is None:
            return self
        value = obj._get(self.key)
        return value if self.convert is None else self.convert(value)

    def __set__(self, obj, value):
        setter = getattr(obj, "_set", None)
        if setter is None:
            raise AttributeError(f"{self.name} is read-only")
        setter(self.key, value)


class VectorParam:
    """A 3-vector property made of three scalar keys (e.g. gravity). Setting
    it sets all three or, if one is refused, none."""

    def __init__(self, keys, doc=None):
        self.keys = keys
        self.__doc__ = doc

    def __get__(self, obj, objtype=None):
        if obj is None:
            return self
        return np.array([obj._get(k) for k in self.keys])

    def __set__(self, obj, value):
        new = vector(value)
        old = self.__get__(obj)
        try:
            for k, v in zip(self.keys, new):
                obj._set(k, float(v))
        except Exception:
            for k, v in zip(self.keys, old):
                obj._set(k, float(v))
            raise


def read_field(world, name, *args, size=3):
    """Calls ``name(world, *args, out)`` with a new array of ``size``
    doubles for ``out`` and returns it."""
    out = np.empty(size)
    world._call(name, *args, ptr(out))
    return out


def first(arr):
    """The first element of a 1-element buffer as a float."""
    return float(arr[0])


def configure(obj, params):
    """Sets ``params`` (name: value) as attributes of ``obj``; every name
    must be one of the class's parameter properties."""
    for name, value in params.items():
        if not isinstance(getattr(type(obj), name, None), (Param, VectorParam)):
            raise TypeError(f"{type(obj).__name__} has no parameter {name!r}")
        setattr(obj, name, value)
    return obj


def as_id(obj):
    """The id of a handle (anything with ``.id``) or of an integer."""
    return int(getattr(obj, "id", obj))


class Keyed:
    """Mixin of the objects configured through keys: ``get(key)`` and
    ``set(key, value)`` by key, or ``set(name=value, ...)`` by property.

    A subclass names its C getter and setter (``_getter``, ``_setter``:
    ``f(world, *ids, key, value)``) and the ids before the key
    (``_ids()``), or overrides ``_get`` and ``_set``.
    """

    __slots__ = ()
    _getter = _setter = None

    def _ids(self):
        return (self.id,)

    def _get(self, key):
        v = ctypes.c_double()
        self.world._call(self._getter, *self._ids(), int(key), ctypes.byref(v))
        return v.value

    def _set(self, key, value):
        self.world._call(self._setter, *self._ids(), int(key), float(value))

    def get(self, key):
        """The value of a key (a float, or an array for a vector field)."""
        return self._get(key)

    def set(self, key=None, value=None, **params):
        """Sets a key to a value, and/or parameters by property name, e.g.
        ``material.set(density=7800, friction=0.5)``."""
        if key is not None:
            self._set(key, value)
        configure(self, params)
        return self
