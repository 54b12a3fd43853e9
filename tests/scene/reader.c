/* reader.c: the scene-file reader of the demill program (tools/demill/):
 * good files build the world they describe (every value read back through
 * the API against the number written in the file), overrides (--set)
 * replace entries by their dotted path, and bad files fail with a message
 * naming the file, the line, the key and what was expected, leaving no
 * world. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "clumps.h"
#include "scene.h"
#include "testutil.h"

static char dir[64];

static void write_file(const char *name, const char *text)
{
    char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

static tree *parse(const char *text)
{
    char err[1024];
    tree *t;
    ck_assert_msg(!tree_parse("t.yaml", (const unsigned char *)text, strlen(text), &t, err,
                              sizeof err),
                  "%s", err);
    return t;
}

/* The message of a scene that must fail (parse or check); NULL world after. */
static const char *failure(const char *text, const char *set)
{
    static char err[1024];
    tree *t;
    if (tree_parse("t.yaml", (const unsigned char *)text, strlen(text), &t, err, sizeof err))
        return err;
    if (set) {
        char path[128];
        const char *eq = strchr(set, '=');
        snprintf(path, sizeof path, "%.*s", (int)(eq - set), set);
        if (tree_set(t, path, eq + 1, err, sizeof err)) {
            tree_free(t);
            return err;
        }
    }
    scene s = {0};
    const int rc = scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err);
    tree_free(t);
    ck_assert_int_eq(rc, -1);
    ck_assert_ptr_null(s.w);
    return err;
}

static const char *const good =
    "world:\n"
    "  dimension: 3\n"
    "  time_step: 2e-6\n"
    "  gravity: [0, 0, -9.81]\n"
    "  integrator: symplectic_euler\n"
    "materials:\n"
    "  glass:\n"
    "    density: 2500\n"
    "    youngs_modulus: 5e7\n"
    "  steel: {density: 7800, friction: 0.4}\n"
    "pairs:\n"
    "  - materials: [glass, steel]\n"
    "    normal: hertz\n"
    "    damping: restitution\n"
    "    restitution: 0.7\n"
    "  - {materials: [glass, glass], normal: linear, damping: viscous, normal_stiffness: 1e4}\n"
    "  - {materials: [steel, steel], normal: hertz, clamp_normal: false}\n"
    "walls:\n"
    "  - material: steel\n"
    "    plane: {point: [0, 0, 0], normal: [0, 0, 1]}\n"
    "    motion: {velocity: [0.5, 0, 0]}\n"
    "particles:\n"
    "  - {material: glass, csv: balls.csv}\n"
    "  - material: steel\n"
    "    region: {box: [-0.05, -0.05, 0.05, 0.05, 0.05, 0.15]}\n"
    "    sizes: {classes: [[0.01, 1]]}\n"
    "    count: 20\n"
    "    seed: 7\n"
    "outputs: {every: 1e-4, csv: t.csv, columns: [world.time, world.contact_count]}\n"
    "stop: {time: 0.01}\n";

