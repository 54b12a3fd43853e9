/** @file demill/material.h
 * @brief Materials and the contact model of each material pair. */
#ifndef DEMILL_MATERIAL_H
#define DEMILL_MATERIAL_H

#include "world.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Material parameter keys (demill_material_set(), demill_material_get()). */
enum {
    /** Density ρ in kg/m³, > 0. Default 2500. Changing it recomputes the
     *  masses of the material's particles; a density that would make a mass
     *  or moment of inertia, or their inverse, not finite or 0 is refused. */
    DEMILL_MATERIAL_DENSITY = 200,
    /** Young's modulus E in Pa, in [1e-100, 1e30], used by Hertz and
     *  Mindlin laws (smaller moduli would make a pair's E* or k_a k_b
     *  underflow to 0). Default 1e8. */
    DEMILL_MATERIAL_YOUNGS_MODULUS = 201,
    /** Poisson ratio ν, in [0, 0.5). Default 0.3. */
    DEMILL_MATERIAL_POISSON_RATIO = 202,
    /** Spring stiffness k in N/m, in [1e-100, 1e30], used by linear laws; a
     *  pair's normal stiffness is the series value k_a k_b / (k_a + k_b).
     *  Default 1e5. */
    DEMILL_MATERIAL_STIFFNESS = 203,
    /** Coefficient of restitution e, in [0, 1]. Default 0.5. e = 0 with
     *  the unclamped normal law (DEMILL_PAIR_CLAMP_NORMAL = 0) is critical
     *  damping; with the clamp it would need infinite damping, which no time
     *  step integrates (demill_world_step() says so). */
    DEMILL_MATERIAL_RESTITUTION = 204,
    /** Sliding friction coefficient μ, >= 0. Default 0.5. */
    DEMILL_MATERIAL_FRICTION = 205,
    /** Rolling friction coefficient μ_r (dimensionless: the resisting torque
     *  is μ_r R* |F_n|), >= 0. Default 0. */
    DEMILL_MATERIAL_ROLLING_FRICTION = 206,
    /** Yield stress σ_y in Pa, in [0, 1e30], for the elasto-plastic normal
     *  laws (DEMILL_NORMAL_THORNTON, DEMILL_NORMAL_PLASTIC_PATHS): a pair's
     *  limiting contact pressure DEMILL_PAIR_YIELD_PRESSURE is derived from
     *  it. 0 (default): the material does not yield. */
    DEMILL_MATERIAL_YIELD_STRESS = 207,
    /** Local (non-viscous) damping coefficient α of the material's
     *  particles, in [0, 1) (Cundall 1987; docs/physics.md, Local damping):
     *  each component of a particle's force F and torque M is opposed by
     *  α |F_c| (α |M_c|) against the sign of its velocity component. For
     *  quasi-static packing and calibration runs; it damps free flight under
     *  gravity too. Velocity Verlet and symplectic Euler only: stepping a
     *  world with the iterative refinement fails while a particle's material
     *  has it. Default 0 (off). */
    DEMILL_MATERIAL_LOCAL_DAMPING = 210,
    /** 1: the material is rigid (infinite Young's modulus and stiffness);
     *  0 (default): deformable. A pair of a rigid and a deformable material
     *  takes its elastic constants from the deformable one alone:
     *  1/E* = (1 - ν²)/E and k_n = k of the deformable material, G* from
     *  its E and ν (the rigid one's E, ν and k are kept but not used). Its
     *  density still counts: particles of a rigid material have mass. Two
     *  rigid materials that may touch (particles of one and particles or a
     *  wall of the other, or of the same rigid material) have no finite
     *  stiffness: demill_world_step() and demill_world_suggest_time_step()
     *  refuse them with DEMILL_ERR_NO_CONTACT_MODEL. (Their pair's derived
     *  values, never used, are those of two deformable materials, so that
     *  demill_pair_get() reads finite numbers.) The Rayleigh-time bound of
     *  demill_world_suggest_time_step() applies to deformable particles
     *  only. */
    DEMILL_MATERIAL_RIGID = 212,
    /** Surface energy γ in J/m², in [0, 1e6], from which a pair's work of
     *  adhesion for JKR cohesion is derived (DEMILL_PAIR_ADHESION_WORK).
     *  Default 0. */
    DEMILL_MATERIAL_SURFACE_ENERGY = 213
};

