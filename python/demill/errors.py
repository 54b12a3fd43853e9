"""Exceptions: every status other than ``DEMILL_OK`` raises an :class:`Error`.

Each status code has its own subclass (:class:`InvalidValue`,
:class:`UnknownKey`, :class:`Unstable`, ...), so that a caller can catch
exactly what it can handle; all carry the code and the library's message.
"""

from .constants import Status

__all__ = ["Error", "NullPointer", "InvalidValue", "NotFinite", "UnknownKey", "InvalidHandle",
           "WorldClosed", "NoContactModel", "Overlap", "OutOfMemory", "BufferTooSmall",
           "ReadOnly", "DimensionError", "VersionError", "Unsupported", "Unstable",
           "FileError", "FormatError", "Interrupted",
           "LimitError"]


class Error(Exception):
    """A libdemill call failed.

    Attributes:
        code: the :class:`~demill.Status` the library returned.
        message: the library's message, naming the argument, particle or
            parameter at fault (``demill_world_last_error``), or the generic
            text of the code (``demill_strerror``) when no world is involved.
    """

    code = None

    def __init__(self, code, message):
        self.code = Status(code) if code in Status._value2member_map_ else code
        self.message = message
        super().__init__(code, message)

    def __str__(self):
        name = self.code.name if isinstance(self.code, Status) else self.code
        return f"{self.message} [{name}]"


class NullPointer(Error):
    """``DEMILL_ERR_NULL_POINTER``: a required pointer was NULL."""


class InvalidValue(Error, ValueError):
    """``DEMILL_ERR_INVALID_VALUE``: a value is out of its allowed range."""


class NotFinite(Error, ValueError):
    """``DEMILL_ERR_NOT_FINITE``: a value is NaN or infinite."""


class UnknownKey(Error, LookupError):
    """``DEMILL_ERR_UNKNOWN_KEY``: unknown parameter key, field or enum value."""


class InvalidHandle(Error):
    """``DEMILL_ERR_INVALID_HANDLE``: an id removed, of another world or kind."""


class WorldClosed(InvalidHandle):
    """The world was closed (:meth:`World.close`); nothing can use it."""


class NoContactModel(Error):
    """``DEMILL_ERR_NO_CONTACT_MODEL``: materials that may touch lack a model."""


class Overlap(Error):
    """``DEMILL_ERR_OVERLAP``: inserted particles overlap."""


class OutOfMemory(Error, MemoryError):
    """``DEMILL_ERR_OUT_OF_MEMORY``."""


class BufferTooSmall(Error):
    """``DEMILL_ERR_BUFFER_TOO_SMALL`` (the binding sizes its buffers itself)."""


class ReadOnly(Error):
    """``DEMILL_ERR_READ_ONLY``: the parameter or field cannot be written."""


class DimensionError(Error, ValueError):
    """``DEMILL_ERR_DIMENSION``: not allowed in a world of this dimension."""


class VersionError(Error):
    """``DEMILL_ERR_VERSION``: the library is not compatible with the binding."""


class Unsupported(Error):
    """``DEMILL_ERR_UNSUPPORTED``: the library was built without what this needs."""


class Unstable(Error):
    """``DEMILL_ERR_UNSTABLE``: the run went unstable; the world is at its last
    good state (lower the time step and step again)."""


class FileError(Error):
    """``DEMILL_ERR_IO``: a file could not be opened, read or written."""


class FormatError(Error):
    """``DEMILL_ERR_FORMAT``: a file or buffer is foreign, truncated or corrupt."""


class Interrupted(Error):
    """``DEMILL_ERR_INTERRUPTED``: the progress callback stopped the run."""


class LimitError(Error):
    """``DEMILL_ERR_LIMIT``: a fixed limit of the library was reached (4096
    live worlds, 65535 drums made in one world)."""


#: The exception class of each status code.
ERRORS = {
    Status.NULL_POINTER: NullPointer,
    Status.INVALID_VALUE: InvalidValue,
    Status.NOT_FINITE: NotFinite,
    Status.UNKNOWN_KEY: UnknownKey,
    Status.INVALID_HANDLE: InvalidHandle,
    Status.NO_CONTACT_MODEL: NoContactModel,
    Status.OVERLAP: Overlap,
    Status.OUT_OF_MEMORY: OutOfMemory,
    Status.BUFFER_TOO_SMALL: BufferTooSmall,
    Status.READ_ONLY: ReadOnly,
    Status.DIMENSION: DimensionError,
    Status.VERSION: VersionError,
    Status.UNSUPPORTED: Unsupported,
    Status.UNSTABLE: Unstable,
    Status.IO: FileError,
    Status.FORMAT: FormatError,
    Status.INTERRUPTED: Interrupted,
    Status.LIMIT: LimitError,
}


def error_for(code, message):
    """The exception for a status code and message (an :class:`Error`)."""
    return ERRORS.get(code, Error)(code, message)

#: The status code of each exception class.
ERRORS_BY_CLASS = {cls: code for code, cls in ERRORS.items()}
ERRORS_BY_CLASS[WorldClosed] = Status.INVALID_HANDLE
