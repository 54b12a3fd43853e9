/** @file demill/grinding.h
 * @brief Ore breakage models and the batch-grinding population balance.
 *
 * A grinding object (demill_grinding) holds a size distribution over size
 * classes in a √2 series, the specific breakage rates S_i and the breakage
 * (appearance) function b_ij of those classes, and optionally an ore
 * breakage model from which b_ij follows. It integrates Austin's
 * size-discrete batch grinding equation (Austin, Klimpel and Luckie 1984,
 * Process Engineering of Size Reduction: Ball Milling)
 *
 *     dw_i/dt = -S_i w_i + sum_{j<i} b_ij S_j w_j
 *
 * in time, and reports the product size distribution, the fraction passing
 * a size, P80 and the specific energy. It needs no world: the rates may be
 * typed in from a laboratory test, or derived from an impact spectrum
 * (demill_grinding_rates_from_impacts()), such as a drum records. docs/grinding.md explains the models and equations.
 *
 * Size classes: class 0 is the coarsest. Class i (i < n - 1) holds sizes in
 * (top/√2^(i+1), top/√2^i]; the last class, n - 1, holds everything finer
 * than top/√2^(n-1) and never breaks (its rate is 0). Sizes are in m,
 * times in s, rates in 1/s, specific energies of impact in J/kg
 * (1 kWh/t = 3600 J/kg) and percentages (A, t10, the t-family) in %.
 *
 * Errors: every function that takes a grinding object returns
 * DEMILL_ERR_NULL_POINTER when it is NULL and DEMILL_ERR_INVALID_HANDLE when
 * it is not a live grinding object (destroyed, or a world); the lists at
 * each function do not repeat these two. A function that fails leaves the
 * object as it was and writes a message that demill_grinding_last_error()
 * returns.
 */
#ifndef DEMILL_GRINDING_H
#define DEMILL_GRINDING_H

#include "common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** An opaque grinding object: size classes, a size distribution, rates, an
 *  appearance function and an ore breakage model. */
typedef struct demill_grinding demill_grinding;

/** Creates a grinding object with `classes` size classes in a √2 series
 *  below `top_size`. Its distribution, rates and appearance function are
 *  all zero and it has no breakage model until they are set.
 *  @param top_size the upper limit of the coarsest class, m, > 0.
 *  @param classes  the number of classes, 2 to 200 (the last one is the
 *                  sink of everything finer).
 *  @param[out] out receives the object.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (out is NULL),
 *          DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (top_size <= 0,
 *          or classes out of range) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_grinding_create(double top_size, uint32_t classes,
                                                demill_grinding **out);

/** Destroys a grinding object. NULL, or an object already destroyed, is
 *  ignored.
 *  @param grinding the object. */
DEMILL_API void demill_grinding_destroy(demill_grinding *grinding);

/** The message of the last failed call on a grinding object.
 *  @param grinding the object.
 *  @return a string owned by the object, "" after a call that succeeded;
 *          a fixed text when grinding is NULL or not a live object. */
DEMILL_API const char *demill_grinding_last_error(const demill_grinding *grinding);

/** The limits of the size classes: n + 1 sizes for n classes, from the top
 *  size down, limits[i] = top/√2^i for i < n, and limits[n] = 0 (the lower
 *  limit of the sink).
 *  @param grinding    the object.
 *  @param[out] limits capacity doubles, m, or NULL to ask the count.
 *  @param capacity    the number of doubles `limits` can hold.
 *  @param[out] count  receives n + 1; may be NULL if limits is not.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (both limits and count NULL)
 *          or DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_grinding_sizes(const demill_grinding *grinding, double *limits,
                                               size_t capacity, size_t *count);

/** Sets the feed: the mass in each class. The product becomes the feed and
 *  the grinding time 0.
 *  @param grinding the object.
 *  @param n        the number of values: the number of classes.
 *  @param mass     n masses, any unit (kg for demill_grinding_specific_energy()),
 *                  each >= 0, with a sum > 0.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (n is not the number of classes, a
 *          negative mass, or a sum that is not > 0). */
DEMILL_API demill_status demill_grinding_set_feed(demill_grinding *grinding, size_t n,
                                                  const double *mass);

/** Sets the specific breakage rates S_i of the classes.
 *  @param grinding the object.
 *  @param n        the number of values: the number of classes.
 *  @param rates    n rates, 1/s, each >= 0; the last (the sink's) 0.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (n is not the number of classes, a
 *          negative rate, or a sink rate that is not 0). */
