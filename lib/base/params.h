/* params.h: the checks every setter applies to a parameter's value. */
#ifndef DM_PARAMS_H
#define DM_PARAMS_H

#include "base/base.h"

/* Checks a value for a settable key: known, writable, finite, in bounds and
 * whole where a choice is expected. Sets the world's message on failure. */
demill_status dm_check_value(demill_world *w, int32_t key, double value);

#endif /* DM_PARAMS_H */
