/* stl_write.h: STL files written by the tests (tests/unit/stl.c) and by
 * the STL fuzzer's seeds (tests/fuzz/stl_seeds.c), from triangles given as
 * corners, and the unit cube they both write. */
#ifndef DEMILL_STL_WRITE_H
#define DEMILL_STL_WRITE_H

#include <stddef.h>
#include <stdint.h>

/* The unit cube [0, 1]^3: 12 triangles, 9 coordinates each (3 corners),
 * counter-clockwise seen from outside, so that the right-hand normal
 * (b - a) x (c - a) points out. */
extern const double dm_test_cube[12 * 9];

/* An ASCII STL file of nt triangles (corners c, 9 each), named name, each
 * facet's normal the unit right-hand normal of its corners (reversed when
 * flip is not NULL and flip[k] is not 0); numbers written with %.17g, in
 * the C locale's format. Returns a malloc'd buffer of *size bytes
 * (without a terminating 0 counted); exits on failure. */
uint8_t *dm_test_stl_ascii(const char *name, const double *c, size_t nt, const int *flip,
                           size_t *size);
/* A binary STL file of the same: header (up to 80 bytes, the rest 0), the
 * count, then each triangle's normal and corners as float32 and a zero
 * attribute. */
uint8_t *dm_test_stl_binary(const char *header, const double *c, size_t nt, const int *flip,
                            size_t *size);

#endif