DEMILL_API demill_status demill_grinding_set_rates(demill_grinding *grinding, size_t n,
                                                   const double *rates);

/** Reads the specific breakage rates S_i.
 *  @param grinding   the object.
 *  @param[out] rates capacity doubles, 1/s, or NULL to ask the count.
 *  @param capacity   the number of doubles `rates` can hold.
 *  @param[out] count receives the number of classes; may be NULL if rates
 *                    is not.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_grinding_rates(const demill_grinding *grinding, double *rates,
                                               size_t capacity, size_t *count);

/** Sets the breakage (appearance) function: b[i * n + j] is the fraction of
 *  the mass broken out of class j that lands in class i. Broken mass leaves
 *  its class: b_ij = 0 for i <= j, and for every class j but the sink
 *  sum_{i>j} b_ij = 1 within 1e-9; the sink's column is all 0.
 *  @param grinding the object.
 *  @param n        the number of values: the number of classes squared.
 *  @param b        n values, row i, column j at b[i * classes + j], each in
 *                  [0, 1].
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (n is not classes², a value outside
 *          [0, 1], a value on or above the diagonal or in the sink's column
 *          that is not 0, or a column that does not sum to 1). */
DEMILL_API demill_status demill_grinding_set_appearance(demill_grinding *grinding, size_t n,
                                                        const double *b);

/** Reads the breakage (appearance) function, laid out as for
 *  demill_grinding_set_appearance().
 *  @param grinding   the object.
 *  @param[out] b     capacity doubles, or NULL to ask the count.
 *  @param capacity   the number of doubles `b` can hold.
 *  @param[out] count receives the number of classes squared; may be NULL if
 *                    b is not.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_grinding_appearance(const demill_grinding *grinding, double *b,
                                                    size_t capacity, size_t *count);

/** Sets the ore's breakage model to the JKMRC drop-weight model (Napier-Munn,
 *  Morrell, Morrison and Kojovic 1996, Mineral Comminution Circuits):
 *  t10 = A (1 - exp(-b E_cs)), E_cs the specific comminution energy in
 *  kWh/t (the specific impact energy in J/kg divided by 3600), with the
 *  fragments' size distribution from the t-family table. Replaces any model
 *  set before.
 *  @param grinding the object.
 *  @param a        A, the largest t10, %, in [0, 100].
 *  @param b        b, t/kWh, >= 0.
 *  @param rows     the number of rows of the t-family table, 2 to 100.
 *  @param table    rows × 6 values, %: each row t10, t2, t4, t25, t50, t75
 *                  (the percentages passing 1/10, 1/2, 1/4, 1/25, 1/50 and
 *                  1/75 of the parent size), t10 increasing from row to row
 *                  and every value in (0, 100], and in each row
 *                  t2 >= t4 >= t10 >= t25 >= t50 >= t75.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (table), DEMILL_ERR_NOT_FINITE
 *          or DEMILL_ERR_INVALID_VALUE (A or b out of range, or a table that
 *          breaks a rule above). */
DEMILL_API demill_status demill_grinding_set_jk(demill_grinding *grinding, double a, double b,
                                                size_t rows, const double *table);

/** Sets the ore's breakage model to the mechanistic model of Tavares and
 *  King (1998, Single-particle fracture under impact loading): the mass-specific
 *  fracture energies of particles of size d follow an upper-truncated
 *  lognormal distribution of median E50(d) = e_inf (1 + (d0/d)^phi), spread
 *  sigma and upper limit emax_ratio × E50(d); the weakening of particles that
 *  survive an impact follows Tavares and King (2002, Modeling of particle
 *  fracture by repeated impacts using continuum damage mechanics) with the
 *  damage exponent gamma; the fragments of a particle broken by an impact of
 *  specific energy E have t10 = a_prime (1 - exp(-b_prime E/E50(d))) and the
 *  size distribution of the t-family table (as for demill_grinding_set_jk()).
 *  Replaces any model set before.
 *  @param grinding   the object.
 *  @param e_inf      E∞, the median fracture energy of large particles, J/kg, > 0.
 *  @param d0         d0, the size below which particles get tougher, m, > 0.
 *  @param phi        φ, the exponent of that toughening, > 0.
 *  @param sigma      σ, the spread of ln E, > 0.
 *  @param emax_ratio Emax/E50, the upper truncation, > 1; 0 for none.
 *  @param gamma      γ, the damage exponent, > 0.
 *  @param a_prime    A', the largest t10, %, in [0, 100].
 *  @param b_prime    b', >= 0 (dimensionless).
 *  @param rows       the number of rows of the t-family table, 2 to 100.
 *  @param table      rows × 6 values, as for demill_grinding_set_jk().
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER (table), DEMILL_ERR_NOT_FINITE
 *          or DEMILL_ERR_INVALID_VALUE (a parameter out of range, or a table
 *          that breaks a rule of demill_grinding_set_jk()). */
