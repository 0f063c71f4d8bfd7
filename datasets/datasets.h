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

/* The name of dataset i in dd_gen's table (i = 0, 1, ...), NULL past it. */
const char *dd_dataset_name(size_t i);

/* Writes n points of dataset `name` into *xyz (3n doubles).  For real
 * models n is a maximum (0 = all vertices) and *np receives the count.
 * Unknown name: DD_ERR_PARSE; missing model archive: DD_ERR_IO.          */
dd_status dd_gen(const char *name, uint32_t n, uint64_t seed,
                 double **xyz, uint32_t *np, char *msg, size_t msglen);

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
