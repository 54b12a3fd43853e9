/* files.c: reading a whole file for the API's loading functions
 * (checkpoints, STL meshes), with the reason of a failure in the world's
 * message. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "world/world.h"

demill_status dm_read_file(demill_world *w, const char *fn, const char *path, uint8_t **bytes,
                           size_t *size)
{
    *bytes = NULL;
    *size = 0;
    errno = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return dm_fail(w, DEMILL_ERR_IO, "%s: %s: %s", fn, path,
                       errno ? strerror(errno) : "cannot open");
    uint8_t *b = NULL;
    size_t n = 0, cap = 0;
    bool ok = true;
    for (;;) {
        if (n == cap) {
            cap = dm_grown_capacity(cap, cap + 65536);
            uint8_t *nb = realloc(b, cap);
            if (!nb) {
                free(b);
                fclose(f);
                return dm_fail(w, DEMILL_ERR_OUT_OF_MEMORY, "%s: %s: out of memory", fn, path);
            }
            b = nb;
        }
        const size_t got = fread(b + n, 1, cap - n, f);
        n += got;
        if (got == 0) {
            ok = !ferror(f);
            break;
        }
    }
    const int e = errno;
    fclose(f);
    if (!ok) {
        free(b);
        return dm_fail(w, DEMILL_ERR_IO, "%s: %s: %s", fn, path, e ? strerror(e) : "read failed");
    }
    *bytes = b;
    *size = n;
    return DEMILL_OK;
}
