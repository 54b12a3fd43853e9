/** @file demill/query.h
 * @brief Contacts and the energy account of a world. */
#ifndef DEMILL_QUERY_H
#define DEMILL_QUERY_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Contact fields, read with demill_contacts_read(). Every contact has a
 *  first body a (always a particle) and a second body b (a particle or a
 *  wall); forces and torques are those b exerts on a. */
enum {
    DEMILL_CONTACT_POINT = 1,            /**< 3 doubles: contact point, m */
    DEMILL_CONTACT_NORMAL = 2,           /**< 3 doubles: unit normal from a towards b */
    DEMILL_CONTACT_OVERLAP = 3,          /**< 1 double: overlap δ > 0, m */
    DEMILL_CONTACT_NORMAL_FORCE = 4,     /**< 3 doubles: normal force on a (elastic + damping), N */
    DEMILL_CONTACT_TANGENTIAL_FORCE = 5, /**< 3 doubles: tangential (friction) force on a, N */
    DEMILL_CONTACT_ROLLING_TORQUE = 6    /**< 3 doubles: rolling-resistance torque on a, N m */
};

/** The size of a contact field.
 *  @param field a DEMILL_CONTACT_* field.
 *  @return the number of doubles per contact of the field (1 or 3), or 0 for
 *          an unknown field. */
DEMILL_API int32_t demill_contact_field_size(int32_t field);

/** Reads a field of every contact (overlap > 0) at the current state:
 *  particle-particle contacts first, then particle-wall contacts, in an
 *  order that stays the same between calls as long as the world is not
 *  stepped or changed. Forces are evaluated from the current positions,
 *  velocities and contact history without changing them. Stale neighbour
 *  lists are brought up to date first, as the next step would bring them
 *  (the particles' storage order may change, and with it the bytes of a
 *  checkpoint saved afterwards; what later steps compute does not).
 *  @param world       the world.
 *  @param field       a DEMILL_CONTACT_* field.
 *  @param[out] out    capacity × field size doubles, or NULL to ask the count.
 *  @param capacity    number of contacts out can hold.
 *  @param[out] count  receives the number of contacts (may be NULL if out is
 *                     not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NO_CONTACT_MODEL,
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_BUFFER_TOO_SMALL (nothing
 *          written, *count set). */
DEMILL_API demill_status demill_contacts_read(demill_world *world, int32_t field, double *out,
                                              size_t capacity, size_t *count);

/** Reads the ids of both bodies of every contact, in the order of
 *  demill_contacts_read().
 *  @param world      the world.
 *  @param[out] a     capacity ids of the first bodies (particles), or NULL
 *                    to skip them.
 *  @param[out] b     capacity ids of the second bodies (particles, walls or
 *                    the drum), or NULL to skip them.
 *  @param capacity   number of contacts a and b can hold.
 *  @param[out] count receives the number of contacts (may be NULL if a or b
 *                    is not).
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER (a,
 *          b and count all NULL), DEMILL_ERR_NO_CONTACT_MODEL,
 *          DEMILL_ERR_OUT_OF_MEMORY or DEMILL_ERR_BUFFER_TOO_SMALL (nothing
 *          written, *count set). */
DEMILL_API demill_status demill_contacts_read_ids(demill_world *world, demill_id *a,
                                                  demill_id *b, size_t capacity, size_t *count);

/** Energy terms, read with demill_world_energy(), all in J. The dissipated
 *  terms and the wall work are running totals since the world was created
 *  (tallied only while DEMILL_WORLD_ENERGY_TRACKING is on); the others
 *  describe the current state. */
