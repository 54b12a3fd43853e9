/* status.h: a world's last error message and its count of changes. */
#ifndef DM_STATUS_H
#define DM_STATUS_H

#include "base/base.h"

/* Writes the world's message and returns code. */
demill_status dm_fail(demill_world *w, demill_status code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* DEMILL_ERR_NULL_POINTER or DEMILL_ERR_INVALID_HANDLE unless w is a live world. */
demill_status dm_check_world(const demill_world *w);
void dm_clear_error(demill_world *w);
/* The end of a call that succeeded and may have changed the world. */
void dm_changed(demill_world *w);

#endif /* DM_STATUS_H */
