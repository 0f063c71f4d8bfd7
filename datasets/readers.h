/*
 * readers.h -- the .ply and .obj point readers (datasets/readers.c), and
 * the format of a file by its extension.
 *
 * dd_read_points (datasets.h) dispatches to these by extension; they read
 * from a stream so that the fuzz targets can feed them memory.  Same
 * contract as dd_read_points: on success *xyz is malloc'd (never NULL,
 * even for 0 points) with 3 * *np finite doubles, the input index is the
 * vertex's order in the file; on failure *xyz is NULL, *np is 0 and msg
 * names the file, the line (text) or byte offset (binary) and the problem.
 */
#ifndef DD_READERS_H
#define DD_READERS_H

#include <stdint.h>
#include <stdio.h>
#include "../src/dtdel.h"

typedef enum dd_format {
    DD_FORMAT_XYZ, DD_FORMAT_OFF, DD_FORMAT_PLY, DD_FORMAT_OBJ,
    DD_FORMAT_XYZW,            /* x y z w per line (datasets.c)        */
    DD_FORMAT_XYZR             /* x y z radius per line, w = radius^2  */
} dd_format;

/* The format named by the path's extension (case-insensitive): .off,
 * .ply, .obj, .xyzw, .xyzr; anything else is .xyz.                       */
dd_format dd_format_of(const char *path);

/* .ply: ascii, binary_little_endian or binary_big_endian 1.0.  The points
 * are the x, y, z properties of the `vertex` element, of any numeric type
 * (char uchar short ushort int uint float double, int8 ... float64).
 * Other properties and elements (faces) are skipped, list properties
 * included; their counts must still agree with the body: a header count
 * the file cannot hold, a truncated body, data after the last element,
 * a malformed line, and NaN or infinite coordinates are errors
 * (DD_ERR_PARSE, DD_ERR_NAN, DD_ERR_INFINITE; DD_ERR_IO on a read error;
 * DD_ERR_NOMEM).  A header count is checked against the file's size (when
 * the stream has one) before anything is allocated for it.              */
dd_status dd_read_ply(FILE *f, const char *name, double **xyz, uint32_t *np,
                      char *msg, size_t msglen);
/* The same, and the vertex property `weight` (or `radius`, the weight
 * being radius^2; both in one file is an error) into *w: n doubles, or
 * NULL when the vertex element has neither.  A NaN or infinite weight
 * or radius, a negative radius, or one whose square overflows is an
 * error naming the vertex (DD_ERR_NAN, DD_ERR_INFINITE, DD_ERR_PARSE).  */
dd_status dd_read_ply_weighted(FILE *f, const char *name, double **xyz, double **w, uint32_t *np,
                               char *msg, size_t msglen);

/* .obj: the points are the `v x y z [w]` lines (w ignored; further
 * numbers, as vertex colours, ignored); every other line (vn, vt, f, g,
 * o, usemtl, ...) and '#' comments are ignored.                          */
dd_status dd_read_obj(FILE *f, const char *name, double **xyz, uint32_t *np,
                      char *msg, size_t msglen);

#endif