DEMILL_API demill_status demill_grinding_set_tavares(demill_grinding *grinding, double e_inf,
                                                     double d0, double phi, double sigma,
                                                     double emax_ratio, double gamma,
                                                     double a_prime, double b_prime, size_t rows,
                                                     const double *table);

/** The t10 the ore's breakage model gives a particle of size `size` broken
 *  by an impact of specific energy `energy`.
 *  @param grinding the object.
 *  @param size     the particle's size, m, > 0 (the JKMRC model does not
 *                  use it).
 *  @param energy   the specific impact energy, J/kg, >= 0.
 *  @param[out] t10 receives t10, %.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (no model set, size <= 0 or energy < 0). */
DEMILL_API demill_status demill_grinding_t10(const demill_grinding *grinding, double size,
                                             double energy, double *t10);

/** The t-family of the model's table at a given t10: t2, t4, t25, t50 and
 *  t75, each interpolated against t10 by monotone piecewise cubic
 *  interpolation (Fritsch and Carlson 1980) through the table's rows.
 *  @param grinding the object.
 *  @param t10      t10, %, within the table's first and last rows.
 *  @param[out] tn  receives 5 values, %: t2, t4, t25, t50, t75.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (no model set, or t10 outside the
 *          table). */
DEMILL_API demill_status demill_grinding_tn(const demill_grinding *grinding, double t10,
                                            double *tn);

/** The fraction of particles of size `size` that break within `impacts`
 *  impacts of specific energy `energy` each, by the Tavares and King model
 *  with damage (the particles that survive an impact are weakened by it).
 *  @param grinding      the object.
 *  @param size          the particles' size, m, > 0.
 *  @param energy        the specific energy of each impact, J/kg, >= 0.
 *  @param impacts       the number of impacts, >= 1.
 *  @param[out] fraction receives the fraction broken, 0 to 1.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (the model is not Tavares and King's,
 *          size <= 0, energy < 0 or no impact). */
DEMILL_API demill_status demill_grinding_broken_fraction(const demill_grinding *grinding,
                                                         double size, double energy,
                                                         uint32_t impacts, double *fraction);

/** Sets the appearance function from the ore's breakage model for impacts
 *  of one specific energy: for each class but the sink, the fragments of a
 *  parent of the class's geometric mean size, by the model's t10 at that
 *  energy and the t-family (docs/grinding.md says how the cumulative
 *  passing curve is interpolated between the t-values and renormalised to
 *  the mass that leaves the class).
 *  @param grinding the object.
 *  @param energy   the specific impact energy, J/kg, > 0.
 *  @return DEMILL_OK, DEMILL_ERR_NOT_FINITE or DEMILL_ERR_INVALID_VALUE (no
 *          model set, energy <= 0, or a class whose t10 is outside the
 *          model's table). */
DEMILL_API demill_status demill_grinding_set_appearance_energy(demill_grinding *grinding,
                                                               double energy);

