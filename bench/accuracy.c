/* accuracy.c: the work-precision study of the integrators (docs/accuracy.md,
 * bench/README.md).
 *
 * For each integrator (symplectic Euler, velocity Verlet, the iterative
 * refinement at several tolerances ε_a) and time step Δt = t_c / n (t_c a
 * contact duration of the problem, n "steps per contact"), it runs reference
 * problems with known answers and prints one CSV line per measurement:
 *
 *   problem,integrator,eps,steps_per_contact,error,seconds,evals_per_step
 *
 * error: the relative error of the problem's quantity (nan if the run went
 * unstable); seconds: the wall time of the whole measurement on one thread
 * (the mean over repetitions for measurements shorter than MIN_TIME); every
 * measurement of a problem simulates the same physical time, whatever Δt.
 * evals_per_step: force evaluations per step over the measurement. Lines
 * starting with '#' are notes, "# what: key=value ...": the mill's reference
 * runs, the mean power of each measured mill run, the refinement's steps
 * that reached the iteration limit ("unconverged"), and at the end the run's
 * wall and CPU time. Progress goes to stderr.
 *
 * The problems:
 *   linear_restitution  binary impact, linear spring-dashpot, e = 0.5: worst
 *                       |e_meas - e| / e over the entry phases (phases[]);
 *                       t_c = π / ω_d, the damped half period
 *   hertz_restitution   the same with Hertz and Tsuji's damping;
 *                       t_c the undamped Hertz duration at 1 m/s
 *   hertz_duration      Hertz, elastic: worst error of the duration against
 *                       t_c = 2.9432752 δ_max / v
 *   thornton_restitution  the same spheres, Thornton's elastic-perfectly
 *                       plastic law, meeting at 10 times their yield speed:
 *                       worst error of the restitution against Thornton's
 *                       closed form; t_c the elastic Hertz duration
 *   gas_energy          64 elastic Hertz discs in a box, no friction, no
 *                       gravity: largest |E(t) - E(0)| / E(0) over GAS_SPAN
 *                       contact durations (10^6 steps at 1/200), sampled once
 *                       per contact duration; t_c at the rms relative speed
 *                       of the particles
 *   rolling             a sphere spun at ω0 on a floor (linear spring-slider,
 *                       μ = 0.3): the larger error of its final speed against
 *                       2/7 R ω0 and of the time to rolling against
 *                       2 R ω0 / (7 μ g); t_c the damped floor contact
 *   mill_power          a 2D mill of 304 balls, 6 lifters, soft linear
 *                       springs (t_c = 1 ms between the smallest balls) at
 *                       75 % of critical speed: the mean power over
 *                       revolutions 2 to 1 + MILL_REVOLUTIONS against a
 *                       reference run (velocity Verlet at
 *                       1/MILL_REFERENCE_STEPS of t_c). The flow is chaotic:
 *                       runs that differ by 1 nm in one ball's position give
 *                       mean powers that differ by 1-2 %; the notes give the
 *                       reference, its check by the converged refinement (if
 *                       the refinement is studied) and MILL_NUDGES such runs.
 *
 * --single runs every world with the single-precision contact kernels
 * (world.single_precision; docs/accuracy.md, Single precision); --nudge K
 * moves disc K of the gas by 1 nm, for the spread that chaos alone gives
 * its largest energy error.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <math.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <demill.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define G 9.81
#define YOUNG 1e8     /* Pa, of every material (Hertz) */
#define POISSON 0.3
#define DENSITY 2500  /* kg/m³, of all but the mill's steel balls */
#define MIN_TIME 0.05             /* s: shorter measurements are repeated */
#define GAS_SPAN 5000.0           /* contact durations of the gas run (quick: 1/20) */
#define MILL_REFERENCE_STEPS 400  /* steps per contact of the mill's reference */
#define MILL_REVOLUTIONS 5        /* averaged, after one to reach the steady flow */
#define MILL_NUDGES 3             /* runs of the reference with a ball moved by 1 nm */

/* The Hertz duration over δ_max / v: 2 ∫₀¹ dx / √(1 - x^{5/2})
 * = 2 √π Γ(2/5) / (5/2 Γ(9/10)) = 2.9432752 (Johnson §11.4). */
static double hertz_duration_factor(void)
{
    return 2.0 * sqrt(M_PI) * tgamma(0.4) / (2.5 * tgamma(0.9));
}

/* ---- schemes, runs and their bookkeeping -------------------------------- */

typedef struct scheme {
    const char *name; /* euler, verlet, refine */
    int integrator;   /* DEMILL_INTEGRATOR_* */
    double eps;       /* refinement: ε_a; 0 for the others */
} scheme;