START_TEST(test_good)
{
    write_file("balls.csv", "x,y,z,radius,vz\n0,0,0.02,0.005,-1\n0.02, 0, 0.02, 0.004, 0\n");
    tree *t = parse(good);
    scene s;
    char err[1024];
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    demill_world *w = s.w;
    double v;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME_STEP, &v));
    ck_assert_double_eq(v, 2e-6);
    ck_assert_double_eq(s.dt, 2e-6);
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Z, &v));
    ck_assert_double_eq(v, -9.81);
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_GRAVITY_Y, &v));
    ck_assert_double_eq(v, 0);
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_INTEGRATOR, &v));
    ck_assert_double_eq(v, DEMILL_INTEGRATOR_SYMPLECTIC_EULER);
    ck_assert_uint_eq(s.nmat, 2);
    ck_assert_str_eq(s.matname[1], "steel");
    DM_OK(w, demill_material_get(w, s.mat[0], DEMILL_MATERIAL_YOUNGS_MODULUS, &v));
    ck_assert_double_eq(v, 5e7);
    DM_OK(w, demill_material_get(w, s.mat[1], DEMILL_MATERIAL_FRICTION, &v));
    ck_assert_double_eq(v, 0.4);
    DM_OK(w, demill_pair_get(w, s.mat[1], s.mat[0], DEMILL_PAIR_RESTITUTION, &v));
    ck_assert_double_eq(v, 0.7);
    DM_OK(w, demill_pair_get(w, s.mat[0], s.mat[0], DEMILL_PAIR_DAMPING, &v));
    ck_assert_double_eq(v, DEMILL_DAMPING_VISCOUS);
    DM_OK(w, demill_pair_get(w, s.mat[0], s.mat[0], DEMILL_PAIR_NORMAL_STIFFNESS, &v));
    ck_assert_double_eq(v, 1e4);
    DM_OK(w, demill_pair_get(w, s.mat[1], s.mat[1], DEMILL_PAIR_CLAMP_NORMAL, &v));
    ck_assert_double_eq(v, 0);
    /* 2 particles from the file, 20 from the fill */
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &v));
    ck_assert_double_eq(v, 22);
    demill_id ids[22];
    size_t n;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_PARTICLE, ids, 22, &n));
    double x[3], vel[3], r;
    DM_OK(w, demill_particle_get(w, ids[1], DEMILL_PARTICLE_POSITION, x));
    DM_OK(w, demill_particle_get(w, ids[0], DEMILL_PARTICLE_VELOCITY, vel));
    DM_OK(w, demill_particle_get(w, ids[1], DEMILL_PARTICLE_RADIUS, &r));
    ck_assert_double_eq(x[0], 0.02);
    ck_assert_double_eq(vel[2], -1);
    ck_assert_double_eq(r, 0.004);
    DM_OK(w, demill_particle_get(w, ids[5], DEMILL_PARTICLE_RADIUS, &r));
    ck_assert_double_eq(r, 0.005);
    /* one wall, moving at 0.5 m/s along x */
    demill_id wall;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_WALL, &wall, 1, &n));
    ck_assert_uint_eq(n, 1);
    ck_assert_double_eq(s.stop_time, 0.01);
    ck_assert(isnan(s.stop_revolutions));
    ck_assert_double_eq(s.every, 1e-4);
    ck_assert_str_eq(s.csv_file, "t.csv");
    ck_assert_uint_eq(s.ncol, 2);
    ck_assert_int_eq(s.col[1].key, DEMILL_WORLD_CONTACT_COUNT);
    ck_assert_uint_eq(s.drum, DEMILL_ID_NONE);
    demill_world_destroy(w);
    tree_free(t);
}
END_TEST

/* the drum: its keys by the registry's names, its parts' materials, its
 * speed held back to start_time */
START_TEST(test_drum)
{
    tree *t = parse("materials: {steel: {}, rubber: {density: 1100}}\n"
                    "pairs: [{materials: [steel, rubber], normal: hertz}]\n"
                    "drum: {material: steel, diameter: 0.5, length: 0.2, lifter_height: 0.02,\n"
                    "       lifters: 6, speed_rpm: 40, start_time: 0.25, parts: {lifters: rubber}}\n"
                    "stop: {revolutions: 3}\n");
    scene s;
    char err[1024];
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    double v;
    DM_OK(s.w, demill_drum_get(s.w, s.drum, DEMILL_DRUM_DIAMETER, &v));
    ck_assert_double_eq(v, 0.5);
    DM_OK(s.w, demill_drum_get(s.w, s.drum, DEMILL_DRUM_LIFTER_COUNT, &v));
    ck_assert_double_eq(v, 6);
    DM_OK(s.w, demill_drum_get(s.w, s.drum, DEMILL_DRUM_SPEED_RPM, &v));
    ck_assert_double_eq(v, 0); /* not before start_time */
    ck_assert_int_eq(s.speed_key, DEMILL_DRUM_SPEED_RPM);
    ck_assert_double_eq(s.speed_value, 40);
    ck_assert_double_eq(s.drum_start, 0.25);
    ck_assert_double_eq(s.stop_revolutions, 3);
    demill_id m;
    DM_OK(s.w, demill_drum_get_material(s.w, s.drum, DEMILL_DRUM_PART_LIFTERS, &m));
    ck_assert_uint_eq(m, s.mat[1]);
    DM_OK(s.w, demill_drum_get_material(s.w, s.drum, DEMILL_DRUM_PART_SHELL, &m));
    ck_assert_uint_eq(m, s.mat[0]);
    demill_world_destroy(s.w);
    tree_free(t);
}
END_TEST