/** Normal force laws, the values of DEMILL_PAIR_NORMAL. */
enum {
    /** No model: the pair may not touch (the default for every pair). */
    DEMILL_NORMAL_NONE = 0,
    /** Linear spring F = k_n δ (Cundall and Strack 1979; docs/physics.md §2). */
    DEMILL_NORMAL_LINEAR = 1,
    /** Hertz F = 4/3 E* √R* δ^{3/2} (Hertz 1882; docs/physics.md §2). */
    DEMILL_NORMAL_HERTZ = 2,
    /** Thornton's elastic-perfectly plastic spheres (Thornton 1997): Hertz
     *  up to the limiting contact pressure DEMILL_PAIR_YIELD_PRESSURE, linear
     *  beyond, unloading along Hertz's curve of an enlarged radius. With
     *  DEMILL_DAMPING_NONE or DEMILL_DAMPING_VISCOUS (docs/physics.md,
     *  Elasto-plastic normal laws). */
    DEMILL_NORMAL_THORNTON = 3,
    /** Walton and Braun's linear hysteresis (Walton and Braun 1986): loading
     *  with the pair's linear stiffness k1 (DEMILL_PAIR_NORMAL_STIFFNESS),
     *  unloading with k2 = k1/e², e the pair's DEMILL_PAIR_RESTITUTION. With
     *  DEMILL_DAMPING_NONE or DEMILL_DAMPING_VISCOUS. */
    DEMILL_NORMAL_WALTON_BRAUN = 4,
    /** The multi-path elasto-plastic law of Li, Gao, Zhang and Liu (2018):
     *  Hertz to the yield point, a fitted plastic force beyond
     *  (DEMILL_PAIR_PLASTIC_FIT_*), unloading along Hertz's curve through
     *  the residual overlap. With DEMILL_DAMPING_NONE or
     *  DEMILL_DAMPING_VISCOUS. */
    DEMILL_NORMAL_PLASTIC_PATHS = 5
};

/** Normal damping laws, the values of DEMILL_PAIR_DAMPING. */
enum {
    /** No damping (default). */
    DEMILL_DAMPING_NONE = 0,
    /** Constant viscous damping F_d = -c_n v_n, c_n from
     *  DEMILL_PAIR_VISCOUS_DAMPING. */
    DEMILL_DAMPING_VISCOUS = 1,
    /** Damping from the coefficient of restitution. Linear law: critical
     *  damping ratio ξ, c_n = 2 ξ √(m* k_n). Hertz: the nonlinear form of
     *  Tsuji, Tanaka and Ishida (1992), c_n = 2 √(5/6) ξ √(m* S_n),
     *  S_n = 2 E* √(R* δ). ξ is chosen so that
     *  an isolated binary collision rebounds with exactly the pair's
     *  restitution, with or without DEMILL_PAIR_CLAMP_NORMAL. Heavy damping
     *  (small e) lowers the stable time step (see
     *  demill_world_suggest_time_step()). */
    DEMILL_DAMPING_RESTITUTION = 2
};

/** Tangential laws, the values of DEMILL_PAIR_TANGENTIAL. */
enum {
    /** Frictionless (default). */
    DEMILL_TANGENTIAL_NONE = 0,
    /** Regularised dynamic Coulomb friction (Haff and Werner 1986):
     *  F_t = -min(μ |F_n|, γ_t |v_t|) v_t/|v_t|, γ_t from
     *  DEMILL_PAIR_COULOMB_REGULARISATION. No history. */
    DEMILL_TANGENTIAL_COULOMB = 1,
    /** Spring-slider with history, linear spring: k_t = ratio × k_n where k_n
     *  is the pair's linear stiffness (DEMILL_PAIR_NORMAL_STIFFNESS) and ratio
     *  is DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO. */
    DEMILL_TANGENTIAL_SPRING = 2,
    /** Spring-slider with history, Mindlin stiffness k_t = 8 G* √(R* δ)
     *  (Mindlin and Deresiewicz 1953; docs/physics.md §4). */
    DEMILL_TANGENTIAL_MINDLIN = 3
};