/** Sets the specific breakage rates S_i and the appearance function b_ij
 *  from the impacts the particles of each class received in a time (an
 *  impact spectrum), by the Tavares and King model with damage:
 *
 *      S_i = sum_k lambda_ik F_i(E_k, K) / M_i(E_k, K),
 *      lambda_ik = counts[i][k] / (N_i T)
 *
 *  lambda_ik the impacts per particle and second in energy bin k, E_k the
 *  bin's midpoint (edges[k] + edges[k+1]) / 2, K = lambda_ik t_d (rounded,
 *  at least 1) the impacts of the bin a particle receives in the damage
 *  time t_d (demill_grinding_set_damage_time(), 0 unless set: K = 1),
 *  F_i(E, K) the fraction of particles of the class's geometric mean size
 *  broken within K impacts of specific energy E, the survivors of each
 *  weakened by it (as demill_grinding_broken_fraction() gives it: Tavares
 *  and King 1998, Single-particle fracture under impact loading; Tavares and
 *  King 2002, Modeling of particle fracture by repeated impacts using
 *  continuum damage mechanics), and M_i(E, K) = sum_{m<K} (1 - F_i(E, m))
 *  the mean number of those impacts a particle survives to receive: the
 *  bin breaks F of the particles over M / lambda_ik seconds of impacts.
 *  With K = 1 this is lambda_ik times the probability that one impact
 *  breaks a fresh particle; with a K that breaks nearly all, lambda_ik over
 *  the mean number of impacts to fracture. Each bin's impacts are a
 *  sequence of their own: the damage done by impacts of other energies is
 *  not counted. Column j of b is the mean of the appearance columns at the
 *  t10 of each bin's energy (as demill_grinding_set_appearance_energy()
 *  makes them), weighted by each bin's part of S_j; a class that does not
 *  break (S_j = 0) gets a column of zeros, as the sink. The sink's counts
 *  are not used. The JKMRC model gives a fragment size distribution for a
 *  breakage event but no probability that an impact breaks a particle
 *  (Napier-Munn et al. 1996 measure t10 on particles that all broke), so it
 *  is refused here: set Tavares and King's model.
 *  @param grinding  the object.
 *  @param classes   the number of classes (the object's).
 *  @param bins      the number of energy bins, 1 to 10000.
 *  @param edges     bins + 1 increasing bin edges, J/kg, the first >= 0.
 *  @param counts    classes × bins impact counts, counts[i * bins + k] for
 *                   class i and bin k, each >= 0.
 *  @param particles classes numbers of particles N_i, each >= 0, > 0 for a
 *                   class (but the sink) with impacts.
 *  @param time      the time T over which the impacts were counted, s, > 0.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE,
 *          DEMILL_ERR_INVALID_VALUE (a count that does not match, edges not
 *          increasing, a negative count or particle number, impacts on a
 *          class without particles, time <= 0, no model set, the JKMRC
 *          model, a breaking bin whose t10 is outside the model's
 *          t-family table, or a bin with more than 1e6 impacts per particle
 *          in the damage time) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_grinding_rates_from_impacts(demill_grinding *grinding,
                                                            size_t classes, size_t bins,
                                                            const double *edges,
                                                            const double *counts,
                                                            const double *particles, double time);

/** Sets the damage time t_d of demill_grinding_rates_from_impacts(): the
 *  rate of each energy bin is that at which the sequence of impacts of its
 *  energy that a particle receives in t_d, K = lambda_ik t_d of them
 *  (rounded, at least 1), breaks particles that the impacts weaken
 *  (Tavares and King 2002): the fraction broken within the K impacts over
 *  the time of the impacts survived. 0 (the default) makes every K 1: the
 *  rate of single impacts on fresh particles, the hazard of a fresh charge.
 *  The grinding time counts the damage of the impacts before and the
 *  strength of the particles that survive them over the grind. The cost of
 *  the rates grows with K (one root of the damage equation per impact and
 *  bin).
 *  @param grinding the object.
 *  @param time     t_d, s, >= 0.
 *  @return DEMILL_OK, DEMILL_ERR_NOT_FINITE or DEMILL_ERR_INVALID_VALUE
 *          (time < 0). */
DEMILL_API demill_status demill_grinding_set_damage_time(demill_grinding *grinding, double time);

/** Reads the damage time t_d of the rates.
 *  @param grinding  the object.
 *  @param[out] time receives t_d, s.
 *  @return DEMILL_OK or DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_grinding_damage_time(const demill_grinding *grinding,
                                                     double *time);

/** Extends the rates to the classes finer than the finest class with a
 *  rate, by Austin's size dependence of the specific rate of breakage
 *  (Austin, Klimpel and Luckie 1984, Process Engineering of Size Reduction:
 *  Ball Milling):
 *
 *      S(x) = A (x/x0)^alpha / (1 + (x/mu)^Lambda),   x0 = 1 mm,
 *
 *  x a class's upper limit. A (and alpha, if fit_alpha) is fitted by least
 *  squares to the logarithms of the rates of the classes that have one
 *  (S_i > 0, such as demill_grinding_rates_from_impacts() gives the classes
 *  the DEM charge holds); every class between the finest of them and the
 *  sink gets the law's rate, and as appearance the finest one's column
 *  shifted down by as many classes (a normalisable breakage function,
 *  Austin et al. 1984), what would fall past the sink added to the sink.
 *  The classes with a rate, and coarser ones, are left as they are.
 *  @param grinding   the object.
 *  @param fit_alpha  nonzero: fit alpha as well (two classes with a rate at
 *                    least); 0: use `alpha`.
 *  @param alpha      alpha, the exponent below the maximum, when not fitted.
 *  @param mu         mu, the size of the rates' maximum, m, > 0; 0 for none
 *                    (a power law: S = A (x/x0)^alpha).
 *  @param big_lambda Lambda, > 0, how fast the rates fall above mu (not
 *                    used when mu is 0).
 *  @param[out] fitted receives 2 values: A, 1/s, and alpha; may be NULL.
 *  @return DEMILL_OK, DEMILL_ERR_NOT_FINITE, DEMILL_ERR_INVALID_VALUE (mu
 *          < 0, Lambda <= 0 with a mu, no class with a rate, or one only
 *          when alpha is fitted, or an appearance column of the finest class
 *          with a rate that does not sum to 1) or DEMILL_ERR_OUT_OF_MEMORY. */