/* One measurement in progress. */
typedef struct run {
    scheme s;
    double spc;             /* steps per contact duration: Δt = t_c / spc */
    int max_iterations;     /* of the refinement */
    int quick;
    int single;             /* DEMILL_WORLD_SINGLE_PRECISION in every world */
    int gas_nudged;         /* gas_energy: 1 + the index of a disc moved by 1 nm, or 0 */
    double reference;       /* mill_power: the reference power, W */
    int nudged;             /* mill_power: 1 + the index of a ball moved by 1 nm, or 0 */
    demill_world *w;        /* the world being stepped, if any */
    uint64_t steps, evals, unconverged; /* over the measurement's worlds */
    jmp_buf unstable;       /* where a step that failed as unstable jumps */
} run;

typedef double (*measure_fn)(run *r);

static const scheme euler = {"euler", DEMILL_INTEGRATOR_SYMPLECTIC_EULER, 0};
static const scheme verlet = {"verlet", DEMILL_INTEGRATOR_VELOCITY_VERLET, 0};

static scheme refinement(double eps)
{
    return (scheme){"refine", DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT, eps};
}

/* The scheme's ε_a as printed: "" for the schemes that have none. */
static const char *eps_text(const scheme *s, char buf[32])
{
    buf[0] = 0;
    if (s->eps > 0)
        snprintf(buf, 32, "%g", s->eps);
    return buf;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Ends the measurement as unstable (DEMILL_ERR_UNSTABLE, or no answer) or
 * the program (any other failure, a bug here). */
static void ok(run *r, demill_status s, const char *what)
{
    if (s == DEMILL_OK)
        return;
    fprintf(stderr, "accuracy: %s: %s (%s)\n", what, demill_strerror(s),
            demill_world_last_error(r->w));
    if (s == DEMILL_ERR_UNSTABLE)
        longjmp(r->unstable, 1);
    exit(EXIT_FAILURE);
}

static _Noreturn void give_up(run *r, const char *why)
{
    fprintf(stderr, "accuracy: %s\n", why);
    longjmp(r->unstable, 1);
}

static void set(run *r, int32_t key, double value)
{
    ok(r, demill_world_set(r->w, key, value), demill_param_name(key));
}

static void pair(run *r, demill_id m, int32_t key, double value)
{
    ok(r, demill_pair_set(r->w, m, m, key, value), demill_param_name(key));
}

static void step(run *r, uint64_t n)
{
    ok(r, demill_world_step(r->w, n), "step");
}

static double get(run *r, demill_id p, int32_t field, int c)
{
    double v[3] = {0, 0, 0};
    ok(r, demill_particle_get(r->w, p, field, v), "particle field");
    return v[c];
}

/* A world of the run's scheme, time step t_c / spc, gravity (0, gy, 0), one
 * thread, energy tally off (no problem reads dissipation), the watchdog off
 * (the study measures the integrators alone, and its coarse steps and soft
 * mill, whose bed presses balls into the shell by up to 30 % of a radius,
 * are meant to run where the watchdog would stop them), and one material
 * of the given density (and E = YOUNG, ν = POISSON) whose pair with itself
 * has the given laws. */
static demill_id open_world(run *r, int dim, double tc, double gy, double density, int normal,
                            int damping, int tangential)
{
    ok(r, demill_world_create(dim, &r->w), "world");
    set(r, DEMILL_WORLD_INTEGRATOR, r->s.integrator);
    if (r->s.integrator == DEMILL_INTEGRATOR_ITERATIVE_REFINEMENT) {
        set(r, DEMILL_WORLD_REFINE_TOLERANCE, r->s.eps);
        set(r, DEMILL_WORLD_REFINE_MAX_ITERATIONS, r->max_iterations);
    }
    set(r, DEMILL_WORLD_TIME_STEP, tc / r->spc);
    set(r, DEMILL_WORLD_GRAVITY_Y, gy);
    set(r, DEMILL_WORLD_ENERGY_TRACKING, 0);
    set(r, DEMILL_WORLD_WATCHDOG, 0);
    set(r, DEMILL_WORLD_SINGLE_PRECISION, r->single);
    demill_id m;
    ok(r, demill_material_create(r->w, &m), "material");
    const int32_t keys[] = {DEMILL_MATERIAL_DENSITY, DEMILL_MATERIAL_YOUNGS_MODULUS,
                            DEMILL_MATERIAL_POISSON_RATIO};
    const double values[] = {density, YOUNG, POISSON};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        ok(r, demill_material_set(r->w, m, keys[k], values[k]), demill_param_name(keys[k]));
    pair(r, m, DEMILL_PAIR_NORMAL, normal);
    pair(r, m, DEMILL_PAIR_DAMPING, damping);
    pair(r, m, DEMILL_PAIR_TANGENTIAL, tangential);
    return m;
}

/* Adds the world's counters to the run's and destroys it. */
static void close_world(run *r)
{
    double steps, evals, unconverged;
    ok(r, demill_world_get(r->w, DEMILL_WORLD_STEP_COUNT, &steps), "steps");
    ok(r, demill_world_get(r->w, DEMILL_WORLD_FORCE_EVALUATIONS, &evals), "evaluations");
    ok(r, demill_world_get(r->w, DEMILL_WORLD_REFINE_UNCONVERGED, &unconverged), "unconverged");
    r->steps += (uint64_t)steps;
    r->evals += (uint64_t)evals;
    r->unconverged += (uint64_t)unconverged;
    demill_world_destroy(r->w);
    r->w = NULL;
}

/* f(r), or NaN if it gave up. Kept apart so that no local variable of the
 * caller lives across the longjmp. */
static double attempt(measure_fn f, run *r)
{
    if (setjmp(r->unstable)) {
        if (r->w)
            close_world(r);
        return NAN;
    }
    return f(r);
}

/* f(r), repeated while all repetitions together take less than MIN_TIME;
 * *seconds receives the mean wall time of one. The counters are those of the
 * last repetition. */
static double timed(measure_fn f, run *r, double *seconds)
{
    const double t0 = now();
    double value;
    int reps = 0;
    do {
        r->steps = r->evals = r->unconverged = 0;
        value = attempt(f, r);
        reps++;
    } while (now() - t0 < MIN_TIME);
    *seconds = (now() - t0) / reps;
    return value;
}

static double rel(double got, double want)
{
    return fabs(got - want) / fabs(want);
}

/* max that keeps a NaN (an answer that went wrong must not be hidden) */
static double worse(double a, double b)
{
    return isnan(a) || b > a ? b : a;
}

static double sphere_mass(double radius, double density)
{
    return 4.0 / 3.0 * M_PI * radius * radius * radius * density;
}

/* Linear spring-dashpot with the restitution damping: the damped half
 * period π / ω_d, ω_d = √(k/m*) √(1 - ξ²), ξ = -ln e / √(π² + ln² e). */
static double linear_contact_time(double k, double mstar, double e)
{
    const double l = log(e);
    return sqrt(mstar / k) * sqrt(M_PI * M_PI + l * l);
}

/* The stiffness that gives linear_contact_time() = tc. */
static double linear_stiffness(double tc, double mstar, double e)
{
    const double l = log(e);
    return mstar * (M_PI * M_PI + l * l) / (tc * tc);
}

/* Hertz, elastic, two spheres of YOUNG and POISSON: the duration of an
 * impact at speed v, from δ_max = (15 m* v² / (16 E* √R*))^{2/5},
 * E* = E / (2 (1 - ν²)). */
static double hertz_contact_time(double rstar, double mstar, double v)
{
    const double estar = YOUNG / (2 * (1 - POISSON * POISSON));
    const double dmax = pow(15.0 * mstar * v * v / (16.0 * estar * sqrt(rstar)), 0.4);
    return hertz_duration_factor() * dmax / v;
}

/* ---- binary impacts (tests/physics/collision.c) --------------------------- */

typedef struct impact {
    double restitution, duration;
} impact;

/* Two equal spheres of radius rad approach head-on along x at relative speed
 * v0 from a gap that closes after (3 + phase) steps; returns the rebound
 * ratio and the duration (entry and exit interpolated linearly between
 * samples). */
static impact collide(run *r, demill_id mat, double rad, double v0, double dt, double phase)
{
    const double gap = (3.0 + phase) * v0 * dt;
    double x[6] = {-rad - gap / 2, 0, 0, rad + gap / 2, 0, 0};
    double v[6] = {v0 / 2, 0, 0, -v0 / 2, 0, 0};
    double radii[2] = {rad, rad};
    demill_id ids[2];
    ok(r, demill_particles_add(r->w, mat, 2, x, radii, v, 0, ids), "particles");
    double prev = -gap, t_in = -1, t_out = -1;
    for (long k = 1; t_out < 0; k++) {
        if (k > 1000000)
            give_up(r, "the collision did not end");
        step(r, 1);
        const double d = 2 * rad - (get(r, ids[1], DEMILL_PARTICLE_POSITION, 0) -
                                    get(r, ids[0], DEMILL_PARTICLE_POSITION, 0));
        if (prev <= 0 && d > 0)
            t_in = ((double)k - 1 + -prev / (d - prev)) * dt;
        if (prev > 0 && d <= 0)
            t_out = ((double)k - 1 + prev / (prev - d)) * dt;
        prev = d;
    }
    step(r, 5); /* apart: the velocities are final */
    const impact o = {(get(r, ids[1], DEMILL_PARTICLE_VELOCITY, 0) -
                       get(r, ids[0], DEMILL_PARTICLE_VELOCITY, 0)) / v0,
                      t_out - t_in};
    ok(r, demill_particles_remove(r->w, 2, ids), "remove");
    return o;
}

/* The entry phases of a binary impact (the fraction of a step after a
 * sample at which the bodies touch): eight spread evenly, and contacts
 * that begin 1e-4 and 1e-2 of a step after a sample or before one, where
 * the entry correction's first sample is nearly a step old or nearly
 * new. */
static const double phases[] = {1e-4,   1e-2,   0.0625, 0.1875, 0.3125,   0.4375,
                                 0.5625, 0.6875, 0.8125, 0.9375, 1 - 1e-2, 1 - 1e-4};

#define LINEAR_RADIUS 0.005
#define LINEAR_STIFFNESS 5e4 /* N/m */
#define HERTZ_RADIUS 0.003

/* The worst relative error over the entry phases of the restitution
 * (duration = 0) or of the duration against tc, for equal spheres of radius
 * rad meeting at 1 m/s in 3D; linear: LINEAR_STIFFNESS. */
static double impacts(run *r, int normal, int damping, double e, double rad, double tc,
                      int duration)
{
    const demill_id m = open_world(r, 3, tc, 0.0, DENSITY, normal, damping, DEMILL_TANGENTIAL_NONE);
    if (normal == DEMILL_NORMAL_LINEAR)
        pair(r, m, DEMILL_PAIR_NORMAL_STIFFNESS, LINEAR_STIFFNESS);
    pair(r, m, DEMILL_PAIR_RESTITUTION, e);
    double worst = 0;
    for (size_t p = 0; p < sizeof phases / sizeof phases[0]; p++) {
        const impact o = collide(r, m, rad, 1.0, tc / r->spc, phases[p]);
        worst = worse(worst, duration ? rel(o.duration, tc) : rel(o.restitution, e));
    }
    close_world(r);
    return worst;
}

/* m* of two equal spheres */
static double equal_mstar(double rad)
{
    return 0.5 * sphere_mass(rad, DENSITY);
}

static double hertz_impact_time(void)
{
    return hertz_contact_time(HERTZ_RADIUS / 2, equal_mstar(HERTZ_RADIUS), 1.0);
}

static double linear_restitution(run *r)
{
    return impacts(r, DEMILL_NORMAL_LINEAR, DEMILL_DAMPING_RESTITUTION, 0.5, LINEAR_RADIUS,
                   linear_contact_time(LINEAR_STIFFNESS, equal_mstar(LINEAR_RADIUS), 0.5), 0);
}

static double hertz_restitution(run *r)
{
    return impacts(r, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_RESTITUTION, 0.5, HERTZ_RADIUS,
                   hertz_impact_time(), 0);
}

static double hertz_duration(run *r)
{
    return impacts(r, DEMILL_NORMAL_HERTZ, DEMILL_DAMPING_NONE, 1.0, HERTZ_RADIUS,
                   hertz_impact_time(), 1);
}

/* Thornton (1997), "Coefficient of restitution for collinear collisions of
 * elastic-perfectly plastic spheres", J. Appl. Mech. 64: the limiting
 * contact pressure of the impacts, and his closed form of e for x = v_y/v. */
#define THORNTON_PRESSURE 2e6 /* Pa */
#define THORNTON_SPEEDS 10.0  /* v / v_y */

static double thornton_e(double x)
{
    return sqrt(6 * sqrt(3.0) / 5) * sqrt(1 - x * x / 6) *
           pow(x / (x + 2 * sqrt(6.0 / 5 - x * x / 5)), 0.25);
}

static double thornton_restitution(run *r)
{
    /* the yield speed from the elastic work to yield, 2/5 F_y δ_y, with
     * δ_y = R* (π p_y/(2E*))² and F_y = π³ p_y³ R*²/(6 E*²) */
    const double rstar = HERTZ_RADIUS / 2, mstar = equal_mstar(HERTZ_RADIUS);
    const double estar = YOUNG / (2 * (1 - POISSON * POISSON)), py = THORNTON_PRESSURE;
    const double dy = rstar * pow(M_PI * py / (2 * estar), 2);
    const double fy = pow(M_PI, 3) * pow(py, 3) * rstar * rstar / (6 * estar * estar);
    const double v = THORNTON_SPEEDS * sqrt(0.8 * fy * dy / mstar);
    const double tc = hertz_contact_time(rstar, mstar, v);
    const demill_id m = open_world(r, 3, tc, 0.0, DENSITY, DEMILL_NORMAL_THORNTON,
                                   DEMILL_DAMPING_NONE, DEMILL_TANGENTIAL_NONE);
    pair(r, m, DEMILL_PAIR_YIELD_PRESSURE, py);
    const double e = thornton_e(1 / THORNTON_SPEEDS);
    double worst = 0;
    for (size_t p = 0; p < sizeof phases / sizeof phases[0]; p++)
        worst = worse(worst,
                      rel(collide(r, m, HERTZ_RADIUS, v, tc / r->spc, phases[p]).restitution, e));
    close_world(r);
    return worst;
}

/* ---- the elastic gas ------------------------------------------------------ */

#define GAS_SIDE 8      /* particles per row */
#define GAS_BOX 0.15    /* m */
#define GAS_RADIUS 0.005

/* splitmix64: a fixed sequence on every platform; uniform in [0, 1) */
static double uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

static double total_energy(run *r)
{
    double e;
    ok(r, demill_world_energy(r->w, DEMILL_ENERGY_TOTAL, &e), "energy");
    return e;
}

/* GAS_SIDE² discs (spheres in the plane, radii 0.8-1.2 R) on a jittered
 * lattice in a box of four walls, velocity components uniform in [-1, 1] m/s;
 * Hertz, no damping, friction or gravity. t_c: the Hertz duration of two
 * spheres of radius R at the rms relative speed √2 v_rms. */
static double gas_energy(run *r)
{
    enum { N = GAS_SIDE * GAS_SIDE };
    double x[3 * N], v[3 * N], radii[N], v2 = 0;
    uint64_t seed = 12345;
    const double a = GAS_BOX / GAS_SIDE;
    for (int i = 0; i < N; i++) {
        const int ij[2] = {i % GAS_SIDE, i / GAS_SIDE};
        for (int c = 0; c < 3; c++) {
            x[3 * i + c] = c < 2 ? (ij[c] + 0.5) * a + 0.2 * a * (uniform(&seed) - 0.5) : 0.0;
            v[3 * i + c] = c < 2 ? 2.0 * uniform(&seed) - 1.0 : 0.0;
            v2 += v[3 * i + c] * v[3 * i + c] / N;
        }
        radii[i] = GAS_RADIUS * (0.8 + 0.4 * uniform(&seed));
    }
    const double tc =
        hertz_contact_time(GAS_RADIUS / 2, equal_mstar(GAS_RADIUS), sqrt(2 * v2));
    const demill_id m = open_world(r, 2, tc, 0.0, DENSITY, DEMILL_NORMAL_HERTZ,
                                   DEMILL_DAMPING_NONE, DEMILL_TANGENTIAL_NONE);
    for (int side = 0; side < 4; side++) {
        double p[3] = {0, 0, 0}, n[3] = {0, 0, 0};
        p[side / 2] = side % 2 ? GAS_BOX : 0.0;
        n[side / 2] = side % 2 ? -1.0 : 1.0;
        demill_id wall;
        ok(r, demill_wall_add_plane(r->w, m, p, n, &wall), "wall");
    }
    if (r->gas_nudged)
        x[3 * (r->gas_nudged - 1)] += 1e-9;
    ok(r, demill_particles_add(r->w, m, N, x, radii, v, DEMILL_ADD_NO_OVERLAP, NULL),
       "particles");
    const double e0 = total_energy(r);
    const long samples = lround((r->quick ? GAS_SPAN / 20 : GAS_SPAN));
    double worst = 0;
    for (long s = 0; s < samples; s++) {
        step(r, (uint64_t)lround(r->spc));
        worst = worse(worst, rel(total_energy(r), e0));
    }
    close_world(r);
    return worst;
}

/* ---- the sphere that rolls from spin (tests/physics/rolling.c) ------------ */

static double rolling(run *r)
{
    const double rad = 0.01, mu = 0.3, w0 = 50.0, k = LINEAR_STIFFNESS;
    const double tc = linear_contact_time(k, sphere_mass(rad, DENSITY), 0.5);
    const demill_id m = open_world(r, 3, tc, -G, DENSITY, DEMILL_NORMAL_LINEAR,
                                   DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_SPRING);
    pair(r, m, DEMILL_PAIR_NORMAL_STIFFNESS, k);
    pair(r, m, DEMILL_PAIR_RESTITUTION, 0.5);
    pair(r, m, DEMILL_PAIR_FRICTION, mu);
    double p[3] = {0, 0, 0}, n[3] = {0, 1, 0}, x[3] = {0, rad, 0};
    demill_id floor, ball;
    ok(r, demill_wall_add_plane(r->w, m, p, n, &floor), "floor");
    ok(r, demill_particles_add(r->w, m, 1, x, &rad, NULL, 0, &ball), "ball");
    const double dt = tc / r->spc;
    step(r, (uint64_t)lround(0.1 / dt)); /* settle: 70 contact durations */
    double zero[3] = {0, 0, 0}, spin[3] = {0, 0, w0};
    ok(r, demill_particle_set(r->w, ball, DEMILL_PARTICLE_VELOCITY, zero), "velocity");
    ok(r, demill_particle_set(r->w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin), "spin");
    /* the slip speed v_x + ω_z R falls at μ g (1 + 1/k), k = 2/5 */
    const double decel = mu * G * 3.5, t_roll = rad * w0 / decel, v_roll = 2.0 / 7.0 * rad * w0;
    const double threshold = 0.005 * rad * w0;
    const long steps = lround(3 * t_roll / dt);
    double prev = rad * w0, t_cross = -1;
    for (long s = 1; s <= steps; s++) {
        step(r, 1);
        const double slip = get(r, ball, DEMILL_PARTICLE_VELOCITY, 0) +
                            get(r, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2) * rad;
        if (t_cross < 0 && slip < threshold) /* the crossing, extrapolated to no slip */
            t_cross = ((double)s - (threshold - slip) / (prev - slip)) * dt + threshold / decel;
        prev = slip;
    }
    if (t_cross < 0)
        give_up(r, "the ball never stopped slipping");
    /* ω = +z with the contact below: the ball rolls towards -x */
    const double error = worse(rel(t_cross, t_roll),
                               rel(-get(r, ball, DEMILL_PARTICLE_VELOCITY, 0), v_roll));
    close_world(r);
    return error;
}

/* ---- the mill ---------------------------------------------------------------- */

#define MILL_DIAMETER 0.2
#define MILL_SMALL 0.005      /* ball diameters, m */
#define MILL_LARGE 0.007
#define MILL_CONTACT 1e-3     /* t_c between two small balls, s */
#define MILL_DENSITY 7800     /* steel */

/* The mean power drawn over revolutions 2 to 1 + MILL_REVOLUTIONS by a drum
 * (6 lifters 6 mm high and wide) filled to 30 % with steel balls of two
 * sizes, half the mass each (lattice fill, seed 42, not settled: the charge
 * falls into place in the first revolution), turning at 75 % of critical
 * from t = 0; balls and drum linear, e = 0.5, spring-slider μ = 0.5, the
 * stiffness that makes a contact of two small balls last MILL_CONTACT. Balls
 * of one size would crystallise in the plane and be carried up as blocks,
 * now and then, for a revolution or more: 1 nm nudges then spread the mean
 * power over 4 revolutions by up to 7 %. r->nudged: moves a ball by 1 nm
 * along x before the start (to see how far chaos alone spreads the
 * answer). */
static double mill_mean_power(run *r)
{
    const double mstar = 0.5 * sphere_mass(MILL_SMALL / 2, MILL_DENSITY);
    const demill_id m = open_world(r, 2, MILL_CONTACT, -G, MILL_DENSITY, DEMILL_NORMAL_LINEAR,
                                   DEMILL_DAMPING_RESTITUTION, DEMILL_TANGENTIAL_SPRING);
    pair(r, m, DEMILL_PAIR_NORMAL_STIFFNESS, linear_stiffness(MILL_CONTACT, mstar, 0.5));
    pair(r, m, DEMILL_PAIR_RESTITUTION, 0.5);
    pair(r, m, DEMILL_PAIR_FRICTION, 0.5);
    demill_id drum;
    ok(r, demill_drum_create(r->w, m, &drum), "drum");
    const int32_t keys[] = {DEMILL_DRUM_DIAMETER, DEMILL_DRUM_LIFTER_HEIGHT,
                            DEMILL_DRUM_LIFTER_WIDTH, DEMILL_DRUM_LIFTERS,
                            DEMILL_DRUM_FILL_POROSITY};
    const double values[] = {MILL_DIAMETER, 0.006, 0.006, 6, 0.2};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        ok(r, demill_drum_set(r->w, drum, keys[k], values[k]), "drum geometry");
    const double sizes[4] = {MILL_SMALL, 0.5, MILL_LARGE, 0.5};
    size_t n;
    ok(r, demill_drum_fill(r->w, drum, m, DEMILL_SIZES_CLASSES, sizes, 4, DEMILL_FILL_FRACTION,
                           0.3, 42, NULL, 0, &n),
       "fill");
    if (r->nudged) {
        double *x = malloc(3 * n * sizeof *x);
        ok(r, x ? demill_particles_read(r->w, DEMILL_PARTICLE_POSITION, x, n, &n)
                : DEMILL_ERR_OUT_OF_MEMORY,
           "positions");
        x[3 * (size_t)(r->nudged - 1)] += 1e-9;
        ok(r, demill_particles_write(r->w, DEMILL_PARTICLE_POSITION, x, n), "positions");
        free(x);
    }
    double omega;
    ok(r, demill_drum_set(r->w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75), "speed");
    ok(r, demill_drum_get(r->w, drum, DEMILL_DRUM_SPEED, &omega), "speed");
    const double revolution = 2 * M_PI / omega * r->spc / MILL_CONTACT; /* steps */
    const long start = lround(revolution), end = lround((1 + MILL_REVOLUTIONS) * revolution);
    step(r, (uint64_t)start);
    double sum = 0;
    for (long s = start; s < end; s++) {
        double power;
        step(r, 1);
        ok(r, demill_drum_get(r->w, drum, DEMILL_DRUM_POWER, &power), "power");
        sum += power;
    }
    close_world(r);
    return sum / (double)(end - start);
}

/* The mean power's relative distance from the reference; the power itself,
 * whose sign the distance loses, as a note. */
static double mill_power(run *r)
{
    const double power = mill_mean_power(r);
    char eps[32];
    printf("# mill_power run: integrator=%s eps=%s steps_per_contact=%g power=%.9g\n",
           r->s.name, eps_text(&r->s, eps), r->spc, power);
    return rel(power, r->reference);
}

/* ---- the study ------------------------------------------------------------- */

typedef struct problem {
    const char *name;
    measure_fn measure;
} problem;

static const problem problems[] = {
    {"linear_restitution", linear_restitution},
    {"hertz_restitution", hertz_restitution},
    {"hertz_duration", hertz_duration},
    {"thornton_restitution", thornton_restitution},
    {"gas_energy", gas_energy},
    {"rolling", rolling},
    {"mill_power", mill_power},
};
enum { NPROBLEMS = sizeof problems / sizeof problems[0], MAX_LIST = 32 };

typedef struct options {
    int problem[NPROBLEMS];        /* selected */
    int euler, verlet, refine;     /* selected */
    double eps[MAX_LIST], spc[MAX_LIST];
    int neps, nspc, max_iterations, quick, single, gas_nudged;
} options;

static void usage(FILE *f)
{
    fputs("usage: accuracy [options]  (CSV on stdout, progress on stderr)\n"
          "  --problems LIST       comma-separated, from linear_restitution, hertz_restitution,\n"
          "                        hertz_duration, gas_energy, rolling, mill_power [all]\n"
          "  --integrators LIST    from euler, verlet, refine [all]\n"
          "  --eps LIST            tolerances ε_a of the refinement [1e-2,1e-4,1e-6]\n"
          "  --steps LIST          time steps as steps per contact duration [5,10,20,50,100,200]\n"
          "  --max-iterations N    force evaluations per refinement step at most [20]\n"
          "  --quick               a short run: steps 5,10,20,50 unless given, the gas over\n"
          "                        1/20 of its time, the mill without the checks of its\n"
          "                        reference\n"
          "  --single              every world with the single-precision kernels\n"
          "                        (world.single_precision)\n"
          "  --nudge K             the gas with disc K (0-63) moved by 1 nm along x: how far\n"
          "                        chaos alone moves its largest energy error\n"
          "  --help                this text\n",
          f);
}

/* Parses a comma-separated list of positive numbers; returns its length, or
 * 0 if it is not one. */
static int parse_numbers(const char *s, double *out)
{
    int n = 0;
    for (;;) {
        char *end;
        const double v = strtod(s, &end);
        if (end == s || !(v > 0) || n == MAX_LIST || (*end && *end != ','))
            return 0;
        out[n++] = v;
        if (!*end)
            return n;
        s = end + 1;
    }
}

/* Marks the names of a comma-separated list in flags (names[k] ↔ flags[k]);
 * returns 0 on an unknown name. */
static int parse_names(const char *s, const char *const *names, int count, int *const *flags)
{
    for (int k = 0; k < count; k++)
        *flags[k] = 0;
    while (*s) {
        const size_t len = strcspn(s, ",");
        int found = 0;
        for (int k = 0; k < count; k++)
            if (strlen(names[k]) == len && !strncmp(s, names[k], len))
                found = *flags[k] = 1;
        if (!found)
            return 0;
        s += len + (s[len] == ',');
    }
    return 1;
}

static int parse_args(int argc, char **argv, options *o)
{
    static const double eps[] = {1e-2, 1e-4, 1e-6}, spc[] = {5, 10, 20, 50, 100, 200};
    const char *pnames[NPROBLEMS];
    int *pflags[NPROBLEMS];
    for (int k = 0; k < NPROBLEMS; k++) {
        pnames[k] = problems[k].name;
        pflags[k] = &o->problem[k];
        o->problem[k] = 1;
    }
    const char *const inames[] = {"euler", "verlet", "refine"};
    int *const iflags[] = {&o->euler, &o->verlet, &o->refine};
    o->euler = o->verlet = o->refine = 1;
    o->neps = 3;
    memcpy(o->eps, eps, sizeof eps);
    o->nspc = 0;
    o->max_iterations = 20;
    o->quick = o->single = o->gas_nudged = 0;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k], *v = k + 1 < argc ? argv[k + 1] : NULL;
        int good = 1;
        if (!strcmp(a, "--help")) {
            usage(stdout);
            exit(EXIT_SUCCESS);
        } else if (!strcmp(a, "--quick")) {
            o->quick = 1;
            continue;
        } else if (!strcmp(a, "--single")) {
            o->single = 1;
            continue;
        } else if (!v) {
            good = 0;
        } else if (!strcmp(a, "--problems")) {
            good = parse_names(v, pnames, NPROBLEMS, pflags);
        } else if (!strcmp(a, "--integrators")) {
            good = parse_names(v, inames, 3, iflags);
        } else if (!strcmp(a, "--eps")) {
            good = (o->neps = parse_numbers(v, o->eps)) > 0;
        } else if (!strcmp(a, "--steps")) {
            good = (o->nspc = parse_numbers(v, o->spc)) > 0;
        } else if (!strcmp(a, "--nudge")) {
            o->gas_nudged = 1 + atoi(v);
            good = o->gas_nudged >= 1 && o->gas_nudged <= GAS_SIDE * GAS_SIDE;
        } else if (!strcmp(a, "--max-iterations")) {
            o->max_iterations = atoi(v);
            good = o->max_iterations >= 1 && o->max_iterations <= 100;
        } else {
            good = 0;
        }
        if (!good) {
            fprintf(stderr, "accuracy: bad option or value: %s %s\n", a, v ? v : "");
            usage(stderr);
            return -1;
        }
        k++;
    }
    if (!o->nspc) {
        o->nspc = o->quick ? 4 : 6;
        memcpy(o->spc, spc, (size_t)o->nspc * sizeof spc[0]);
    }
    return 0;
}