/* a 2D scene: a polyline wall, discs filled into a rectangle */
START_TEST(test_2d)
{
    tree *t = parse("world: {dimension: 2}\n"
                    "materials: {m: {}}\n"
                    "pairs: [{materials: [m, m], normal: linear}]\n"
                    "walls:\n"
                    "  - {material: m, polyline: {points: [[-0.1, 0.1, 0], [-0.1, 0, 0], [0.1, 0, 0]],\n"
                    "                             closed: false}}\n"
                    "particles:\n"
                    "  - {material: m, region: {box: [-0.09, 0.01, 0, 0.09, 0.09, 0]},\n"
                    "     sizes: {classes: [[0.01, 1]]}, count: 30}\n"
                    "stop: {time: 1}\n");
    scene s;
    char err[1024];
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    double v;
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_DIMENSION, &v));
    ck_assert_double_eq(v, 2);
    ck_assert_int_eq(s.dim, 2);
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_PARTICLE_COUNT, &v));
    ck_assert_double_eq(v, 30);
    size_t n;
    DM_OK(s.w, demill_world_ids(s.w, DEMILL_KIND_WALL, NULL, 0, &n));
    ck_assert_uint_eq(n, 1);
    demill_world_destroy(s.w);
    tree_free(t);
}
END_TEST

/* time_step: auto is the library's suggestion for the built scene, with
 * its steps_per_contact */
START_TEST(test_auto_time_step)
{
    write_file("ball.csv", "x,y,z,radius\n0,0.015,0,0.01\n");
    tree *t = parse("world: {time_step: auto, steps_per_contact: 20}\n"
                    "materials: {steel: {density: 7800, youngs_modulus: 2e8}}\n"
                    "pairs: [{materials: [steel, steel], normal: hertz, damping: restitution}]\n"
                    "walls: [{material: steel, plane: {point: [0, 0, 0], normal: [0, 1, 0]}}]\n"
                    "particles: [{material: steel, csv: ball.csv}]\n"
                    "stop: {time: 1}\n");
    scene s;
    char err[1024];
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    double dt, want;
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_TIME_STEP, &dt));
    DM_OK(s.w, demill_world_suggest_time_step(s.w, 0, 20, &want, NULL, NULL));
    ck_assert_double_eq(dt, want);
    ck_assert_double_eq(s.dt, want);
    ck_assert_double_ne(dt, 1e-5); /* not the default */
    demill_world_destroy(s.w);
    tree_free(t);
}
END_TEST

/* An ASCII STL file of the regular octahedron of vertices (+-5, 0, 0), (0,
 * +-5, 0), (0, 0, +-5) mm, wound counter-clockwise seen from outside. */
static void write_octahedron(const char *name)
{
    char path[128];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs("solid octahedron\n", f);
    for (int o = 0; o < 8; o++) {
        const int sx = o & 1 ? -5 : 5, sy = o & 2 ? -5 : 5, sz = o & 4 ? -5 : 5;
        const int v[3][3] = {{sx, 0, 0}, {0, sy, 0}, {0, 0, sz}};
        const int odd = (sx < 0) ^ (sy < 0) ^ (sz < 0); /* a mirrored octant turns the winding */
        fputs(" facet normal 0 0 0\n  outer loop\n", f);
        for (int k = 0; k < 3; k++) {
            const int *p = v[odd && k ? 3 - k : k];
            fprintf(f, "   vertex %d %d %d\n", p[0], p[1], p[2]);
        }
        fputs("  endloop\n endfacet\n", f);
    }
    fputs("endsolid octahedron\n", f);
    fclose(f);
}

/* clumps: a template of two spheres, one of a mesh, a fill of one template
 * by count and a mix of both by mass */
