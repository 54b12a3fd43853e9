/* vtk_scene.c: writes the known scenes that vtk_readback.py reads back with
 * VTK's own readers. Usage: io_vtk_scene DIR (an existing directory).
 *
 * The scenes are given by the formulas below, which vtk_readback.py
 * repeats; it derives what the files must hold from them, not from this
 * program. DIR must hold a directory "series". Gravity is the default
 * (0, -9.81, 0), Δt the default 1e-5 s.
 *
 * 3d: materials 0 (7800 kg/m³) and 1 (2500 kg/m³), linear contacts; a drum
 *   of material 0, diameter 0.3 m, length 0.1 m, 4 lifters 0.02 m high and
 *   0.03 m wide (lifter 0 at 3π/2), turning at 2 rad/s from t = 0; a plane
 *   wall through (0, -0.25, 0) with normal (0.2, 1, -0.1). 1000 steps with
 *   no particles, then 16 particles, k = 0..15:
 *     position          (-0.09 + 0.012 k, 0.02 (k mod 4) - 0.03, 0.01 ((k mod 3) - 1))
 *     radius            0.004 + 0.0001 k
 *     velocity          (0.1 k, -0.2, 0.05 (k mod 2))
 *     angular velocity  (1 + k, -k, 0.5 k)
 *     orientation       (1, 0.1 k, -0.2, 0.05 k), normalised by the write
 *     material          0 for k < 10, else 1
 *   and forces evaluated (0 steps): 3d_particles.vtu, 3d_walls.vtp.
 *   Then a series series/mill: frames at that time and after 100 and 200
 *   more steps (free fall: no particle touches anything).
 * 2d: material 0 (7800 kg/m³); a drum of diameter 0.4 m with 6 lifters
 *   0.03 m high and 0.04 m wide turning at -1.5 rad/s; a plane wall through
 *   (0, -0.3, 0) with normal (0.3, 1, 0). 500 steps, then 8 particles,
 *   k = 0..7: position (-0.07 + 0.02 k, 0.01 (k mod 2), 0), radius 0.006,
 *   velocity (0.05 k, 0.1, 0), angular velocity (0, 0, 2 k); 0 steps:
 *   2d_particles.vtu, 2d_walls.vtp.
 * empty: a 3D world with nothing: empty_particles.vtu, empty_walls.vtp.
 * plane: a 3D world with only the plane wall of 3d:
 *   plane_walls.vtp.
 * finite: a 3D world with a cylinder about the axis from (0, 0, 0) along
 *   (0, 1, 0), radius 0.1, length 0.2, capped at both ends; a cone from
 *   (0.5, 0, 0) along (0, 0, 1), radius 0 there and 0.1 at length 0.1; an
 *   annulus about (-0.5, 0, 0), normal (1, 0, 0), radii 0.1 and 0.04; a
 *   rectangle about (0, 0, 0.5), normal (0, 1, 0), half-widths 0.2 along
 *   (1, 0, 0) and 0.1 across: finite_walls.vtp.
 * loads: a 3D world, material 0 (7800 kg/m³) with linear contacts of
 *   stiffness 1e5 N/m; a mesh floor of the vertices (-0.1, 0, -0.1),
 *   (0.1, 0, -0.1), (0.1, 0, 0.1), (-0.1, 0, 0.1) and the triangles (0, 1, 2),
 *   (0, 2, 3), recording its loads; the rectangle of finite, not recording;
 *   a ball of radius 0.01 at rest at (0.03, 0.01 - m g / k, -0.02), m its
 *   mass and g 9.81 m/s². 500 steps: loads_walls.vtp.
 * clumps: a 3D world, material 0 (7800 kg/m³); a template of two spheres
 *   of radius 0.004 at (0, 0, 0) and (0.005, 0, 0); in this order: a sphere
 *   of radius 0.003 at (-0.05, 0, 0), clumps k = 0, 1, 2 of the template
 *   at (0.05 k, 0.1, 0) in the orientation (1, 0.2 k, -0.1, 0.3),
 *   normalised by the add, a sphere of radius 0.003 at (0.2, 0, 0); then
 *   clump 1 removed: clumps_particles.vtu.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <demill.h>

static demill_world *g_world;

static void check(demill_status s, const char *what)
{
    if (s != DEMILL_OK) {
        fprintf(stderr, "io_vtk_scene: %s: %s: %s\n", what, demill_strerror(s),
                demill_world_last_error(g_world));
        exit(EXIT_FAILURE);
    }
}

static const char *dir;

static const char *path(const char *name)
{
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s/%s", dir, name);
    return buf;
}

static demill_id material(demill_world *w, double density)
{
    demill_id m;
    check(demill_material_create(w, &m), "material");
    check(demill_material_set(w, m, DEMILL_MATERIAL_DENSITY, density), "density");
    return m;
}

static void linear(demill_world *w, demill_id a, demill_id b)
{
    check(demill_pair_set(w, a, b, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_LINEAR), "pair");
}

static demill_id drum(demill_world *w, demill_id mat, double diameter, int lifters,
                      double height, double width, double speed)
{
    demill_id d;
    check(demill_drum_create(w, mat, &d), "drum");
    check(demill_drum_set(w, d, DEMILL_DRUM_DIAMETER, diameter), "diameter");
    check(demill_drum_set(w, d, DEMILL_DRUM_LENGTH, 0.1), "length");
    check(demill_drum_set(w, d, DEMILL_DRUM_LIFTER_HEIGHT, height), "lifter height");
    check(demill_drum_set(w, d, DEMILL_DRUM_LIFTER_WIDTH, width), "lifter width");
    check(demill_drum_set(w, d, DEMILL_DRUM_LIFTERS, lifters), "lifters");
    check(demill_drum_set(w, d, DEMILL_DRUM_SPEED, speed), "speed");
    return d;
}

static void plane(demill_world *w, demill_id mat, const double p[3], const double n[3])
{
    demill_id id;
    check(demill_wall_add_plane(w, mat, p, n, &id), "plane");
}

static const double plane3_p[3] = {0, -0.25, 0}, plane3_n[3] = {0.2, 1, -0.1};

static void scene3d(void)
{
    demill_world *w;
    check(demill_world_create(3, &w), "world");
    g_world = w;
    demill_id a = material(w, 7800), b = material(w, 2500);
    linear(w, a, a);
    linear(w, a, b);
    linear(w, b, b);
    drum(w, a, 0.3, 4, 0.02, 0.03, 2.0);
    plane(w, a, plane3_p, plane3_n);
    check(demill_world_step(w, 1000), "steps");
    enum { N = 16 };
    double x[3 * N], r[N], v[3 * N], om[3 * N], q[4 * N];
    for (int k = 0; k < N; k++) {
        q[4 * k] = 1.0; /* (1, 0.1 k, -0.2, 0.05 k), which the write normalises */
        q[4 * k + 1] = 0.1 * k;
        q[4 * k + 2] = -0.2;
        q[4 * k + 3] = 0.05 * k;
        x[3 * k] = -0.09 + 0.012 * k;
        x[3 * k + 1] = 0.02 * (k % 4) - 0.03;
        x[3 * k + 2] = 0.01 * (k % 3 - 1);
        r[k] = 0.004 + 0.0001 * k;
        v[3 * k] = 0.1 * k;
        v[3 * k + 1] = -0.2;
        v[3 * k + 2] = 0.05 * (k % 2);
        om[3 * k] = 1 + k;
        om[3 * k + 1] = -k;
        om[3 * k + 2] = 0.5 * k;
    }
    check(demill_particles_add(w, a, 10, x, r, v, DEMILL_ADD_NO_OVERLAP, NULL), "particles");
    check(demill_particles_add(w, b, N - 10, x + 30, r + 10, v + 30, DEMILL_ADD_NO_OVERLAP, NULL),
          "particles");
    check(demill_particles_write(w, DEMILL_PARTICLE_ANGULAR_VELOCITY, om, N), "spin");
    check(demill_particles_write(w, DEMILL_PARTICLE_ORIENTATION, q, N), "orientation");
    check(demill_world_step(w, 0), "forces");
    check(demill_vtk_write_particles(w, path("3d_particles.vtu")), "3d particles");
    check(demill_vtk_write_walls(w, path("3d_walls.vtp")), "3d walls");
    demill_vtk_series *s;
    check(demill_vtk_series_open(w, path("series/mill"), &s), "series");
    for (int f = 0; f < 3; f++) {
        if (f)
            check(demill_world_step(w, 100), "series steps");
        check(demill_vtk_series_write(w, s), "frame");
    }
    demill_vtk_series_close(s);
    demill_world_destroy(w);
}