enum {
    DEMILL_ENERGY_KINETIC_TRANSLATIONAL = 1, /**< Σ 1/2 m v² */
    DEMILL_ENERGY_KINETIC_ROTATIONAL = 2,    /**< Σ 1/2 I ω² */
    DEMILL_ENERGY_POTENTIAL = 3,             /**< gravitational, -Σ m g·x (zero at the origin) */
    DEMILL_ENERGY_ELASTIC_NORMAL = 4,        /**< stored in normal springs: k δ²/2 or 8/15 E* √R* δ^{5/2} */
    DEMILL_ENERGY_ELASTIC_TANGENTIAL = 5,    /**< stored in tangential springs: k_t |ξ|²/2 */
    /** Work done on the particles by moving walls: by their motion and by
     *  their surfaces' velocity (demill_wall_set_surface_velocity()). For a
     *  wall attached to a body, only its surface velocity's: the work of
     *  the body's own motion moves energy between the particles and the
     *  body, whose terms 14 to 18 hold it. */
    DEMILL_ENERGY_WALL_WORK = 6,
    DEMILL_ENERGY_DISSIPATED_NORMAL = 7,     /**< by normal damping (and by the normal-force clamp) */
    DEMILL_ENERGY_DISSIPATED_TANGENTIAL = 8, /**< by the tangential dashpot and the Coulomb regularisation below the cap */
    DEMILL_ENERGY_DISSIPATED_FRICTION = 9,   /**< by sliding friction (slip at the Coulomb cap) */
    DEMILL_ENERGY_DISSIPATED_ROLLING = 10,   /**< by rolling friction: the constant torque, or the rolling spring's slip */
    DEMILL_ENERGY_DISSIPATED = 11,           /**< every dissipation term summed: 7 to 10, 19 to 21 */
    /** Balance: kinetic + potential + elastic (4, 5, 23) + dissipated (11)
     *  + work against cohesion (22) - wall work - DEMILL_ENERGY_FLOW, with
     *  the bodies' terms: + 14 + 15 + 16 + 17 - 18. It stays constant up to integration error between changes made
     *  through the API (adding, removing or writing particles or bodies); an
     *  outlet also takes out the elastic energy of the contacts of the
     *  particles it removes, which it does not count. */
    DEMILL_ENERGY_TOTAL = 12,
    /** Brought in by feeds less taken out by outlets: the kinetic and
     *  potential energy of the particles they inserted and removed, at the
     *  moment they did (demill/insert.h). */
    DEMILL_ENERGY_FLOW = 13,
    DEMILL_ENERGY_BODY_KINETIC = 14,    /**< of the bodies (demill/body.h): Σ 1/2 m v² */
    DEMILL_ENERGY_BODY_ELASTIC = 15,    /**< stored in the bodies' springs: Σ 1/2 k (x - rest)² */
    DEMILL_ENERGY_BODY_POTENTIAL = 16,  /**< the bodies' gravitational energy, -Σ m g·x (bodies gravity acts on) */
    DEMILL_ENERGY_BODY_DISSIPATED = 17, /**< by the bodies' dampers */
    DEMILL_ENERGY_BODY_WORK = 18,       /**< done on the bodies by their external forces */
    DEMILL_ENERGY_DISSIPATED_PLASTIC = 19,         /**< by plastic deformation (the elasto-plastic normal laws) */
    DEMILL_ENERGY_DISSIPATED_ROLLING_VISCOUS = 20, /**< by the rolling dashpot */
    DEMILL_ENERGY_DISSIPATED_LOCAL = 21,           /**< by local (non-viscous) damping */
    /** Work done against the cohesive forces (adhesion, liquid bridges):
     *  positive while they are pulled apart, negative while they pull the
     *  particles together. */
    DEMILL_ENERGY_COHESION = 22,
    DEMILL_ENERGY_ELASTIC_ROLLING = 23             /**< stored in rolling springs */
};

/** Reads one energy term of the world. The terms that include the energy
 *  stored in the contacts (DEMILL_ENERGY_ELASTIC_NORMAL,
 *  DEMILL_ENERGY_ELASTIC_TANGENTIAL, DEMILL_ENERGY_ELASTIC_ROLLING,
 *  DEMILL_ENERGY_TOTAL) bring stale
 *  neighbour lists up to date first, as demill_contacts_read() does.
 *  @param world      the world.
 *  @param term       a DEMILL_ENERGY_* term.
 *  @param[out] value receives the energy, J.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NO_CONTACT_MODEL or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_world_energy(demill_world *world, int32_t term, double *value);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_QUERY_H */