/* What a measurement gives. */
typedef struct result {
    double value, seconds, evals_per_step;
    uint64_t steps, unconverged;
} result;

/* f(r) with a run made from the template t; reports on stderr. */
static result measure(measure_fn f, const char *what, run t)
{
    result o;
    o.value = timed(f, &t, &o.seconds);
    o.evals_per_step = t.steps ? (double)t.evals / (double)t.steps : NAN;
    o.steps = t.steps;
    o.unconverged = t.unconverged;
    char eps[32];
    fprintf(stderr, "accuracy: %s %s%s%s", what, t.s.name, t.s.eps > 0 ? " " : "",
            eps_text(&t.s, eps));
    if (t.nudged)
        fprintf(stderr, " (ball %d nudged)", t.nudged - 1);
    fprintf(stderr, " at 1/%g: %.4g (%.3g s, %.3f evaluations per step", t.spc, o.value,
            o.seconds, o.evals_per_step);
    if (t.unconverged)
        fprintf(stderr, ", %llu steps unconverged", (unsigned long long)t.unconverged);
    fprintf(stderr, ")\n");
    return o;
}

/* A note line about one of the mill's reference runs. */
static void mill_note(const char *label, const run *t, result o, double difference)
{
    char eps[32];
    printf("# mill_power %s: integrator=%s eps=%s steps_per_contact=%g nudged=%d power=%.9g "
           "seconds=%.4g evals_per_step=%.4g unconverged=%llu difference=%.4g\n",
           label, t->s.name, eps_text(&t->s, eps), t->spc, t->nudged ? t->nudged - 1 : -1,
           o.value, o.seconds, o.evals_per_step, (unsigned long long)o.unconverged, difference);
    fflush(stdout);
}