START_TEST(test_clumps)
{
    write_octahedron("oct.stl");
    tree *t = parse("materials: {steel: {density: 7800}}\n"
                    "pairs: [{materials: [steel, steel], normal: hertz}]\n"
                    "drum: {material: steel, diameter: 0.3, length: 0.1}\n"
                    "templates:\n"
                    "  pair: {material: steel, spheres: [[0, 0, 0, 0.005], [0.006, 0, 0, 0.004]]}\n"
                    "  oct:\n"
                    "    material: steel\n"
                    "    stl: {file: oct.stl, scale: 0.001, spheres: 3, cells: 32}\n"
                    "particles:\n"
                    "  - {template: pair, region: {box: [-0.05, 0.07, -0.04, 0.05, 0.12, 0.04]},\n"
                    "     count: 10, seed: 4}\n"
                    "  - {template: [[pair, 0.6], [oct, 0.4]], region: drum, mass: 0.5}\n"
                    "stop: {time: 1}\n");
    scene s;
    char err[1024];
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    demill_world *w = s.w;
    ck_assert_uint_eq(s.ntmpl, 2);
    ck_assert_str_eq(s.tmplname[1], "oct");
    /* two spheres of radii a, b, centres d apart: their volumes less the
     * lens, pi (a + b - d)^2 (d^2 + 2 d (a + b) - 3 (a - b)^2) / (12 d)
     * (Weisstein, Sphere-Sphere Intersection, MathWorld) */
    const double a = 0.005, b = 0.004, d = 0.006, rho = 7800;
    const double lens = M_PI * (a + b - d) * (a + b - d) *
                        (d * d + 2 * d * (a + b) - 3 * (a - b) * (a - b)) / (12 * d);
    const double m_pair = rho * (4 * M_PI / 3 * (a * a * a + b * b * b) - lens);
    double m_oct, v;
    DM_OK(w, demill_clump_template_get(w, s.tmpl[0], DEMILL_TEMPLATE_MASS, &v));
    ck_assert_msg(fabs(v / m_pair - 1) < 1e-12, "pair: %.17g against %.17g", v, m_pair);
    /* the octahedron's volume, 4/3 (5 mm)^3, read at scale 0.001 */
    DM_OK(w, demill_clump_template_get(w, s.tmpl[1], DEMILL_TEMPLATE_MESH_VOLUME, &v));
    ck_assert_msg(fabs(v / (4.0 / 3 * 125e-9) - 1) < 1e-12, "octahedron: %.17g m^3", v);
    DM_OK(w, demill_clump_template_get(w, s.tmpl[1], DEMILL_TEMPLATE_MASS, &m_oct));
    /* the count exactly; the mix's mass in whole clumps of each, the
     * nearest number to its share */
    ck_assert_uint_eq(s.tmpl_clumps[0], 10 + (size_t)lround(0.3 / m_pair));
    ck_assert_uint_eq(s.tmpl_clumps[1], (size_t)lround(0.2 / m_oct));
    size_t nc, n_oct_members;
    DM_OK(w, demill_world_ids(w, DEMILL_KIND_CLUMP, NULL, 0, &nc));
    ck_assert_uint_eq(nc, s.tmpl_clumps[0] + s.tmpl_clumps[1]);
    DM_OK(w, demill_clump_template_spheres(w, s.tmpl[1], NULL, NULL, 0, &n_oct_members));
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_PARTICLE_COUNT, &v));
    ck_assert_double_eq(v, 2 * s.tmpl_clumps[0] + n_oct_members * s.tmpl_clumps[1]);
    /* the charge's mass: each clump once */
    double mass, centre[3];
    DM_OK(w, clumps_charge(w, &mass, centre));
    const double want = s.tmpl_clumps[0] * m_pair + s.tmpl_clumps[1] * m_oct;
    ck_assert_msg(fabs(mass / want - 1) < 1e-12, "charge %.17g kg against %.17g", mass, want);
    demill_world_destroy(w);
    /* demill check makes no template and reads no STL file */
    tree_set(t, "templates.oct.stl.file", "missing.stl", err, sizeof err);
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_CHECK, err, sizeof err), "%s", err);
    ck_assert_uint_eq(s.tmpl[0], DEMILL_ID_NONE);
    ck_assert_uint_eq(s.tmpl[1], DEMILL_ID_NONE);
    demill_world_destroy(s.w);
    tree_free(t);
}
END_TEST

