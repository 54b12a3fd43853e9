/* vtk.c: the VTK writers' errors, and that writing changes nothing.
 *
 * (What the files hold is read back with VTK itself by vtk_readback.py.)
 * Checked:
 *  - NULL world, path, prefix, out and series give DEMILL_ERR_NULL_POINTER,
 *    a prefix without a file name part DEMILL_ERR_INVALID_VALUE;
 *  - a file in a directory that does not exist gives DEMILL_ERR_IO with the
 *    path and the system's reason in the message, for the particles, the
 *    walls and a series (which is then not opened: *out is NULL);
 *  - a write that fails after the file was opened (/dev/full: no space
 *    left) gives DEMILL_ERR_IO too, the data being checked to the end;
 *  - a frame whose file cannot be written is not added: the .pvd stays as
 *    it was, no temporary file is left, and the next frame reuses the
 *    number;
 *  - none of it changes the world: a run that writes files (and fails to)
 *    between its steps ends bitwise where a run that does not ends, with
 *    the watchdog on, and a successful write leaves the last-error message.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, mkdir, rmdir */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"

static char dir[64];

static const char *in_dir(const char *name)
{
    static char buf[2][256];
    static int k;
    k ^= 1;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static void make_dir(void)
{
    snprintf(dir, sizeof dir, "%s", "/tmp/demill-io-vtk-XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(dir));
}

static void remove_dir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    ck_assert_int_eq(system(cmd), 0);
}

/* A 3D world with a drum, a plane and a few particles about to hit the drum. */
static demill_world *scene(demill_id *ids)
{
    demill_world *w;
    demill_id m, drum, floor;
    ck_assert_int_eq(demill_world_create(3, &w), DEMILL_OK);
    DM_OK(w, demill_material_create(w, &m));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_NORMAL, DEMILL_NORMAL_HERTZ));
    DM_OK(w, demill_pair_set(w, m, m, DEMILL_PAIR_TANGENTIAL, DEMILL_TANGENTIAL_MINDLIN));
    DM_OK(w, demill_drum_create(w, m, &drum));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTER_PHASE, 0.0));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_LIFTERS, 3));
    DM_OK(w, demill_drum_set(w, drum, DEMILL_DRUM_SPEED, 1.0));
    const double p[3] = {0, -0.2, 0}, n[3] = {0, 1, 0};
    DM_OK(w, demill_wall_add_plane(w, m, p, n, &floor));
    /* 5 mm above the shell, falling at 1 m/s */
    double x[9] = {0, -0.135, 0, 0.025, -0.135, 0.01, -0.025, -0.135, -0.01};
    double r[3] = {0.01, 0.01, 0.01}, v[9] = {0, -1, 0, 0, -1, 0, 0.1, -1, 0};
    DM_OK(w, demill_particles_add(w, m, 3, x, r, v, DEMILL_ADD_NO_OVERLAP, ids));
    return w;
}

static void assert_io(demill_world *w, demill_status got, const char *path, const char *reason)
{
    const char *msg = demill_world_last_error(w);
    ck_assert_msg(got == DEMILL_ERR_IO, "%s: returned %d, expected DEMILL_ERR_IO (%s)", path,
                  (int)got, msg);
    ck_assert_msg(strstr(msg, path), "message \"%s\" does not name %s", msg, path);
    ck_assert_msg(strstr(msg, reason), "message \"%s\" does not say \"%s\"", msg, reason);
}

START_TEST(null_arguments)
{
    demill_id ids[3];
    demill_world *w = scene(ids);
    demill_vtk_series *s = (demill_vtk_series *)&s;
    ck_assert_int_eq(demill_vtk_write_particles(NULL, "x.vtu"), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_vtk_write_walls(NULL, "x.vtp"), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_vtk_series_open(NULL, "x", &s), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_vtk_series_write(NULL, s), DEMILL_ERR_NULL_POINTER);
    ck_assert_int_eq(demill_vtk_write_particles(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "path"));
    ck_assert_int_eq(demill_vtk_write_walls(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "path"));
    ck_assert_int_eq(demill_vtk_series_open(w, NULL, &s), DEMILL_ERR_NULL_POINTER);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "prefix"));
    ck_assert_int_eq(demill_vtk_series_open(w, "x", NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "out"));
    ck_assert_int_eq(demill_vtk_series_write(w, NULL), DEMILL_ERR_NULL_POINTER);
    ck_assert_ptr_nonnull(strstr(demill_world_last_error(w), "series"));
    static const char *const no_name[] = {"", "out/", "/"};
    for (int k = 0; k < 3; k++) {
        s = (demill_vtk_series *)&s;
        ck_assert_int_eq(demill_vtk_series_open(w, no_name[k], &s), DEMILL_ERR_INVALID_VALUE);
        ck_assert_ptr_null(s);
    }
    demill_vtk_series_close(NULL);
    demill_world_destroy(w);
}
END_TEST

