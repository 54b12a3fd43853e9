/* two_balls.c: two steel balls collide head-on, then a spinning ball is set
 * down on a floor and starts to roll. Prints what happens and compares it
 * with theory (Hertz impact, Johnson 1985, Contact Mechanics, §11.4; a ball
 * set spinning on a floor rolls off at v = 2/7 R ω0, from its angular momentum
 * about the contact point).
 *
 *   two_balls            run both scenes
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <demill.h>

#define PI 3.14159265358979323846

static void check(demill_world *w, demill_status s, const char *what)
{
    if (s != DEMILL_OK) {
        fprintf(stderr, "two_balls: %s failed: %s (%s)\n", what, demill_strerror(s),
                demill_world_last_error(w));
        exit(EXIT_FAILURE);
    }
}

static double get(demill_world *w, demill_id p, int field, int c)
{
    double v[3];
    check(w, demill_particle_get(w, p, field, v), "demill_particle_get");
    return v[c];
}

/* A material like hardened steel, but with a Young's modulus of 2e9 Pa so that
 * a contact lasts long enough to be watched with a 1e-6 s step. */
static demill_id steel(demill_world *w)
{
    demill_id m;
    check(w, demill_material_create(w, &m), "demill_material_create");
    check(w, demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, 7800), "density");
    check(w, demill_material_set(w, m, DEMILL_MATERIAL_YOUNGS_MODULUS, 2e9), "Young's modulus");
    check(w, demill_material_set(w, m, DEMILL_MATERIAL_POISSON_RATIO, 0.3), "Poisson ratio");
    check(w, demill_material_set(w, m, DEMILL_MATERIAL_RESTITUTION, 0.8), "restitution");
    check(w, demill_material_set(w, m, DEMILL_MATERIAL_FRICTION, 0.3), "friction");
    check(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ), "normal law");
    check(w, demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION), "damping");
    check(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN),
          "tangential law");
    return m;
}

static void collision(void)
{
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "two_balls: cannot create a world\n");
        exit(EXIT_FAILURE);
    }
    check(w, demill_world_set(w, DEMILL_WORLD_GRAVITY_Y, 0.0), "gravity");
    check(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 1e-6), "time step");
    demill_id m = steel(w), ball[2];
    const double r = 0.01, v0 = 1.0;
    double x[6] = {-0.011, 0, 0, 0.011, 0, 0}, v[6] = {v0 / 2, 0, 0, -v0 / 2, 0, 0};
    double radii[2] = {r, r};
    check(w, demill_particles_add(w, m, 2, x, radii, v, DEMILL_ADD_NO_OVERLAP, ball), "add balls");

    printf("1. Two steel balls (R = %g mm) meet head-on at %g m/s.\n", r * 1e3, v0);
    double t_start = -1, t_end = -1, fmax = 0, t = 0;
    while (t_end < 0) {
        check(w, demill_world_step(w, 1), "step");
        double contacts, f = fabs(get(w, ball[1], DEMILL_PARTICLE_FORCE, 0));
        check(w, demill_world_get(w, DEMILL_WORLD_CONTACT_COUNT, &contacts), "contact count");
        check(w, demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        if (contacts > 0 && t_start < 0)
            t_start = t;
        if (contacts == 0 && t_start >= 0)
            t_end = t;
        fmax = f > fmax ? f : fmax;
    }
    check(w, demill_world_step(w, 10), "step");
    double va = get(w, ball[0], DEMILL_PARTICLE_VELOCITY, 0);
    double vb = get(w, ball[1], DEMILL_PARTICLE_VELOCITY, 0);
    double mass = get(w, ball[0], DEMILL_PARTICLE_MASS, 0), dissipated;
    check(w, demill_world_energy(w, DEMILL_ENERGY_DISSIPATED, &dissipated), "energy");
    /* undamped Hertz: δ_max = (15 m* v0² / (16 E* √R*))^{2/5}, t_c = 2.9432 δ_max / v0 */
    double estar = 2e9 / (2 * (1 - 0.09)), mstar = mass / 2, rstar = r / 2;
    double dmax = pow(15 * mstar * v0 * v0 / (16 * estar * sqrt(rstar)), 0.4);
    printf("   contact lasted %.1f µs (undamped Hertz theory: %.1f µs), peak force %.1f N\n",
           (t_end - t_start) * 1e6, 2.9432 * dmax / v0 * 1e6, fmax);
    printf("   after: %+.4f and %+.4f m/s, restitution %.3f (material: 0.800)\n", va, vb,
           (vb - va) / v0);
    printf("   energy dissipated %.3g J = %.1f %% of the impact energy (1 - e² = 36.0 %%)\n\n",
           dissipated, 100 * dissipated / (0.5 * mstar * v0 * v0));
    demill_world_destroy(w);
}

