/* first.c: a steel ball dropped on a steel floor. It bounces, and each
 * bounce returns e² of the drop height (e = 0.5, the default restitution).
 * The first program of docs/getting-started-c.md, which shows this file as
 * it is (the test api_docs_snippets keeps the two the same). */
#include <demill.h>

#include <stdio.h>

/* Every function returns a status code; on failure print what went wrong. */
static int failed(demill_world *w, demill_status s, const char *what)
{
    if (s != DEMILL_OK)
        fprintf(stderr, "first: %s: %s (%s)\n", what, demill_strerror(s),
                demill_world_last_error(w));
    return s != DEMILL_OK;
}

int main(void)
{
    demill_world *w;
    demill_id steel, floor_id, ball;
    double origin[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    double x[3] = {0, 0.1, 0}, r = 0.01; /* centre 10 cm up, radius 1 cm */
    double dt, t = 0, pos[3], vel[3], top = 0, last_vy = 0;
    int bounces = 0;

    if (demill_world_create(3, &w) != DEMILL_OK) /* gravity (0, -9.81, 0) */
        return 1;
    if (failed(w, demill_material_create(w, &steel), "material") ||
        failed(w, demill_material_set(w, steel, DEMILL_MATERIAL_DENSITY, 7800), "density") ||
        failed(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ),
               "normal law") ||
        failed(w, demill_pair_set(w, steel, steel, DEMILL_PAIR_DAMPING,
                                  DEMILL_DAMPING_RESTITUTION), "damping") ||
        failed(w, demill_wall_add_plane(w, steel, origin, up, &floor_id), "floor") ||
        failed(w, demill_particles_add(w, steel, 1, x, &r, NULL, 0, &ball), "ball") ||
        failed(w, demill_world_suggest_time_step(w, 0, 0, &dt, NULL, NULL), "time step") ||
        failed(w, demill_world_set(w, DEMILL_WORLD_TIME_STEP, dt), "time step")) {
        demill_world_destroy(w);
        return 1;
    }
    printf("time step %.3g s; the ball falls from %.3f m\n", dt, x[1] - r);

    while (t < 1.0 && bounces < 3) {
        if (failed(w, demill_world_step(w, 10), "step") ||
            failed(w, demill_particle_get(w, ball, DEMILL_PARTICLE_POSITION, pos), "position") ||
            failed(w, demill_particle_get(w, ball, DEMILL_PARTICLE_VELOCITY, vel), "velocity") ||
            failed(w, demill_world_get(w, DEMILL_WORLD_TIME, &t), "time")) {
            demill_world_destroy(w);
            return 1;
        }
        if (last_vy > 0 && vel[1] <= 0) { /* the top of a bounce */
            bounces++;
            printf("t = %.3f s: bounce %d reaches %.4f m\n", t, bounces, top - r);
        }
        top = pos[1];
        last_vy = vel[1];
    }
    demill_world_destroy(w);
    return 0;
}
