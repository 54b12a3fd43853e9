/** @file demill/common.h
 * @brief Export macro, ids, status codes, version and parameter keys.
 *
 * This header is part of the stable libdemill API; include <demill.h> rather
 * than this file directly. All functions are C99-callable, take and return
 * only fixed-width integers, doubles, pointers and opaque handles, and are
 * usable unchanged from C++ and through FFI (for example Python ctypes).
 *
 * Thread safety: a world and everything it owns may be used by one thread at a
 * time. Separate worlds share no state and may be used from separate threads
 * concurrently. Functions that take no world (version, strings, parameter
 * metadata) are safe to call from any thread at any time.
 */
#ifndef DEMILL_COMMON_H
#define DEMILL_COMMON_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32) && !defined(DEMILL_STATIC)
#  if defined(DEMILL_BUILDING)
#    define DEMILL_API __declspec(dllexport)
#  else
#    define DEMILL_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) || defined(__clang__)
#  define DEMILL_API __attribute__((visibility("default")))
#else
#  define DEMILL_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------ */
/** @name Version
 * The version of the headers a program was compiled with is given by the
 * macros; the version of the library it runs with by the functions. Within
 * the 0.x series a minor version may add to the API but never changes or
 * removes anything; the shared library's SONAME is libdemill.so.0.
 * @{ */
/** Major version of the headers: 0 for the 0.x series. */
#define DEMILL_VERSION_MAJOR 0
/** Minor version of the headers: grows when the API is extended. */
#define DEMILL_VERSION_MINOR 1
/** Patch version of the headers: fixes that change no interface. */
#define DEMILL_VERSION_PATCH 0
/** MAJOR * 10000 + MINOR * 100 + PATCH, e.g. 100 for 0.1.0. */
#define DEMILL_VERSION_NUMBER \
    (DEMILL_VERSION_MAJOR * 10000 + DEMILL_VERSION_MINOR * 100 + DEMILL_VERSION_PATCH)
/** The version of the headers as "MAJOR.MINOR.PATCH". */
#define DEMILL_VERSION_STRING "0.1.0"

/** The version number of the library at run time.
 *  @return MAJOR * 10000 + MINOR * 100 + PATCH of the running library (the
 *          encoding of DEMILL_VERSION_NUMBER). */
DEMILL_API uint32_t demill_version_number(void);

/** The version of the library at run time.
 *  @return "MAJOR.MINOR.PATCH" of the running library; a static string,
 *          never NULL. */
DEMILL_API const char *demill_version_string(void);

/** Checks that the running library can serve a program compiled against
 *  headers of version `header_version`.
 *  @param header_version the version the program was compiled with: pass
 *                        DEMILL_VERSION_NUMBER.
 *  @return DEMILL_OK if the major versions match and the library is at least
 *          as new as the headers; DEMILL_ERR_VERSION otherwise. */
DEMILL_API int32_t demill_check_version(uint32_t header_version);
/** @} */

/* ------------------------------------------------------------------------ */
/** @name Status codes
 * Every fallible function returns one of these. Codes never change meaning
 * and are never renumbered. A function that fails leaves the world exactly as
 * it was before the call (the one exception, documented at
 * demill_world_step(), is a failure in the middle of a multi-step run). The
 * world's last-error message (demill_world_last_error()) says what was wrong.
 * Every function that takes a world returns DEMILL_ERR_NULL_POINTER when it
 * is NULL and DEMILL_ERR_INVALID_HANDLE when it is not a live world; the
 * lists of errors at each function do not repeat these two.
 * A parameter value for a choice (an enum) that is not a whole number gives
 * DEMILL_ERR_INVALID_VALUE; a whole number that names no choice gives
 * DEMILL_ERR_UNKNOWN_KEY.
 * @{ */
/** A status code: DEMILL_OK or one of the DEMILL_ERR_* codes. */
typedef int32_t demill_status;
/** The status codes, the values of demill_status. */
enum {
    DEMILL_OK = 0,                   /**< success */
    DEMILL_ERR_NULL_POINTER = 1,     /**< a required pointer argument is NULL */
    DEMILL_ERR_INVALID_VALUE = 2,    /**< a value is out of its allowed range */
    DEMILL_ERR_NOT_FINITE = 3,       /**< a value is NaN or infinite */
    DEMILL_ERR_UNKNOWN_KEY = 4,      /**< unknown parameter key, field or enum value */
    DEMILL_ERR_INVALID_HANDLE = 5,   /**< id removed, of another world or of the wrong kind; or not a world */
    DEMILL_ERR_NO_CONTACT_MODEL = 6, /**< two materials that may touch have no contact model */
    DEMILL_ERR_OVERLAP = 7,          /**< inserted particles overlap and the caller asked for none */
    DEMILL_ERR_OUT_OF_MEMORY = 8,    /**< an allocation failed */
    DEMILL_ERR_BUFFER_TOO_SMALL = 9, /**< the caller's buffer holds fewer items than needed */
    DEMILL_ERR_READ_ONLY = 10,       /**< the parameter or field can be read but not written */
    DEMILL_ERR_DIMENSION = 11,       /**< the value is not allowed in a world of this dimension */
    DEMILL_ERR_VERSION = 12,         /**< the library is not compatible with the headers */
    DEMILL_ERR_UNSUPPORTED = 13,     /**< the library was built without what this needs */
    DEMILL_ERR_UNSTABLE = 14,        /**< the simulation went unstable (see DEMILL_WORLD_WATCHDOG) */
    DEMILL_ERR_IO = 15,              /**< a file could not be opened, read or written (the message has the system's reason) */
    DEMILL_ERR_FORMAT = 16,          /**< a file or buffer is not what it should be: foreign, truncated, corrupt or of an unsupported version */
    DEMILL_ERR_INTERRUPTED = 17,     /**< the progress callback asked the run to stop (see demill_world_set_progress()) */
    DEMILL_ERR_LIMIT = 18            /**< a fixed limit of the library was reached (4096 live worlds, 65535 drums made in one world) */
};

