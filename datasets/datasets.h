/*
 * datasets.h -- point-set generators (DESIGN section 9) and point-file
 * readers (.xyz, .off).
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
#include "../src/dtdel.h"

/* Writes n points of dataset `name` into *xyz (3n doubles).  For real
 * models n is a maximum (0 = all vertices) and *np receives the count.
 * Unknown name: DD_ERR_PARSE; missing model archive: DD_ERR_IO.          */
dd_status dd_gen(const char *name, uint32_t n, uint64_t seed,
                 double **xyz, uint32_t *np, char *msg, size_t msglen);

/* Reads a .xyz file (x y z per line; blank lines and lines starting with
 * '#' ignored) or an .off file (vertices only), chosen by the extension
 * (.off, else xyz).  Errors name the file and the line: DD_ERR_IO,
 * DD_ERR_PARSE, DD_ERR_NAN, DD_ERR_INFINITE.  No points: DD_OK, *np = 0. */
dd_status dd_read_points(const char *path, double **xyz, uint32_t *np,
                         char *msg, size_t msglen);

#endif
