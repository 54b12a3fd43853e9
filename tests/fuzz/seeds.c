/* seeds.c: writes the starting inputs of the checkpoint fuzzer into a
 * directory: checkpoints of an empty 2D and 3D world, a 2D box of discs with
 * a moving wall, a small 3D mill with lifters and a collision spectrum, and
 * clumps of two templates among spheres on a floor, in 3D and in 2D (each
 * stepped so that contacts carry history; a clump removed so that a slot
 * is free), every one both as a whole file (first byte 0) and as a payload
 * (first byte 2 f + 1 for format f, see checkpoint.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

#define OK(call)                                                                                   \
    do {                                                                                           \
        if ((call) != DEMILL_OK) {                                                                 \
            fprintf(stderr, "seeds: %s: %s\n", #call, demill_world_last_error(w));                \
            exit(1);                                                                               \
        }                                                                                          \
    } while (0)

static void write_seed(const char *dir, const char *name, demill_world *w)
{
    size_t n;
    OK(demill_world_save_buffer(w, NULL, 0, &n));
    unsigned char *b = malloc(n);
    if (!b)
        exit(1);
    OK(demill_world_save_buffer(w, b, n, &n));
    for (int mode = 0; mode < 2; mode++) {
        char path[4096];
        snprintf(path, sizeof path, "%s/seed-%s-%s", dir, name, mode ? "payload" : "file");
        FILE *f = fopen(path, "wb");
        const unsigned char first = (unsigned char)(mode ? 2 * b[8] + 1 : 0);
        const size_t skip = mode ? 32 : 0; /* the header, rebuilt by the target */
        if (!f || fwrite(&first, 1, 1, f) != 1 || fwrite(b + skip, 1, n - skip, f) != n - skip ||
            fclose(f))
            exit((perror(path), 1));
    }
    free(b);
}

static demill_id material(demill_world *w, int normal, int tangential)
{
    demill_id m;
    OK(demill_material_create(w, &m));
    OK(demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, normal));
    OK(demill_pair_set(w, m, m, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    OK(demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, tangential));
    return m;
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return fprintf(stderr, "usage: seeds DIRECTORY\n"), 2;
    demill_world *w;
    for (int dim = 2; dim <= 3; dim++) {
        OK(demill_world_create(dim, &w));
        write_seed(argv[1], dim == 2 ? "empty2d" : "empty3d", w);
        demill_world_destroy(w);
    }

    OK(demill_world_create(2, &w));
    demill_id m = material(w, DEMILL_NORMAL_LINEAR, DEMILL_TANGENTIAL_SPRING), wall;
    const double floor_pt[3] = {0, 0, 0}, up[3] = {0, 1, 0}, side[3] = {1, 0, 0};
    OK(demill_wall_add_plane(w, m, floor_pt, up, &wall));
    OK(demill_wall_add_plane(w, m, floor_pt, side, &wall));
    const double v[3] = {0.1, 0, 0};
    OK(demill_wall_set_motion(w, wall, v, NULL, NULL));
    double x[3 * 12] = {0}, r[12];
    for (int k = 0; k < 12; k++) {
        x[3 * k] = 0.01 + 0.0085 * (k % 4);
        x[3 * k + 1] = 0.005 + 0.0085 * (k / 4);
        r[k] = 0.004;
    }
    OK(demill_particles_add(w, m, 12, x, r, NULL, 0, NULL));
    OK(demill_world_step(w, 200));
    write_seed(argv[1], "box2d", w);
    demill_world_destroy(w);

    OK(demill_world_create(3, &w));
    m = material(w, DEMILL_NORMAL_HERTZ, DEMILL_TANGENTIAL_MINDLIN);
    OK(demill_pair_set(w, m, m, DEMILL_PAIR_ROLLING, DEMILL_ROLLING_CONSTANT_TORQUE));
    demill_id drum;
    OK(demill_drum_create(w, m, &drum));
    OK(demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.05));
    OK(demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.012));
    OK(demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 3));
    const double sizes[2] = {0.006, 1};
    OK(demill_drum_fill(w, drum, m, DEMILL_SIZES_CLASSES, sizes, 2, DEMILL_FILL_COUNT, 16, 1,
                        NULL, 0, NULL));
    const double edges[1] = {0.005};
    OK(demill_drum_spectrum_start(w, drum, 1, edges, 4, 1e-9, 1e-3));
    OK(demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.8));
    OK(demill_world_step(w, 300));
    write_seed(argv[1], "mill3d", w);
    demill_world_destroy(w);

    for (int dim = 3; dim >= 2; dim--) {
        OK(demill_world_create(dim, &w));
        m = material(w, DEMILL_NORMAL_LINEAR, DEMILL_TANGENTIAL_SPRING);
        OK(demill_wall_add_plane(w, m, floor_pt, up, &wall));
        const double dumbbell[6] = {-0.003, 0, 0, 0.003, 0, 0}, ell[9] = {0, 0, 0, 0.005, 0, 0,
                                                                       0, 0.005, 0};
        const double rd[2] = {0.004, 0.003}, rl[3] = {0.004, 0.004, 0.003};
        demill_id tmpl[2], clump[4];
        OK(demill_clump_template_add(w, m, 2, dumbbell, rd, &tmpl[0]));
        OK(demill_clump_template_add(w, m, 3, ell, rl, &tmpl[1]));
        for (int k = 0; k < 4; k++) {
            const double at[3] = {0.02 * k, 0.008, 0}, q[4] = {1, 0, 0, 0.3 * k};
            OK(demill_clump_add(w, tmpl[k % 2], at, q, &clump[k]));
        }
        const double ball[3] = {0.03, 0.03, 0}, rb = 0.004;
        OK(demill_particles_add(w, m, 1, ball, &rb, NULL, 0, NULL));
        OK(demill_clump_remove(w, clump[1]));
        OK(demill_world_step(w, 200));
        write_seed(argv[1], dim == 3 ? "clumps3d" : "clumps2d", w);
        demill_world_destroy(w);
    }
    return 0;
}
