/* Consumer of an installed libdemill, built by tests/api/install_consumer.sh
 * against the installed headers and library only (never the source tree):
 * once through pkg-config, once through find_package(demill) with the shared
 * (demill::demill) and the static (demill::demill_static) library.
 *
 * It checks that headers and library agree on the version, then drops one
 * free particle and compares its height after 0.01 s with the analytic free
 * fall y(t) = y0 - g t^2 / 2. Velocity Verlet integrates a constant
 * acceleration exactly, so the only error is round-off (relative 1e-6 is a
 * very loose bound). Exits 0 and prints a line ending in "OK" on success. */
#include <demill.h>

#include <stdio.h>
#include <string.h>

/* No <math.h>: the consumer itself needs nothing from libm, so linking the
 * static library shows whether the package brings libm along for it. */
static double absd(double v) { return v < 0 ? -v : v; }

#define CHECK(call)                                                            \
    do {                                                                       \
        demill_status s_ = (call);                                             \
        if (s_ != DEMILL_OK) {                                                 \
            fprintf(stderr, "consumer: %s failed: %s (%s)\n", #call,            \
                    demill_strerror(s_), demill_world_last_error(w));          \
            demill_world_destroy(w);                                           \
            return 1;                                                          \
        }                                                                      \
    } while (0)

int main(void)
{
    demill_world *w = NULL;
    demill_id mat = DEMILL_ID_NONE, ball = DEMILL_ID_NONE;
    const double y0 = 0.1, g = 9.81;
    const uint64_t steps = 1000;
    double x[3] = {0.0, y0, 0.0}, r = 0.01, pos[3], dt, t, expect, rel;

    if (demill_check_version(DEMILL_VERSION_NUMBER) != DEMILL_OK) {
        fprintf(stderr, "consumer: demill_check_version(%d) failed\n", DEMILL_VERSION_NUMBER);
        return 1;
    }
    if (demill_version_number() != DEMILL_VERSION_NUMBER) {
        fprintf(stderr, "consumer: library version number %u, headers %d\n",
                (unsigned)demill_version_number(), DEMILL_VERSION_NUMBER);
        return 1;
    }
    if (strcmp(demill_version_string(), DEMILL_VERSION_STRING) != 0) {
        fprintf(stderr, "consumer: library version \"%s\", headers \"%s\"\n",
                demill_version_string(), DEMILL_VERSION_STRING);
        return 1;
    }

    CHECK(demill_world_create(3, &w));
    CHECK(demill_material_create(w, &mat));
    CHECK(demill_pair_set(w, mat, mat, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    CHECK(demill_particles_add(w, mat, 1, x, &r, NULL, 0, &ball));
    CHECK(demill_world_get(w, DEMILL_WORLD_TIME_STEP, &dt));
    CHECK(demill_world_step(w, steps));
    CHECK(demill_world_get(w, DEMILL_WORLD_TIME, &t));
    CHECK(demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, pos));
    demill_world_destroy(w);

    if (dt != 1e-5 || absd(t - 0.01) > 1e-12) {
        fprintf(stderr, "consumer: time step %g s, time %.17g s; expected 1e-5 s, 0.01 s\n", dt, t);
        return 1;
    }
    t = (double)steps * dt;
    expect = y0 - 0.5 * g * t * t;
    rel = absd(pos[1] - expect) / absd(expect);
    if (!(rel <= 1e-6) || pos[0] != 0.0 || pos[2] != 0.0) {
        fprintf(stderr, "consumer: position (%.17g, %.17g, %.17g), expected (0, %.17g, 0)\n",
                pos[0], pos[1], pos[2], expect);
        return 1;
    }
    printf("demill %s: y(%g s) = %.12f m, analytic %.12f m, relative error %.1e: OK\n",
           demill_version_string(), t, pos[1], expect, rel);
    return 0;
}