static void rolling(void)
{
    demill_world *w;
    if (demill_world_create(3, &w) != DEMILL_OK) {
        fprintf(stderr, "two_balls: cannot create a world\n");
        exit(EXIT_FAILURE);
    }
    check(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, 2e-6), "time step");
    demill_id m = steel(w), floor, ball;
    const double r = 0.01, w0 = 30.0, mu = 0.3, g = 9.81;
    double p[3] = {0, 0, 0}, n[3] = {0, 1, 0}, x[3] = {0, r, 0};
    check(w, demill_wall_add_plane(w, m, p, n, &floor), "floor");
    check(w, demill_particles_add(w, m, 1, x, &r, NULL, 0, &ball), "add ball");
    check(w, demill_world_step(w, 20000), "settle"); /* 40 ms: the ball comes to rest */
    double spin[3] = {0, 0, w0}, zero[3] = {0, 0, 0}, t0;
    check(w, demill_particle_set(w, ball, DEMILL_PARTICLE_VELOCITY, zero), "velocity");
    check(w, demill_particle_set(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, spin), "spin");
    check(w, demill_world_get(w, DEMILL_WORLD_TIME, &t0), "time");

    printf("2. A ball spinning at %g rad/s (no linear velocity) touches a floor, μ = %g.\n", w0,
           mu);
    printf("   %8s %10s %10s %12s\n", "t [ms]", "v_x [m/s]", "ω_z [1/s]", "slip [m/s]");
    double t_roll = -1;
    for (int k = 0; k <= 12; k++) { /* a row every 3 ms */
        double t;
        check(w, demill_world_get(w, DEMILL_WORLD_TIME, &t), "time");
        double vx = get(w, ball, DEMILL_PARTICLE_VELOCITY, 0);
        double wz = get(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2);
        double slip = vx + wz * r;
        printf("   %8.2f %10.4f %10.3f %12.5f\n", (t - t0) * 1e3, vx, wz, slip);
        for (int s = 0; k < 12 && s < 1500; s++) {
            check(w, demill_world_step(w, 1), "step");
            slip = get(w, ball, DEMILL_PARTICLE_VELOCITY, 0) +
                   get(w, ball, DEMILL_PARTICLE_ANGULAR_VELOCITY, 2) * r;
            if (t_roll < 0 && fabs(slip) < 1e-4 * r * w0) {
                check(w, demill_world_get(w, DEMILL_WORLD_TIME, &t_roll), "time");
                t_roll -= t0;
            }
        }
    }
    double v = get(w, ball, DEMILL_PARTICLE_VELOCITY, 0);
    printf("   it rolls towards -x: v = %.4f m/s (theory 2/7 R ω0 = %.4f m/s)\n", v,
           -2.0 / 7.0 * r * w0);
    printf("   pure rolling after %.2f ms (theory 2 R ω0/(7 μ g) = %.2f ms)\n", t_roll * 1e3,
           2 * r * w0 / (7 * mu * g) * 1e3);
    demill_world_destroy(w);
}

int main(void)
{
    printf("libdemill %s: two balls\n\n", demill_version_string());
    if (demill_check_version(DEMILL_VERSION_NUMBER) != DEMILL_OK) {
        fprintf(stderr, "two_balls: built against headers %s but linked with %s\n",
                DEMILL_VERSION_STRING, demill_version_string());
        return EXIT_FAILURE;
    }
    collision();
    rolling();
    return EXIT_SUCCESS;
}