/** Rolling resistance laws, the values of DEMILL_PAIR_ROLLING. */
enum {
    /** No rolling resistance (default). */
    DEMILL_ROLLING_NONE = 0,
    /** Constant torque (model type A of Ai, Chen, Rotter and Ooi 2011;
     *  docs/physics.md §5): M_r = -min(μ_r R* |F_n|, γ_r |ω_rel|)
     *  ω_rel/|ω_rel| with ω_rel = ω_a - ω_b; γ_r from
     *  DEMILL_PAIR_ROLLING_REGULARISATION. */
    DEMILL_ROLLING_CONSTANT_TORQUE = 1,
    /** Elastic-plastic spring-dashpot (model type C of Ai, Chen, Rotter and
     *  Ooi 2011; docs/physics.md, Rolling spring-dashpot): a rolling spring
     *  k_r on the relative rolling rotation (ω_rel = ω_a - ω_b less its
     *  twist about the normal), its torque capped at μ_r R* |F_n|, and a
     *  dashpot c_r = η_r 2 √(I_r k_r) that is off while the spring slips at
     *  the cap. Unlike the constant torque it holds a ball still on a slope
     *  below its threshold (tan β < μ_r). k_r defaults to 2.25 k_n μ_r² R*²
     *  (DEMILL_PAIR_ROLLING_STIFFNESS), η_r to 0.3
     *  (DEMILL_PAIR_ROLLING_DAMPING_RATIO). Runs the generic kernel. */
    DEMILL_ROLLING_SPRING = 2
};

/** Cohesion laws, the values of DEMILL_PAIR_COHESION. */
enum {
    /** No cohesion (default): the pair interacts only while it overlaps. */
    DEMILL_COHESION_NONE = 0,
    /** JKR adhesion of elastic spheres (Johnson, Kendall and Roberts 1971;
     *  docs/physics.md, Cohesion), with the Hertz normal law only (stepping
     *  refuses it with another, DEMILL_ERR_INVALID_VALUE): the force F(a) =
     *  4E* a³/(3R*) − √(8π w E* a³) of the contact radius a(δ), w from
     *  DEMILL_PAIR_ADHESION_WORK; the contact forms at δ = 0 and breaks
     *  when pulled apart to δ_c = −(3/4)(π² w² R* / E*²)^{1/3}; the pull-off
     *  force is (3/2) π w R*. */
    DEMILL_COHESION_JKR = 1,
    /** A liquid bridge (Willett, Adams, Johnson and Seville 2000; Lian,
     *  Thornton and Adams 1993; docs/physics.md, Cohesion), with any normal
     *  law: an attraction of 4π R* γ cos θ while the pair overlaps, falling
     *  off with the gap s as 1/(1 + 2.1 S + 10 S²), S = (s/2)√(2R* / V); the
     *  bridge forms at contact and breaks at the gap (1 + θ/2) V^{1/3}. γ, θ
     *  and V from DEMILL_PAIR_SURFACE_TENSION, _CONTACT_ANGLE and
     *  _LIQUID_VOLUME. */
    DEMILL_COHESION_CAPILLARY = 2
};

/** Material pair parameter keys (demill_pair_set(), demill_pair_get()).
 *  The five law keys choose the contact model; the others tune it. Keys
 *  marked "derived" take their value from the two materials until set for
 *  the pair. */
