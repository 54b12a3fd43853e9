/** @file demill/state.h
 * @brief The whole state of a world kept aside and brought back: in-memory
 * snapshots, checkpoint files and buffers, and the ids of what a world holds
 * (to find materials, walls and the drum again after a load).
 *
 * A world's state is everything that decides how it goes on: parameters,
 * materials and pair models, particles, walls and the drum with their motion
 * and phase, the contact lists with their histories, the energy tallies, the
 * drum's measurements and collision spectrum, the integrator's state and the
 * step count. Restoring a state and stepping gives bitwise the same results
 * as stepping the world it was taken from. (The library keeps no random
 * state between calls: demill_drum_fill() draws from its own seed.)
 *
 * What belongs to the host rather than to the simulation is not part of it
 * and is kept by the world a state is restored into: the thread count
 * (DEMILL_WORLD_THREADS, which changes no result), the progress callback and
 * the last-error message. The world keeps its own identity too: ids issued
 * after a restore or load name objects of that world (with the same index and
 * generation as in the world the state came from); demill_world_ids() lists
 * them.
 */
#ifndef DEMILL_STATE_H
#define DEMILL_STATE_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------ */
/** @name Snapshots
 * A snapshot is a copy of a world's state in memory, for parameter sweeps
 * and for trying something and going back: settle a charge once, take a
 * snapshot, then restore it before each run of the sweep. It costs about
 * the memory of the world's particles and contacts.
 * @{ */

/** An opaque copy of a world's state. */
typedef struct demill_snapshot demill_snapshot;

/** Copies the world's state into a new snapshot.
 *  @param world the world (not changed).
 *  @param out   receives the snapshot, to be freed with demill_snapshot_free();
 *               set to NULL on failure.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (out) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_snapshot_take(demill_world *world, demill_snapshot **out);

/** Makes the world's state a copy of the snapshot's. The world may be the
 *  one the snapshot was taken from or another one; it takes the snapshot's
 *  dimension. The snapshot is not changed and can be restored again.
 *  @param world    the world to restore into.
 *  @param snapshot a snapshot from demill_snapshot_take().
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (snapshot),
 *          DEMILL_ERR_INVALID_HANDLE (snapshot is not a snapshot) or
 *          DEMILL_ERR_OUT_OF_MEMORY (the world is left as it was). */
DEMILL_API demill_status demill_snapshot_restore(demill_world *world,
                                                 const demill_snapshot *snapshot);

/** Frees a snapshot. NULL is ignored.
 *  @param snapshot the snapshot, or NULL. */
DEMILL_API void demill_snapshot_free(demill_snapshot *snapshot);
/** @} */

/* ------------------------------------------------------------------------ */
/** @name Checkpoints
 * A checkpoint is a world's state as bytes, in a file or a caller's buffer,
 * to continue a run in another process or on another day. The format is
 * versioned and carries a CRC-32 of its contents: a library reads the
 * checkpoints of its own and of every earlier format version. It stores
 * numbers in the byte order of the machine that wrote it and is read on
 * machines of the same byte order (all common ones are little-endian).
 * A load checks everything it reads (the checksum, every size, index and
 * parameter) before the world is touched: a truncated, corrupt or foreign
 * file gives DEMILL_ERR_FORMAT with a message saying what is wrong, and
 * leaves the world as it was.
 * @{ */

/** Writes the world's state to a checkpoint file. The file is written
 *  under a temporary name next to it and renamed into place when complete,
 *  so that an existing checkpoint is never left half overwritten.
 *  @param world the world (not changed).
 *  @param path  the file to write.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (path), DEMILL_ERR_IO (the
 *          message has the path and the system's reason),
 *          DEMILL_ERR_UNSTABLE (the state is not finite: a run diverged with
 *          the watchdog off; nothing is written) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_world_save(demill_world *world, const char *path);

/** Replaces the world's state with the one in a checkpoint file (see the
 *  group's description for what is kept). The world takes the checkpoint's
 *  dimension, so any world will do, e.g. a new one from
 *  demill_world_create(3, &w).
 *  @param world the world to load into.
 *  @param path  the checkpoint file.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (path), DEMILL_ERR_IO (the file
 *          cannot be opened or read), DEMILL_ERR_FORMAT (not a checkpoint,
 *          truncated, corrupt, of a newer format version, or holding a value
 *          the library never writes, such as a non-finite number) or
 *          DEMILL_ERR_OUT_OF_MEMORY. On failure the world is unchanged. */
DEMILL_API demill_status demill_world_load(demill_world *world, const char *path);

/** Writes the world's state as a checkpoint into a caller's buffer (the
 *  same bytes demill_world_save() writes to a file).
 *  @param world    the world (not changed).
 *  @param buffer   where to write, or NULL to ask the size only.
 *  @param capacity bytes the buffer holds.
 *  @param size     receives the checkpoint's size in bytes (may be NULL if
 *                  buffer is not).
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (buffer and size both NULL),
 *          DEMILL_ERR_BUFFER_TOO_SMALL (nothing written, *size set),
 *          DEMILL_ERR_UNSTABLE (the state is not finite, as for
 *          demill_world_save()) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_world_save_buffer(demill_world *world, void *buffer,
                                                  size_t capacity, size_t *size);

/** Replaces the world's state with the checkpoint in a buffer of `size`
 *  bytes (as demill_world_load() does from a file).
 *  @param world  the world to load into.
 *  @param buffer the checkpoint's bytes.
 *  @param size   their number.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (buffer), DEMILL_ERR_FORMAT
 *          (not a checkpoint, truncated, corrupt, or of a newer format
 *          version) or DEMILL_ERR_OUT_OF_MEMORY. On failure the world is
 *          unchanged. */
DEMILL_API demill_status demill_world_load_buffer(demill_world *world, const void *buffer,
                                                  size_t size);
/** @} */

/* ------------------------------------------------------------------------ */
/** @name Listing what a world holds
 * @{ */

/** Lists the ids of every object of a kind the world holds:
 *  DEMILL_KIND_MATERIAL (in the order they were created),
 *  DEMILL_KIND_PARTICLE (in id order, as demill_particles_read_ids()),
 *  DEMILL_KIND_WALL (the walls added with demill_wall_add_plane(), in the
 *  order of their slots: a new wall may take the slot of a removed one; the
 *  drum's own surfaces are not walls), DEMILL_KIND_DRUM (none or one),
 *  DEMILL_KIND_FEED and DEMILL_KIND_OUTLET (in the order of their slots,
 *  as walls), DEMILL_KIND_BODY (in the order of their slots, as walls),
 *  DEMILL_KIND_TEMPLATE (in the order they were made) or DEMILL_KIND_CLUMP
 *  (in the order of their slots: a new clump may take the slot of a
 *  removed one).
 *  @param world    the world.
 *  @param kind     a DEMILL_KIND_* constant.
 *  @param out      capacity ids, or NULL to ask the count.
 *  @param capacity ids out can hold.
 *  @param count    receives the number of objects (may be NULL if out is
 *                  not).
 *  @return DEMILL_OK, DEMILL_ERR_UNKNOWN_KEY (kind), DEMILL_ERR_NULL_POINTER
 *          (out and count both NULL) or DEMILL_ERR_BUFFER_TOO_SMALL (nothing
 *          written, *count set). */
DEMILL_API demill_status demill_world_ids(const demill_world *world, int32_t kind,
                                          demill_id *out, size_t capacity, size_t *count);
/** @} */

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_STATE_H */