/* --set replaces a scalar, a list item and a whole list, and adds a key */
START_TEST(test_set)
{
    write_file("balls.csv", "x,y,z,radius\n0,0,0.02,0.005\n");
    tree *t = parse(good);
    char err[1024];
    ck_assert(!tree_set(t, "materials.steel.density", "8000", err, sizeof err));
    ck_assert(!tree_set(t, "particles.1.count", "5", err, sizeof err));
    ck_assert(!tree_set(t, "world.gravity", "[0, -1, 0]", err, sizeof err));
    ck_assert(!tree_set(t, "world.threads", "1", err, sizeof err));
    ck_assert(tree_set(t, "materials.iron.density", "1", err, sizeof err));
    ck_assert_str_eq(err, "--set materials.iron.density: no entry 'iron' in the scene");
    ck_assert(tree_set(t, "particles.2.count", "1", err, sizeof err));
    ck_assert_str_eq(err, "--set particles.2.count: '2' is not an item of the list (0 to 1)");
    scene s;
    ck_assert_msg(!scene_build(&s, t, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    double v;
    DM_OK(s.w, demill_material_get(s.w, s.mat[1], DEMILL_MATERIAL_DENSITY, &v));
    ck_assert_double_eq(v, 8000);
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_GRAVITY_Y, &v));
    ck_assert_double_eq(v, -1);
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_PARTICLE_COUNT, &v));
    ck_assert_double_eq(v, 6);
    demill_world_destroy(s.w);
    /* the tree written back reads as the same scene */
    char path[128];
    snprintf(path, sizeof path, "%s/back.yaml", dir);
    FILE *f = fopen(path, "w");
    ck_assert(!tree_write(f, t));
    fclose(f);
    tree *back;
    ck_assert_msg(!tree_parse_file(path, &back, err, sizeof err), "%s", err);
    ck_assert_msg(!scene_build(&s, back, dir, SCENE_BUILD, err, sizeof err), "%s", err);
    DM_OK(s.w, demill_world_get(s.w, DEMILL_WORLD_PARTICLE_COUNT, &v));
    ck_assert_double_eq(v, 6);
    demill_world_destroy(s.w);
    tree_free(back);
    tree_free(t);
}
END_TEST