enum {
    DEMILL_PAIR_NORMAL = 300,      /**< normal law, DEMILL_NORMAL_*; a pair with NONE may not touch */
    DEMILL_PAIR_DAMPING = 301,     /**< normal damping law, DEMILL_DAMPING_* */
    DEMILL_PAIR_TANGENTIAL = 302,  /**< tangential law, DEMILL_TANGENTIAL_* */
    DEMILL_PAIR_ROLLING = 303,     /**< rolling resistance law, DEMILL_ROLLING_* */
    DEMILL_PAIR_COHESION = 304,    /**< cohesion law, DEMILL_COHESION_* */
    /** Restitution in [0, 1]; derived: mean of the two materials'. */
    DEMILL_PAIR_RESTITUTION = 310,
    /** Sliding friction μ >= 0; derived: mean of the two materials'. */
    DEMILL_PAIR_FRICTION = 311,
    /** Rolling friction μ_r >= 0; derived: mean of the two materials'. */
    DEMILL_PAIR_ROLLING_FRICTION = 312,
    /** Linear normal stiffness k_n in N/m; derived: k_a k_b / (k_a + k_b). */
    DEMILL_PAIR_NORMAL_STIFFNESS = 313,
    /** Viscous damping coefficient c_n in N s/m for DEMILL_DAMPING_VISCOUS,
     *  >= 0. Default 0. */
    DEMILL_PAIR_VISCOUS_DAMPING = 314,
    /** k_t / k_n for DEMILL_TANGENTIAL_SPRING, > 0. Default 2/7. */
    DEMILL_PAIR_TANGENTIAL_STIFFNESS_RATIO = 315,
    /** Factor on the tangential dashpot of the spring-slider laws, >= 0.
     *  The dashpot c_t follows the normal damping law with k_t in place of
     *  the normal stiffness (viscous: c_t = factor × c_n). Default 1. */
    DEMILL_PAIR_TANGENTIAL_DAMPING_FACTOR = 316,
    /** Factor on the regularisation of DEMILL_TANGENTIAL_COULOMB, > 0:
     *  γ_t = factor × √(m* S_n), S_n the normal contact stiffness (k_n, or
     *  2 E* √(R* δ) for Hertz). The default 1 keeps the regularisation stable
     *  (explicitly integrated, against the tangential effective mass of a
     *  rolling sphere, 2/7 m*) down to about 6 steps per contact. */
    DEMILL_PAIR_COULOMB_REGULARISATION = 317,
    /** Factor on the regularisation of DEMILL_ROLLING_CONSTANT_TORQUE, > 0:
     *  γ_r = factor × R*² √(m* S_n). Default 1. */
    DEMILL_PAIR_ROLLING_REGULARISATION = 318,
    /** 1 (default): the normal force never pulls (F_n >= 0). 0: the damped
     *  normal force may become slightly attractive at the end of a contact,
     *  as in LIGGGHTS without limitForce. */
    DEMILL_PAIR_CLAMP_NORMAL = 319,
    /** Limiting contact pressure p_y in Pa, in [0, 1e30], of the
     *  elasto-plastic laws DEMILL_NORMAL_THORNTON and
     *  DEMILL_NORMAL_PLASTIC_PATHS: a Hertz contact yields where its peak
     *  pressure reaches p_y. 0: no yield (Hertz). Derived: 1.6 σ_y of the
     *  weaker material (DEMILL_MATERIAL_YIELD_STRESS; the onset of yield by
     *  the von Mises criterion, Johnson 1985), 0 if neither yields. */
    DEMILL_PAIR_YIELD_PRESSURE = 320,
    /** DEMILL_NORMAL_PLASTIC_PATHS: the plastic force past the elastic
     *  limit is f_y P(R*) ((a - a_y)/a_y)^H, P(R*) = c0 + c1 R* + c2 R*²
     *  (taken as 0 where negative), a = √(R* δ) the contact half-width and
     *  a_y, f_y the elastic limit's (docs/physics.md). c0, dimensionless;
     *  default 54.95, the aluminium fit of Li, Gao, Zhang and Liu (2018). */
    DEMILL_PAIR_PLASTIC_FIT_C0 = 321,
    /** c1 in 1/m (see DEMILL_PAIR_PLASTIC_FIT_C0); default -2889. */
    DEMILL_PAIR_PLASTIC_FIT_C1 = 322,
    /** c2 in 1/m² (see DEMILL_PAIR_PLASTIC_FIT_C0); default 88478. */
    DEMILL_PAIR_PLASTIC_FIT_C2 = 323,
    /** The exponent H of DEMILL_NORMAL_PLASTIC_PATHS's plastic force, in
     *  (0, 3). Default 1 (not given by Li et al. 2018: fit it with P). */
    DEMILL_PAIR_PLASTIC_FIT_EXPONENT = 324,
    /** Rolling stiffness k_r of DEMILL_ROLLING_SPRING in N m/rad, >= 0.
     *  Default 0: each contact's k_r = 2.25 k_n μ_r² R*² (Ai et al. 2011),
     *  k_n its normal stiffness (k_n, or 2 E* √(R* δ) for Hertz). */
    DEMILL_PAIR_ROLLING_STIFFNESS = 327,
    /** Damping ratio η_r of the rolling dashpot of DEMILL_ROLLING_SPRING,
     *  >= 0: c_r = η_r 2 √(I_r k_r), I_r the pair's moment of inertia about
     *  the contact, [1/(I_a + m_a r_a²) + 1/(I_b + m_b r_b²)]⁻¹ (a wall's
     *  term 0). Default 0.3; 0: no dashpot. */
    DEMILL_PAIR_ROLLING_DAMPING_RATIO = 328,
    /** Work of adhesion w in J/m² of JKR cohesion (DEMILL_COHESION_JKR), in
     *  [0, 1e6]: the pull-off force is (3/2) π w R*. Derived: 2 √(γ_a γ_b)
     *  from the materials' DEMILL_MATERIAL_SURFACE_ENERGY (2γ for two of
     *  the same material). */
    DEMILL_PAIR_ADHESION_WORK = 331,
    /** Liquid volume V in m³ of each bridge of DEMILL_COHESION_CAPILLARY, in
     *  (0, 1]. Default 1e-12 (a cube of 100 µm). */
    DEMILL_PAIR_LIQUID_VOLUME = 332,
    /** Surface tension γ in N/m of the bridges' liquid, in [0, 1e6].
     *  Default 0.072 (water at 25 °C). */
    DEMILL_PAIR_SURFACE_TENSION = 333,
    /** Contact angle θ in rad of the bridges' liquid on the solids, in
     *  [0, π/2]. Default 0 (wetting). */
    DEMILL_PAIR_CONTACT_ANGLE = 334
};