DEMILL_API demill_status demill_grinding_extend_rates(demill_grinding *grinding, int32_t fit_alpha,
                                                      double alpha, double mu, double big_lambda,
                                                      double *fitted);

/** Grinds for a time: integrates the batch grinding equation with the
 *  current rates and appearance function from the current product, exactly
 *  for rates that are constant over the call (the matrix exponential of its
 *  lower triangular system, docs/grinding.md).
 *  @param grinding the object.
 *  @param time     the time to grind, s, > 0.
 *  @return DEMILL_OK, DEMILL_ERR_NOT_FINITE or DEMILL_ERR_INVALID_VALUE
 *          (time <= 0, or no feed set). */
DEMILL_API demill_status demill_grinding_run(demill_grinding *grinding, double time);

/** The grinding time since the feed was set.
 *  @param grinding  the object.
 *  @param[out] time receives the time, s.
 *  @return DEMILL_OK or DEMILL_ERR_NULL_POINTER. */
DEMILL_API demill_status demill_grinding_time(const demill_grinding *grinding, double *time);

/** Reads the product: the mass in each class, in the unit of the feed.
 *  @param grinding   the object.
 *  @param[out] mass  capacity doubles, or NULL to ask the count.
 *  @param capacity   the number of doubles `mass` can hold.
 *  @param[out] count receives the number of classes; may be NULL if mass is
 *                    not.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER or
 *          DEMILL_ERR_BUFFER_TOO_SMALL. */
DEMILL_API demill_status demill_grinding_product(const demill_grinding *grinding, double *mass,
                                                 size_t capacity, size_t *count);

/** The fraction of the product's mass finer than a size: exact at the class
 *  limits, linear in the logarithm of size between them.
 *  @param grinding      the object.
 *  @param size          the size, m, at least the sink's upper limit (finer
 *                       than that the distribution is not known).
 *  @param[out] fraction receives the fraction passing, 0 to 1.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (no feed set, or size below the sink's
 *          upper limit). */
DEMILL_API demill_status demill_grinding_passing(const demill_grinding *grinding, double size,
                                                 double *fraction);

/** The size that a given fraction of the product's mass passes (0.8 for
 *  P80), the inverse of demill_grinding_passing().
 *  @param grinding  the object.
 *  @param fraction  the fraction passing, in (0, 1].
 *  @param[out] size receives the size, m.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (no feed set, a fraction outside (0, 1],
 *          or a fraction that the sink alone holds, so that the size lies
 *          in it). */
DEMILL_API demill_status demill_grinding_size_passing(const demill_grinding *grinding,
                                                      double fraction, double *size);

/** The specific energy spent in grinding so far: power × time / mass.
 *  @param grinding   the object.
 *  @param power      the mill's power draw, W, >= 0.
 *  @param ore_mass   the mass of ore ground, kg, > 0.
 *  @param[out] kwh_t receives the specific energy, kWh/t.
 *  @return DEMILL_OK, DEMILL_ERR_NULL_POINTER, DEMILL_ERR_NOT_FINITE or
 *          DEMILL_ERR_INVALID_VALUE (power < 0 or ore_mass <= 0). */
DEMILL_API demill_status demill_grinding_specific_energy(const demill_grinding *grinding,
                                                         double power, double ore_mass,
                                                         double *kwh_t);

#ifdef __cplusplus
}
#endif

#endif /* DEMILL_GRINDING_H */