/* each bad file's message, exactly */
START_TEST(test_bad)
{
    static const struct {
        const char *yaml, *set, *message;
    } cases[] = {
        {"materials:\n  steel:\n    density: heavy\nstop: {time: 1}\n", NULL,
         "t.yaml:3: materials.steel.density: expected a number > 0 kg/m^3, got 'heavy'"},
        {"materials:\n  steel:\n    densty: 7800\nstop: {time: 1}\n", NULL,
         "t.yaml:3: materials.steel.densty: unknown key (did you mean 'density'?)"},
        {"materials:\n  steel: {poisson_ratio: 0.5}\nstop: {time: 1}\n", NULL,
         "t.yaml:2: materials.steel.poisson_ratio: expected a number in [0, 0.5), got '0.5'"},
        {"world: {integrator: leapfrog}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: world.integrator: expected one of velocity_verlet, symplectic_euler, "
         "iterative_refinement, got 'leapfrog'"},
        {"world: {threads: 1.5}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: world.threads: 1.5 is not a whole number"},
        {"world: {dimension: 4}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: world.dimension: expected 2 or 3, got '4'"},
        {"world: {dimension: 3\nstop: {time: 1}\n", NULL,
         "t.yaml:2: did not find expected ',' or '}'"},
        {"materials: {steel: {}}\npairs:\n  - materials: [steel, iron]\nstop: {time: 1}\n", NULL,
         "t.yaml:3: pairs.0.materials.1: expected a material of 'materials' (steel), got 'iron'"},
        {"wrld: {}\n", NULL, "t.yaml:1: wrld: unknown key (did you mean 'world'?)"},
        {"world: {}\n", NULL, "t.yaml:1: missing 'stop' (time, revolutions, empty or steady)"},
        {"a: &x 1\nb: *x\n", NULL, "t.yaml:1: anchors, aliases and tags are not allowed in a scene file"},
        {"stop: {time: 1}\nstop: {time: 2}\n", NULL, "t.yaml:2: key 'stop' given twice"},
        {"{[1]: 2}\n", NULL, "t.yaml:1: a key must be a name, not a list"},
        {"stop: {time: -1}\n", NULL, "t.yaml:1: stop.time: expected a number > 0, got '-1'"},
        {"stop: {revolutions: 2}\n", NULL, "t.yaml:1: stop.revolutions: revolutions need a drum"},
        {"materials: {m: {}}\ndrum: {material: m, lifters: 100}\nstop: {time: 1}\n", NULL,
         "t.yaml:2: drum.lifters: expected a number in [0, 64], got '100'"},
        {"materials: {m: {}}\ndrum: {material: m, speed: 1, speed_rpm: 2}\nstop: {time: 1}\n", NULL,
         "t.yaml:2: drum.speed_rpm: one speed only (speed, speed_rpm or speed_fraction)"},
        {"materials: {m: {}}\ndrum: {material: m}\nstop: {revolutions: 1}\n", NULL,
         "t.yaml:3: stop.revolutions: the drum has no speed (speed, speed_rpm or speed_fraction)"},
        {"materials: {m: {}}\nparticles:\n  - {material: m, region: drum, sizes: {classes: [[0.01, 1]]}, "
         "count: 3}\nstop: {time: 1}\n",
         NULL, "t.yaml:3: particles.0.region: the region drum needs a 'drum' section"},
        {"materials: {m: {}}\nparticles:\n  - {material: m, region: {box: [0, 0, 0, 1, 1]}, sizes: "
         "{classes: [[0.01, 1]]}, count: 3}\nstop: {time: 1}\n",
         NULL, "t.yaml:3: particles.0.region.box: expected a list of 6 numbers, got a list"},
        {"materials: {m: {}}\nparticles:\n  - {material: m, csv: none.csv}\nstop: {time: 1}\n", NULL,
         NULL /* the path is the test's folder: checked below */},
        {"materials: {m: {}}\nwalls:\n  - {material: m, plane: {point: [0, 0, 0], normal: [0, 0, 0]}}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:3: walls.0.plane: normal has zero length"},
        {"outputs: {columns: [drum.power]}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.columns.0: a drum quantity without a drum"},
        {"outputs: {pictures: [series]}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.pictures.0: the series picture draws outputs.columns, which are not "
         "given"},
        {"outputs: {pictures: [seris]}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.pictures.0: expected charge, power or series, got 'seris'"},
        {"outputs: {columns: [outlet.0.mass]}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.columns.0: 'outlet.0.mass': the scene has 0 outlets"},
        {"outputs: {columns: [outlet.0.weight]}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.columns.0: expected a world.* or drum.* quantity of the parameter "
         "registry (e.g. world.time, drum.power), body.NAME.FIELD_x (FIELD position, velocity, "
         "force_particles, force_spring, force_damper or force_external), outlet.N.mass, "
         "outlet.N.count, particles.centre_x or energy.NAME (NAME a term of the energy account, "
         "e.g. dissipated_normal), got 'outlet.0.weight'"},
        {"outputs: {discharge: {outlet: 0, orifice_diameter: 0.04, bulk_region: {box: [0, 0, 0, 1, "
         "1, 1]}}}\nstop: {time: 1}\n",
         NULL,
         "t.yaml:1: outputs.discharge.outlet: expected the index of one of the scene's 0 outlets, "
         "got '0'"},
        {"outputs: {amplitude: {of: [world.time], window: 1}}\nstop: {steady: {quantity: "
         "world.time, window: 1, tolerance: 1}}\n",
         NULL, "t.yaml:2: stop: outputs.amplitude needs a stop.time (its window ends there)"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, sphere: [[0, 0, 0, 1]]}}\nstop: {time: 1}\n",
         NULL, "t.yaml:2: templates.r.sphere: unknown key (did you mean 'spheres'?)"},
        {"materials: {m: {}}\ntemplates: {r: {material: m}}\nstop: {time: 1}\n", NULL,
         "t.yaml:2: templates.r: expected either spheres or stl"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 1]]}}\nstop: {time: 1}\n",
         NULL, "t.yaml:2: templates.r.spheres.0: expected a list of 4 numbers, got a list"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0]]}}\nstop: {time: 1}\n",
         NULL, "t.yaml:2: templates.r.spheres: radius 0 = 0 must be > 0"},
        {"world: {dimension: 2}\nmaterials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 1, "
         "1]]}}\nstop: {time: 1}\n",
         NULL, "t.yaml:3: templates.r.spheres: centre 0 has z = 1 but the world is 2D"},
        {"world: {dimension: 2}\nmaterials: {m: {}}\ntemplates: {r: {material: m, stl: {file: r.stl, "
         "spheres: 5}}}\nstop: {time: 1}\n",
         NULL, "t.yaml:3: templates.r.stl: a template from a mesh needs a 3D world"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, stl: {file: r.stl, spheres: 2.5}}}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:2: templates.r.stl.spheres: expected a whole number in [1, 1e+06], got '2.5'"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, stl: {file: r.stl, spheres: 5, cells: 300}}}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:2: templates.r.stl.cells: expected a whole number in [4, 256], got '300'"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0.01]]}}\nparticles:\n"
         "  - {template: q, region: {box: [0, 0, 0, 1, 1, 1]}, count: 2}\nstop: {time: 1}\n",
         NULL, "t.yaml:4: particles.0.template: expected a template of 'templates' (r), got 'q'"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0.01]]}}\nparticles:\n"
         "  - {template: r, material: m, region: {box: [0, 0, 0, 1, 1, 1]}, count: 2}\nstop: {time: 1}\n",
         NULL, "t.yaml:4: particles.0: a fill of clumps has no material, sizes or csv: its templates "
               "give them"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0.01]]}}\nparticles:\n"
         "  - {template: [[r, 0.5], [r, 0.5]], region: {box: [0, 0, 0, 1, 1, 1]}, count: 2}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:4: particles.0.template.1.0: template 'r' given twice"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0.01]]}}\nparticles:\n"
         "  - {template: [[r, 0]], region: {box: [0, 0, 0, 1, 1, 1]}, mass: 2}\nstop: {time: 1}\n",
         NULL, "t.yaml:4: particles.0.template: the mass fractions sum to 0"},
        {"materials: {m: {}}\ntemplates: {r: {material: m, spheres: [[0, 0, 0, 0.3]]}}\nparticles:\n"
         "  - {template: r, region: {box: [0, 0, 0, 1, 1, 1]}, count: 20}\nstop: {time: 1}\n",
         NULL, "t.yaml:4: particles.0.template: only 1 of 20 clumps fit in the region: no free place "
               "among 4096 candidates"},
        {"materials: {m: {}}\nwalls:\n  - {material: m, plane: {point: [0, 0, 0], normal: [0, 1, 0]}, "
         "motion: {velocity: [1, 0, 0], start: -1}}\nstop: {time: 1}\n",
         NULL, "t.yaml:3: walls.0.motion.start: expected a number >= 0, got '-1'"},
        {"bodies: {lid: {mass: 1, force: {amplitude: [0, 1, 0], frequency: 0}, load: {force: [0, -1, "
         "0]}}}\nstop: {time: 1}\n",
         NULL, "t.yaml:1: bodies.lid.load: a body has a force or a load, not both"},
        {"materials: {m: {}}\nbodies: {lid: {mass: 1}}\nwalls:\n  - {material: m, plane: {point: [0, "
         "0, 0], normal: [0, 1, 0]}}\noutputs: {shear: {wall: 0, held: [lid], lid: lid, area: 1}}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:5: outputs.shear.wall: wall 0 has no motion.velocity to shear the sample with"},
        {"bodies: {lid: {mass: 1}}\noutputs: {shear: {wall: 0, held: [lid], lid: lid, area: 1}}\n"
         "stop: {time: 1}\n",
         NULL, "t.yaml:2: outputs.shear.wall: expected the index of one of the scene's 0 walls, got '0'"},
        {"materials: {m: {}}\nbodies: {lid: {mass: 1}}\nwalls:\n  - {material: m, plane: {point: [0, "
         "0, 0], normal: [0, 1, 0]}, motion: {velocity: [1, 0, 0]}}\noutputs: {shear: {wall: 0, held: "
         "[box], lid: lid, area: 1}}\nstop: {time: 1}\n",
         NULL, "t.yaml:5: outputs.shear.held.0: expected a body of 'bodies', got 'box'"},
        {"outputs: {conveyor: {feed: 0, outlet: 0, from: 1}}\nstop: {time: 1}\n", NULL,
         "t.yaml:1: outputs.conveyor: the conveyor needs a belt: a wall with a surface_velocity"},
        {"materials: {m: {}}\nwalls:\n  - {material: m, plane: {point: [0, 0, 0], normal: [0, 1, 0]}, "
         "surface_velocity: [1, 0, 0]}\n  - {material: m, plane: {point: [0, 1, 0], normal: [0, -1, "
         "0]}, surface_velocity: [2, 0, 0]}\noutputs: {conveyor: {feed: 0, outlet: 0, from: 1}}\n"
         "stop: {time: 1}\n",
         NULL,
         "t.yaml:4: walls.1.surface_velocity: expected the surface velocity of the belt's other "
         "walls"},
        {"materials: {m: {}}\nwalls:\n  - {material: m, plane: {point: [0, 0, 0], normal: [0, 1, 0]}, "
         "surface_velocity: [1, 0, 0]}\noutputs: {conveyor: {feed: 0, outlet: 0, from: 1}}\nstop: "
         "{time: 1}\n",
         NULL, "t.yaml:4: outputs.conveyor.feed: expected the index of one of the scene's 0 feeds, got '0'"},