/** Creates a material with default parameters (see the DEMILL_MATERIAL_*
 *  keys).
 *  @param world    the world.
 *  @param[out] out receives the material's id.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER,
 *          DEMILL_ERR_INVALID_VALUE (too many materials: 256 at most) or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_material_create(demill_world *world, demill_id *out);

/** Sets a material parameter. Changing a material while particles of it
 *  exist recomputes their masses (density) and the contact constants.
 *  @param world    the world.
 *  @param material the material's id.
 *  @param key      a DEMILL_MATERIAL_* key.
 *  @param value    the new value, in the key's unit.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NOT_FINITE or DEMILL_ERR_INVALID_VALUE (also: the
 *          density of a material a clump template was made of,
 *          demill/clump.h). */
DEMILL_API demill_status demill_material_set(demill_world *world, demill_id material,
                                             int32_t key, double value);

/** Reads a material parameter.
 *  @param world      the world.
 *  @param material   the material's id.
 *  @param key        a DEMILL_MATERIAL_* key.
 *  @param[out] value receives the value.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_UNKNOWN_KEY. */
DEMILL_API demill_status demill_material_get(const demill_world *world, demill_id material,
                                             int32_t key, double *value);

/** Sets a parameter of the contact between materials a and b (a may equal
 *  b; the order does not matter). Setting a law key chooses that part of the
 *  model; setting a derived key overrides the value taken from the
 *  materials.
 *  @param world the world.
 *  @param a     one material's id.
 *  @param b     the other material's id (may equal a).
 *  @param key   a DEMILL_PAIR_* key.
 *  @param value the new value: a choice (DEMILL_NORMAL_*, DEMILL_DAMPING_*,
 *               DEMILL_TANGENTIAL_*, DEMILL_ROLLING_*, DEMILL_COHESION_*)
 *               for a law key, else a
 *               number in the key's unit.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_UNKNOWN_KEY,
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE or
 *          DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_pair_set(demill_world *world, demill_id a, demill_id b,
                                         int32_t key, double value);

/** Reads the effective value of a pair parameter (derived or set).
 *  @param world      the world.
 *  @param a          one material's id.
 *  @param b          the other material's id (may equal a).
 *  @param key        a DEMILL_PAIR_* key.
 *  @param[out] value receives the value.
 *  @return DEMILL_OK, DEMILL_ERR_INVALID_HANDLE, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_UNKNOWN_KEY. */
DEMILL_API demill_status demill_pair_get(const demill_world *world, demill_id a, demill_id b,
                                         int32_t key, double *value);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_MATERIAL_H */