/* The mill's reference power, velocity Verlet at MILL_REFERENCE_STEPS, and
 * unless quick its checks, as notes: the refinement converged (ε_a 1e-8) at
 * the same step if the refinement is studied (refine), and the reference
 * run with one ball moved by 1 nm, MILL_NUDGES times, which shows how far
 * chaos alone spreads the mean power. t: the options of the runs. */
static double mill_reference(run t, int refine)
{
    t.s = verlet;
    t.spc = MILL_REFERENCE_STEPS;
    const result ref = measure(mill_mean_power, "mill_power reference", t);
    mill_note("reference", &t, ref, 0.0);
    if (t.quick)
        return ref.value;
    run c = t;
    result o;
    if (refine) {
        c.s = refinement(1e-8);
        o = measure(mill_mean_power, "mill_power check", c);
        mill_note("check", &c, o, rel(o.value, ref.value));
    }
    for (c = t, c.nudged = 1; c.nudged <= MILL_NUDGES; c.nudged++) {
        o = measure(mill_mean_power, "mill_power check", c);
        mill_note("nudged", &c, o, rel(o.value, ref.value));
    }
    return ref.value;
}

int main(int argc, char **argv)
{
    const double wall0 = now(), cpu0 = (double)clock() / CLOCKS_PER_SEC;
    options o;
    if (parse_args(argc, argv, &o))
        return EXIT_FAILURE;
    scheme schemes[2 + MAX_LIST];
    int nschemes = 0;
    if (o.euler)
        schemes[nschemes++] = euler;
    if (o.verlet)
        schemes[nschemes++] = verlet;
    for (int k = 0; o.refine && k < o.neps; k++)
        schemes[nschemes++] = refinement(o.eps[k]);
    if (o.single)
        printf("# precision: single (world.single_precision on in every world)\n");
    if (o.gas_nudged)
        printf("# gas_energy: disc %d moved by 1 nm\n", o.gas_nudged - 1);
    printf("problem,integrator,eps,steps_per_contact,error,seconds,evals_per_step\n");
    run t = {.max_iterations = o.max_iterations, .quick = o.quick, .single = o.single,
             .gas_nudged = o.gas_nudged, .reference = NAN};
    for (int p = 0; p < NPROBLEMS; p++) {
        if (!o.problem[p])
            continue;
        if (problems[p].measure == mill_power)
            t.reference = mill_reference(t, o.refine);
        for (int s = 0; s < nschemes; s++)
            for (int k = 0; k < o.nspc; k++) {
                t.s = schemes[s];
                t.spc = o.spc[k];
                const result m = measure(problems[p].measure, problems[p].name, t);
                char eps[32];
                printf("%s,%s,%s,%g,%.4e,%.4e,%.4f\n", problems[p].name, t.s.name,
                       eps_text(&t.s, eps), t.spc, m.value, m.seconds, m.evals_per_step);
                if (m.unconverged)
                    printf("# unconverged: problem=%s integrator=%s eps=%s steps_per_contact=%g "
                           "steps=%llu unconverged=%llu\n",
                           problems[p].name, t.s.name, eps, t.spc, (unsigned long long)m.steps,
                           (unsigned long long)m.unconverged);
                fflush(stdout);
            }
    }
    printf("# run: wall_seconds=%.1f cpu_seconds=%.1f\n", now() - wall0,
           (double)clock() / CLOCKS_PER_SEC - cpu0);
    return EXIT_SUCCESS;
}
