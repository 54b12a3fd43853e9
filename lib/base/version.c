/* version.c: run-time version of the library. */
#include "base/base.h"

DEMILL_API uint32_t demill_version_number(void)
{
    return DEMILL_VERSION_NUMBER;
}

DEMILL_API const char *demill_version_string(void)
{
    return DEMILL_VERSION_STRING;
}

DEMILL_API demill_status demill_check_version(uint32_t header_version)
{
    /* A release only adds to the API of its major version, so the library
     * serves headers of the same major version that are not newer than it. */
    if (header_version / 10000 != DEMILL_VERSION_MAJOR || header_version > DEMILL_VERSION_NUMBER)
        return DEMILL_ERR_VERSION;
    return DEMILL_OK;
}
