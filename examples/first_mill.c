/* first_mill.c: a small ball mill. A drum 20 cm across with four lifters,
 * a quarter filled with steel balls 12 mm in diameter, turns at 75 % of its
 * critical speed; the program prints the power it draws and where the charge
 * lies.
 * The second program of docs/getting-started-c.md, which shows this file as
 * it is (the test api_docs_snippets keeps the two the same). */
#include <demill.h>

#include <stdio.h>

#define DEG(a) ((a) * 57.29577951308232)

/* Stops the program at the first failure, saying what went wrong. */
#define CHECK(call)                                                                \
    do {                                                                           \
        demill_status s_ = (call);                                                 \
        if (s_ != DEMILL_OK) {                                                     \
            fprintf(stderr, "first_mill: %s: %s (%s)\n", #call, demill_strerror(s_), \
                    demill_world_last_error(w));                                   \
            demill_world_destroy(w);                                               \
            return 1;                                                              \
        }                                                                          \
    } while (0)

int main(void)
{
    demill_world *w = NULL;
    demill_id steel, drum;
    const double balls[2] = {0.012, 1.0}; /* one size class: 12 mm diameter, all the mass */
    size_t n;
    int32_t settled;
    double revolutions = 0, power, toe, shoulder;

    CHECK(demill_world_create(3, &w));
    CHECK(demill_material_create(w, &steel));
    CHECK(demill_material_set(w, steel, DEMILL_MATERIAL_DENSITY, 7800));
    CHECK(demill_material_set(w, steel, DEMILL_MATERIAL_FRICTION, 0.5));
    CHECK(demill_pair_set(w, steel, steel, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    CHECK(demill_pair_set(w, steel, steel, DEMILL_PAIR_DAMPING, DEMILL_DAMPING_RESTITUTION));
    CHECK(demill_pair_set(w, steel, steel, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));

    CHECK(demill_drum_create(w, steel, &drum)); /* the liner is steel too */
    CHECK(demill_drum_set(w, drum, DEMILL_DRUM_DIAMETER, 0.2));
    CHECK(demill_drum_set(w, drum, DEMILL_DRUM_LENGTH, 0.05));
    CHECK(demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 4));
    CHECK(demill_drum_fill(w, drum, steel, DEMILL_SIZES_CLASSES, balls, 2,
                           DEMILL_FILL_FRACTION, 0.25, 1, NULL, 0, &n));
    CHECK(demill_world_settle(w, 0.5, 1e-6, &settled)); /* let the charge fall */
    printf("%zu balls, %s\n", n, settled ? "settled" : "still moving after 0.5 s");

    CHECK(demill_drum_set(w, drum, DEMILL_DRUM_SPEED_FRACTION, 0.75));
    while (revolutions < 2) {
        CHECK(demill_world_step(w, 1000));
        CHECK(demill_drum_get(w, drum, DEMILL_DRUM_REVOLUTIONS, &revolutions));
    }
    /* means over the last completed revolution */
    CHECK(demill_drum_get(w, drum, DEMILL_DRUM_POWER_MEAN, &power));
    CHECK(demill_drum_get(w, drum, DEMILL_DRUM_TOE_ANGLE_MEAN, &toe));
    CHECK(demill_drum_get(w, drum, DEMILL_DRUM_SHOULDER_ANGLE_MEAN, &shoulder));
    printf("power %.1f W, toe %.0f°, shoulder %.0f°\n", power, DEG(toe), DEG(shoulder));
    demill_world_destroy(w);
    return 0;
}