static void scene2d(void)
{
    demill_world *w;
    check(demill_world_create(2, &w), "world");
    g_world = w;
    demill_id a = material(w, 7800);
    linear(w, a, a);
    drum(w, a, 0.4, 6, 0.03, 0.04, -1.5);
    const double p[3] = {0, -0.3, 0}, n[3] = {0.3, 1, 0};
    plane(w, a, p, n);
    check(demill_world_step(w, 500), "steps");
    enum { N = 8 };
    double x[3 * N], r[N], v[3 * N], om[3 * N];
    for (int k = 0; k < N; k++) {
        x[3 * k] = -0.07 + 0.02 * k;
        x[3 * k + 1] = 0.01 * (k % 2);
        x[3 * k + 2] = 0;
        r[k] = 0.006;
        v[3 * k] = 0.05 * k;
        v[3 * k + 1] = 0.1;
        v[3 * k + 2] = 0;
        om[3 * k] = om[3 * k + 1] = 0;
        om[3 * k + 2] = 2 * k;
    }
    check(demill_particles_add(w, a, N, x, r, v, DEMILL_ADD_NO_OVERLAP, NULL), "particles");
    check(demill_particles_write(w, DEMILL_PARTICLE_ANGULAR_VELOCITY, om, N), "spin");
    check(demill_world_step(w, 0), "forces");
    check(demill_vtk_write_particles(w, path("2d_particles.vtu")), "2d particles");
    check(demill_vtk_write_walls(w, path("2d_walls.vtp")), "2d walls");
    demill_world_destroy(w);
}