#define SILO_WALLS "materials: {m: {}}\nwalls:\n  - {material: m, plane: {point: [0, 0, 0], normal: " \
                   "[0, 1, 0]}}\n  - {material: m, cylinder: {point: [0, 0, 0], axis: "
#define SILO_JANSSEN "radius: 0.05, length: 0.5}}\noutputs: {janssen: {wall: 1, floor: 0, band: 0.01, " \
                     "zone: [0, 0.1], window: 0.1}}\n"
        {SILO_WALLS "[1, 0, 0], " SILO_JANSSEN "stop: {time: 1}\n", NULL,
         "t.yaml:5: outputs.janssen.wall: the cylinder's axis is not along gravity"},
        {SILO_WALLS "[0, 1, 0], " SILO_JANSSEN "stop: {time: 1}\n", "outputs.janssen.wall=0",
         "--set outputs.janssen.wall: walls.0 is not a cylinder"},
        {SILO_WALLS "[0, 1, 0], " SILO_JANSSEN "stop: {time: 1}\n", "outputs.janssen.floor=1",
         "--set outputs.janssen.floor: walls.1 is not a plane or a disc"},
        {SILO_WALLS "[0, 1, 0], " SILO_JANSSEN "stop: {time: 1}\n", "outputs.janssen.zone=[0.1, 0.1]",
         "--set outputs.janssen.zone: expected two heights above the floor, 0 <= from < to, more "
         "than a band apart"},
        {SILO_WALLS "[0, 1, 0], " SILO_JANSSEN "stop: {empty: {box: [0, 0, 0, 1, 1, 1]}}\n", NULL,
         "t.yaml:5: outputs.janssen: needs a stop.time (its window ends there)"},
        {"materials: {m: {}}\nstop: {time: 1}\n", "materials.m.restitution=high",
         "--set materials.m.restitution: expected a number in [0, 1], got 'high'"},
        {"world: {}\nstop: {time: 1}\n", "world.gravity=[0, x, 0]",
         "--set world.gravity.1: expected a number, got 'x'"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *got = failure(cases[k].yaml, cases[k].set);
        if (cases[k].message)
            ck_assert_msg(!strcmp(got, cases[k].message), "case %zu: got \"%s\", want \"%s\"", k, got,
                          cases[k].message);
        else
            ck_assert_msg(strstr(got, "t.yaml:3: particles.0.csv: cannot open ") && strstr(got, "none.csv"),
                          "case %zu: got \"%s\"", k, got);
    }
}
END_TEST

