/*
 * datasets.h -- point-set generators (DESIGN section 9) and point-file
 * readers (.xyz, .off; .ply, .obj in readers.c).
 *
 * Generators are deterministic functions of (name, n, seed).  Real models
 * are read from the data archive of Debian's libcgal-dev / libcgal-demo.
 * All functions return a dd_status (dtdel.h) and write a message naming
 * the problem into msg on failure.  Returned arrays are malloc'd; the
 * caller frees them.  On success *xyz is never NULL (even for 0 points);
 * on failure *xyz is NULL and *np is 0.  msg may be NULL.
 */
#ifndef DD_DATASETS_H
#define DD_DATASETS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "../src/dtdel.h"

/* The name of dataset i in dd_gen's table (i = 0, 1, ...), NULL past it;
 * the weighted datasets come last.                                       */
const char *dd_dataset_name(size_t i);

/* Writes n points of dataset `name` into *xyz (3n doubles).  For real
 * models n is a maximum (0 = all vertices) and *np receives the count.
 * Unknown name: DD_ERR_PARSE; missing model archive: DD_ERR_IO.          */
dd_status dd_gen(const char *name, uint32_t n, uint64_t seed,
                 double **xyz, uint32_t *np, char *msg, size_t msglen);

/* ---- weighted points (datasets/weighted.c, DESIGN 12) ----
 * Weighted datasets: wuniform-few, wuniform, wuniform-most (uniform in
 * the cube, weights (alpha n^(-1/3))^2 u for alpha 0.3, 1, 3: from few to
 * most points hidden), protecting (Mesh_3-like protecting balls along the
 * cube's edges, unweighted volume points), molecule (packed atoms, radii
 * 1.2-1.9, weight r^2), wgrid (integer grid, weights 0-2, equal positions
 * with different weights), wmoment, whelix (the curves, weights up to
 * twice the squared spacing; in convex position, so none hidden).  dd_gen
 * gives their points without the weights.                              */

/* The name of weighted dataset i (i = 0, 1, ...), NULL past the end. */
const char *dd_weighted_dataset_name(size_t i);
/* 1 if name is a weighted dataset. */
int dd_dataset_is_weighted(const char *name);
/* As dd_gen, and the weights in *w (n doubles, malloc'd); for a dataset
 * without weights, dd_gen's points and *w = NULL.                       */
dd_status dd_gen_weighted(const char *name, uint32_t n, uint64_t seed, double **xyz, double **w,
                          uint32_t *np, char *msg, size_t msglen);
/* As dd_read_points, and the weights in *w: .xyzw (x y z w per line),
 * .xyzr (x y z radius per line; weight = radius^2), .ply with a vertex
 * property `weight` or `radius`; *w = NULL for a file without weights
 * (any other format, a .ply without them).  Errors name the file, the
 * line (or byte offset) and the problem: a missing weight or radius
 * (DD_ERR_PARSE), NaN (DD_ERR_NAN), infinite or overflowing its square
 * (DD_ERR_INFINITE), a negative radius (DD_ERR_PARSE).  dd_read_points
 * reads the same files as unweighted, the fourth column ignored.        */
dd_status dd_read_weighted(const char *path, double **xyz, double **w, uint32_t *np, char *msg,
                           size_t msglen);
dd_status dd_read_weighted_stream(FILE *f, const char *name, double **xyz, double **w, uint32_t *np,
                                  char *msg, size_t msglen);

/* Reads a .xyz file (x y z per line; blank lines and lines starting with
 * '#' ignored), an .off file (vertices only), a .ply file (the vertex
 * element's x, y, z; ascii or binary) or an .obj file (the 'v' lines),
 * chosen by the extension (.off, .ply, .obj, else xyz; readers.h).
 * Errors name the file and the line (or byte offset in binary data):
 * DD_ERR_IO, DD_ERR_PARSE, DD_ERR_NAN, DD_ERR_INFINITE, DD_ERR_NOMEM.
 * No points: DD_OK, *np = 0.                                             */
dd_status dd_read_points(const char *path, double **xyz, uint32_t *np,
                         char *msg, size_t msglen);
/* The same from an open stream; `name` gives the format (its extension)
 * and names the input in messages.                                       */
dd_status dd_read_points_stream(FILE *f, const char *name, double **xyz,
                                uint32_t *np, char *msg, size_t msglen);

#endif