/** A generic description of a status code.
 *  @param code a status code returned by any function.
 *  @return a static string such as "invalid value", never NULL; a code that
 *          is not a status code gives "unknown status code". For what went
 *          wrong in a particular call, read demill_world_last_error(). */
DEMILL_API const char *demill_strerror(demill_status code);
/** @} */

/* ------------------------------------------------------------------------ */
/** @name Ids
 * Materials, particles, walls, drums, bodies, clump templates and clumps
 * are named by 64-bit ids.
 * An id encodes the
 * kind of object, the world it belongs to and a generation counter, so an id
 * of a removed object, of another world or of the wrong kind is rejected with
 * DEMILL_ERR_INVALID_HANDLE instead of touching the wrong object.
 * DEMILL_ID_NONE (0) is never a valid id.
 *
 * What exactly is guaranteed: an id never names any object but its own in
 * its own world, however many objects are added and removed (a handle whose
 * generation counter would wrap round is retired, never reused); no two
 * worlds alive at the same time accept each other's ids (at most 4096 worlds
 * are alive at once: demill_world_create() returns DEMILL_ERR_LIMIT beyond).
 * An id of a destroyed world may name an object of a world created after
 * 4096 or more further worlds; do not keep ids past their world.
 * @{ */
/** The id of a material, particle, wall, drum, body, clump template or
 *  clump of a world. */
typedef uint64_t demill_id;
/** The id that names nothing. */
#define DEMILL_ID_NONE ((demill_id)0)

/** The kind of object an id names (see demill_id_kind()). */
enum {
    DEMILL_KIND_NONE = 0,     /**< not an id of any kind (e.g. DEMILL_ID_NONE) */
    DEMILL_KIND_MATERIAL = 1, /**< a material (demill_material_create()) */
    DEMILL_KIND_PARTICLE = 2, /**< a particle (demill_particles_add()) */
    DEMILL_KIND_WALL = 3,     /**< a wall (demill_wall_add_plane()) */
    DEMILL_KIND_DRUM = 4,     /**< a drum (demill_drum_create()) */
    DEMILL_KIND_FEED = 5,     /**< a feed (demill_feed_create()) */
    DEMILL_KIND_OUTLET = 6,   /**< an outlet (demill_outlet_create()) */
    DEMILL_KIND_BODY = 7,     /**< a body (demill_body_add()) */
    DEMILL_KIND_TEMPLATE = 8, /**< a clump template (demill_clump_template_add()) */
    DEMILL_KIND_CLUMP = 9     /**< a clump (demill_clump_add()) */
};

/** The kind of object an id names, without checking that the object still
 *  exists.
 *  @param id any id.
 *  @return the kind encoded in the id, DEMILL_KIND_*; DEMILL_KIND_NONE for an
 *          id that encodes no kind. */
DEMILL_API int32_t demill_id_kind(demill_id id);
/** @} */

/* ------------------------------------------------------------------------ */
/** @name Parameters
 * Worlds, materials and material pairs are configured through numeric keys
 * with one value type, double. Keys whose value is a choice (an enum) or a
 * switch take whole numbers. Keys are grouped: 1xx world, 2xx material,
 * 3xx material pair. New keys are added over time; existing ones never change
 * meaning. The functions below describe a key without needing a world.
 * @{ */

/** The name of a parameter key.
 *  @param key a parameter key (DEMILL_WORLD_*, DEMILL_MATERIAL_*,
 *             DEMILL_PAIR_*, DEMILL_DRUM_*).
 *  @return the key's name, e.g. "world.time_step" (a static string), or NULL
 *          for an unknown key. */
DEMILL_API const char *demill_param_name(int32_t key);

/** The unit of a parameter key's value.
 *  @param key a parameter key.
 *  @return the unit in SI, e.g. "s", "Pa", "1" (dimensionless), "enum" or
 *          "bool" (a static string), or NULL for an unknown key. */
DEMILL_API const char *demill_param_unit(int32_t key);

/** The allowed range [*lo, *hi] of a key and its default (for keys whose
 *  default is derived from materials, the value used for an identical pair of
 *  default materials).
 *  Open bounds are reported as the nearest representable value inside them.
 *  @param key                a parameter key.
 *  @param[out] lo            receives the lower bound; may be NULL.
 *  @param[out] hi            receives the upper bound; may be NULL.
 *  @param[out] default_value receives the default; may be NULL.
 *  @return DEMILL_OK or DEMILL_ERR_UNKNOWN_KEY. */
DEMILL_API demill_status demill_param_bounds(int32_t key, double *lo, double *hi,
                                             double *default_value);
/** @} */

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_COMMON_H */