/* every key of the registry's groups is a scene key, under its own name,
 * in its group's table */
START_TEST(test_keys)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    scene_list_keys(f);
    fclose(f);
    static const struct {
        int32_t first, last;
        const char *section;
    } groups[] = {{100, 149, "#### world\n"}, {200, 299, "#### materials.NAME\n"},
                  {300, 399, "#### pairs[]\n"}, {400, 449, "#### drum\n"}};
    for (size_t g = 0; g < 4; g++) {
        const char *table = strstr(text, groups[g].section);
        ck_assert_ptr_nonnull(table);
        const char *end = strstr(table + 1, "####");
        int count = 0;
        for (int32_t key = groups[g].first; key <= groups[g].last; key++) {
            const char *name = demill_param_name(key);
            if (!name)
                continue;
            char row[80];
            snprintf(row, sizeof row, "\n| `%s` | %s |", strchr(name, '.') + 1,
                     strcmp(demill_param_unit(key), "enum") ? demill_param_unit(key) : "choice");
            const char *at = strstr(table, row);
            ck_assert_msg(at && (!end || at < end), "%s missing from `demill keys`", name);
            count++;
        }
        ck_assert_int_gt(count, 0);
    }
    free(text);
}
END_TEST

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/demill-reader-XXXXXX");
    if (!mkdtemp(dir))
        return 1;
    Suite *s = suite_create("scene_reader");
    TCase *tc = tcase_create("reader");
    tcase_add_test(tc, test_good);
    tcase_add_test(tc, test_set);
    tcase_add_test(tc, test_auto_time_step);
    tcase_add_test(tc, test_drum);
    tcase_add_test(tc, test_2d);
    tcase_add_test(tc, test_clumps);
    tcase_add_test(tc, test_bad);
    tcase_add_test(tc, test_keys);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_set_fork_status(sr, CK_NOFORK);
    srunner_run_all(sr, CK_NORMAL);
    const int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    if (system(cmd))
        return 1;
    return failed ? 1 : 0;
}