static void scene_empty_and_plane(void)
{
    demill_world *w;
    check(demill_world_create(3, &w), "world");
    g_world = w;
    check(demill_vtk_write_particles(w, path("empty_particles.vtu")), "empty particles");
    check(demill_vtk_write_walls(w, path("empty_walls.vtp")), "empty walls");
    plane(w, material(w, 7800), plane3_p, plane3_n);
    check(demill_vtk_write_walls(w, path("plane_walls.vtp")), "plane walls");
    demill_world_destroy(w);
}

static void scene_finite(void)
{
    demill_world *w;
    check(demill_world_create(3, &w), "world");
    g_world = w;
    demill_id m = material(w, 7800), id;
    const double o[3] = {0, 0, 0}, y[3] = {0, 1, 0}, cone[3] = {0.5, 0, 0}, z[3] = {0, 0, 1};
    const double ring[3] = {-0.5, 0, 0}, x[3] = {1, 0, 0}, rect[3] = {0, 0, 0.5};
    check(demill_wall_add_cylinder(w, m, o, y, 0.1, 0.2, DEMILL_CAPS_BOTH, &id), "cylinder");
    check(demill_wall_add_cone(w, m, cone, z, 0.0, 0.1, 0.1, DEMILL_CAPS_NONE, &id), "cone");
    check(demill_wall_add_disc(w, m, ring, x, 0.1, 0.04, &id), "annulus");
    check(demill_wall_add_rectangle(w, m, rect, y, x, 0.2, 0.1, &id), "rectangle");
    check(demill_vtk_write_walls(w, path("finite_walls.vtp")), "finite walls");
    demill_world_destroy(w);
}

static void scene_loads(void)
{
    demill_world *w;
    check(demill_world_create(3, &w), "world");
    g_world = w;
    demill_id m = material(w, 7800), floor, rect, ball;
    linear(w, m, m);
    const double k = 1e5, r = 0.01, mg = 7800 * 4.0 / 3.0 * 3.14159265358979323846 * r * r * r * 9.81;
    check(demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL_STIFFNESS, k), "stiffness");
    const double v[] = {-0.1, 0, -0.1, 0.1, 0, -0.1, 0.1, 0, 0.1, -0.1, 0, 0.1};
    const uint32_t t[] = {0, 1, 2, 0, 2, 3};
    check(demill_wall_add_mesh(w, m, 4, v, 2, t, &floor), "floor");
    const double c[3] = {0, 0, 0.5}, y[3] = {0, 1, 0}, x[3] = {1, 0, 0};
    check(demill_wall_add_rectangle(w, m, c, y, x, 0.2, 0.1, &rect), "rectangle");
    const double at[3] = {0.03, r - mg / k, -0.02};
    check(demill_particles_add(w, m, 1, at, &r, NULL, 0, &ball), "ball");
    check(demill_wall_loads_start(w, floor), "loads");
    check(demill_world_step(w, 500), "steps");
    check(demill_vtk_write_walls(w, path("loads_walls.vtp")), "loads walls");
    demill_world_destroy(w);
}

static void scene_clumps(void)
{
    demill_world *w;
    check(demill_world_create(3, &w), "world");
    g_world = w;
    demill_id m = material(w, 7800), tmpl, clump[3];
    const double c[6] = {0, 0, 0, 0.005, 0, 0}, radii[2] = {0.004, 0.004}, r = 0.003;
    const double a[3] = {-0.05, 0, 0}, b[3] = {0.2, 0, 0};
    check(demill_clump_template_add(w, m, 2, c, radii, &tmpl), "template");
    check(demill_particles_add(w, m, 1, a, &r, NULL, 0, NULL), "sphere");
    for (int k = 0; k < 3; k++) {
        const double x[3] = {0.05 * k, 0.1, 0}, q[4] = {1, 0.2 * k, -0.1, 0.3};
        check(demill_clump_add(w, tmpl, x, q, &clump[k]), "clump");
    }
    check(demill_particles_add(w, m, 1, b, &r, NULL, 0, NULL), "sphere");
    check(demill_clump_remove(w, clump[1]), "remove");
    check(demill_vtk_write_particles(w, path("clumps_particles.vtu")), "clumps");
    demill_world_destroy(w);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: io_vtk_scene DIR\n");
        return EXIT_FAILURE;
    }
    dir = argv[1];
    scene3d();
    scene2d();
    scene_empty_and_plane();
    scene_finite();
    scene_loads();
    scene_clumps();
    return EXIT_SUCCESS;
}
