/* loads.c: the loads a wall records for wear and pressure maps
 * (docs/geometry.md, Wall loads): their storage, one block per wall, and the
 * elements they are kept for (a mesh's triangles, a polyline's segments, else
 * the wall as one patch) with each element's area. contact/forces.c sums
 * them after each step. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "physics/geometry/geometry.h"

uint32_t dm_loads_elements(const dm_wall *wall)
{
    return wall->mesh ? wall->mesh->nt : 1;
}

dm_loads *dm_loads_new(uint32_t n)
{
    dm_loads *l = calloc(1, sizeof *l + DM_LOADS * (size_t)n * sizeof *l->v);
    if (l)
        l->n = n;
    return l;
}

dm_loads *dm_loads_copy(const dm_loads *src)
{
    const size_t bytes = sizeof *src + DM_LOADS * (size_t)src->n * sizeof *src->v;
    dm_loads *l = malloc(bytes);
    if (l)
        memcpy(l, src, bytes);
    return l;
}

void dm_loads_free(dm_loads *l)
{
    free(l);
}

double dm_loads_normal(const dm_loads *l, uint32_t e)
{
    const double *v = l->v + DM_LOADS * (size_t)e;
    return v[3] == l->steps ? v[0] : 0.0;
}

/* |b - a|, and with c the area of the triangle (a, b, c). */
static double span(const double *a, const double *b, const double *c)
{
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    if (!c)
        return sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double g[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    return 0.5 * sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

/* The area of one face of a finite wall: a surface of revolution (its
 * meridian segment turned about the axis: π (ρ0 + ρ1) times the segment's
 * length, a frustum's lateral area, which for a flat annulus is
 * π (ρ1² − ρ0²)) or a rectangle. */
static double face_area(const dm_wall *wall)
{
    if (wall->kind == DM_WALL_RECT)
        return 4.0 * wall->seg[0] * wall->seg[1];
    const double *s = wall->seg;
    return DM_PI * (s[0] + s[2]) * hypot(s[2] - s[0], s[3] - s[1]);
}

double dm_loads_area(const demill_world *w, uint32_t slot, uint32_t e)
{
    const dm_wall *wall = &w->walls[slot];
    if (wall->mesh) {
        const dm_trimesh *m = wall->mesh;
        const uint32_t *el = m->el + (size_t)m->nel * e;
        return span(m->v + 3 * (size_t)el[0], m->v + 3 * (size_t)el[1],
                    m->nel == 3 ? m->v + 3 * (size_t)el[2] : NULL);
    }
    if (wall->kind != DM_WALL_REVOLVED && wall->kind != DM_WALL_RECT)
        return NAN; /* a plane: unbounded */
    double area = face_area(wall);
    for (int q = 0; q < 2; q++)
        if (wall->parts[q])
            area += face_area(&w->walls[wall->parts[q] - 1]);
    return area;
}
