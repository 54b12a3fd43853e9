/* status.c: status code texts and the per-world last-error message. */
#include <stdarg.h>
#include <stdio.h>

#include "base/status.h"

DEMILL_API const char *demill_strerror(demill_status code)
{
    switch (code) {
    case DEMILL_OK: return "success";
    case DEMILL_ERR_NULL_POINTER: return "a required pointer argument is NULL";
    case DEMILL_ERR_INVALID_VALUE: return "a value is out of its allowed range";
    case DEMILL_ERR_NOT_FINITE: return "a value is NaN or infinite";
    case DEMILL_ERR_UNKNOWN_KEY: return "unknown parameter key, field or enum value";
    case DEMILL_ERR_INVALID_HANDLE: return "invalid handle: removed, of another world, or of the wrong kind";
    case DEMILL_ERR_NO_CONTACT_MODEL: return "a pair of materials that may touch has no contact model";
    case DEMILL_ERR_OVERLAP: return "inserted particles overlap";
    case DEMILL_ERR_OUT_OF_MEMORY: return "out of memory";
    case DEMILL_ERR_BUFFER_TOO_SMALL: return "the buffer is too small";
    case DEMILL_ERR_READ_ONLY: return "the parameter or field is read-only";
    case DEMILL_ERR_DIMENSION: return "the value is not allowed in a world of this dimension";
    case DEMILL_ERR_VERSION: return "the library version is not compatible with the headers";
    case DEMILL_ERR_UNSUPPORTED: return "the library was built without what this needs";
    case DEMILL_ERR_UNSTABLE: return "the simulation went unstable; the world is at its last good state";
    case DEMILL_ERR_IO: return "input/output error";
    case DEMILL_ERR_FORMAT: return "not a valid file of this kind, or of an unsupported version";
    case DEMILL_ERR_INTERRUPTED: return "the run was stopped by its progress callback";
    case DEMILL_ERR_LIMIT: return "a fixed limit of the library was reached";
    default: return "unknown status code";
    }
}

demill_status dm_fail(demill_world *w, demill_status code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    dm_base *b = dm_base_of(w);
    vsnprintf(b->error, sizeof b->error, fmt, ap);
    va_end(ap);
    return code;
}

void dm_clear_error(demill_world *w)
{
    dm_base_of(w)->error[0] = '\0';
}

void dm_changed(demill_world *w)
{
    dm_base_of(w)->edits++;
    dm_clear_error(w);
}

demill_status dm_check_world(const demill_world *w)
{
    if (!w)
        return DEMILL_ERR_NULL_POINTER;
    if (dm_base_of_const(w)->magic != DM_WORLD_MAGIC)
        return DEMILL_ERR_INVALID_HANDLE;
    return DEMILL_OK;
}

DEMILL_API const char *demill_world_last_error(const demill_world *world)
{
    if (!world)
        return "world is NULL";
    if (dm_base_of_const(world)->magic != DM_WORLD_MAGIC)
        return "not a demill world (destroyed or never created)";
    return dm_base_of_const(world)->error;
}