START_TEST(unwritable_paths)
{
    demill_id ids[3];
    demill_world *w = scene(ids);
    DM_OK(w, demill_world_step(w, 10));
    const char *missing = "/nonexistent-demill-dir/frame.vtu";
    assert_io(w, demill_vtk_write_particles(w, missing), missing, "No such file or directory");
    assert_io(w, demill_vtk_write_walls(w, missing), missing, "No such file or directory");
    demill_vtk_series *s = (demill_vtk_series *)&s;
    assert_io(w, demill_vtk_series_open(w, "/nonexistent-demill-dir/mill", &s),
              "/nonexistent-demill-dir/mill.pvd", "No such file or directory");
    ck_assert_ptr_null(s);
    if (access("/dev/full", W_OK) == 0) { /* opens, then has no room */
        assert_io(w, demill_vtk_write_particles(w, "/dev/full"), "/dev/full",
                  "No space left on device");
        assert_io(w, demill_vtk_write_walls(w, "/dev/full"), "/dev/full",
                  "No space left on device");
    }
    demill_world_destroy(w);
}
END_TEST

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static size_t count(const char *text, const char *what)
{
    size_t n = 0;
    for (const char *p = strstr(text, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

START_TEST(failed_frame_is_not_listed)
{
    demill_id ids[3];
    demill_world *w = scene(ids);
    make_dir();
    demill_vtk_series *s;
    DM_OK(w, demill_vtk_series_open(w, in_dir("mill"), &s));
    ck_assert_uint_eq(count(slurp(in_dir("mill.pvd")), "<DataSet"), 0);
    DM_OK(w, demill_vtk_series_write(w, s));
    DM_OK(w, demill_world_step(w, 5));
    /* frame 1's walls file cannot be written: a directory is in its way */
    ck_assert_int_eq(mkdir(in_dir("mill_walls_000001.vtp"), 0700), 0);
    assert_io(w, demill_vtk_series_write(w, s), in_dir("mill_walls_000001.vtp"), "directory");
    const char *pvd = slurp(in_dir("mill.pvd"));
    ck_assert_uint_eq(count(pvd, "<DataSet"), 2);
    ck_assert_ptr_null(strstr(pvd, "000001"));
    ck_assert(!exists(in_dir("mill.pvd.tmp")));
    ck_assert_int_eq(rmdir(in_dir("mill_walls_000001.vtp")), 0);
    DM_OK(w, demill_vtk_series_write(w, s));
    pvd = slurp(in_dir("mill.pvd"));
    ck_assert_uint_eq(count(pvd, "<DataSet"), 4);
    ck_assert_uint_eq(count(pvd, "mill_walls_000001.vtp"), 1);
    ck_assert_uint_eq(count(pvd, "mill_particles_000001.vtu"), 1);
    ck_assert(!exists(in_dir("mill_particles_000002.vtu")));
    ck_assert(!exists(in_dir("mill.pvd.tmp")));
    demill_vtk_series_close(s);
    demill_world_destroy(w);
    remove_dir();
}
END_TEST

/* Every particle's position, velocity and angular velocity, in id order. */
static void state(demill_world *w, double out[27])
{
    const int32_t f[3] = {DEMILL_PARTICLE_POSITION, DEMILL_PARTICLE_VELOCITY,
                          DEMILL_PARTICLE_ANGULAR_VELOCITY};
    size_t n;
    for (int k = 0; k < 3; k++)
        DM_OK(w, demill_particles_read(w, f[k], out + 9 * k, 3, &n));
}

START_TEST(writing_changes_nothing)
{
    demill_id ids[3], twin_ids[3];
    demill_world *w = scene(ids), *twin = scene(twin_ids);
    make_dir();
    demill_vtk_series *s;
    DM_OK(w, demill_vtk_series_open(w, in_dir("run"), &s));
    int touched = 0; /* so that contacts with their history were written too */
    for (int k = 0; k < 6; k++) {
        DM_OK(w, demill_world_step(w, 150));
        DM_OK(twin, demill_world_step(twin, 150));
        demill_world_get(w, -1, NULL); /* an error message, which a write leaves */
        char before[1024];
        snprintf(before, sizeof before, "%s", demill_world_last_error(w));
        DM_OK(w, demill_vtk_series_write(w, s));
        DM_OK(w, demill_vtk_write_particles(w, in_dir("one.vtu")));
        DM_OK(w, demill_vtk_write_walls(w, in_dir("one.vtp")));
        ck_assert_str_eq(demill_world_last_error(w), before);
        ck_assert_int_eq(demill_vtk_write_walls(w, "/nonexistent-demill-dir/x.vtp"),
                         DEMILL_ERR_IO);
        double c;
        DM_OK(w, demill_world_get(w, DEMILL_WORLD_WALL_CONTACT_COUNT, &c));
        touched |= c > 0;
    }
    double a[27], b[27];
    state(w, a);
    state(twin, b);
    ck_assert_msg(!memcmp(a, b, sizeof a), "writing files changed the run");
    double ta, tb;
    DM_OK(w, demill_world_get(w, DEMILL_WORLD_TIME, &ta));
    DM_OK(twin, demill_world_get(twin, DEMILL_WORLD_TIME, &tb));
    ck_assert(ta == tb);
    ck_assert_msg(touched, "the balls never hit the drum");
    demill_vtk_series_close(s);
    demill_world_destroy(w);
    demill_world_destroy(twin);
    remove_dir();
}
END_TEST

int main(void)
{
    Suite *s = suite_create("io_vtk");
    TCase *tc = tcase_create("vtk");
    tcase_add_test(tc, null_arguments);
    tcase_add_test(tc, unwritable_paths);
    tcase_add_test(tc, failed_frame_is_not_listed);
    tcase_add_test(tc, writing_changes_nothing);
    suite_add_tcase(s, tc);
    return dm_test_run(s);
}
