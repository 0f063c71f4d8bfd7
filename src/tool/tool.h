/*
 * tool.h -- what the two halves of the dtdel command share: the user's
 * commands (src/cli/) and the benchmark harness (src/bench/).  Exit
 * codes, usage errors, numbers, the monotonic clock, the seeded draws,
 * medians, and the "rows" of a comparison (the engine's strategies plus
 * CGAL's remove() and CGAL-rnd through the shim).
 *
 * Its layer is below both halves (scripts/layers.sh): it uses the public
 * headers, datasets/ and src/cgal/, never src/bench/ or src/cli/.  The
 * command table, with every command's usage and help, is the
 * dispatcher's (src/cli/cli.c), so a usage error here only says what is
 * wrong and leaves the usage line to it (EXIT_SHOW_USAGE).
 */
#ifndef DD_TOOL_H
#define DD_TOOL_H

#include "dtdel.h"
#include "dtdel_stats.h"
#include "cgal/cgal_shim.h"
#include "datasets/datasets.h"

#include <stdint.h>
#include <stdio.h>

#define EXIT_INPUT 1
#define EXIT_USAGE 2
/* What a command returns after a usage error: the dispatcher prints the
 * command's usage line and exits EXIT_USAGE.  Above every exit status
 * (0-255), so never one itself; commands pass it up unchanged.          */
#define EXIT_SHOW_USAGE (0x100 | EXIT_USAGE)

/* Says "dtdel CMD: " and fmt (with arg) on stderr; returns
 * EXIT_SHOW_USAGE, for the dispatcher to add CMD's usage.               */
int usage_error(const char *cmd, const char *fmt, const char *arg);
/* Parses a non-negative decimal integer, all of s; 0 on success. */
int parse_u64(const char *s, uint64_t *out);
/* A monotonic clock, in seconds. */
double now_seconds(void);
/* Whether two canonical forms are the same list of cells. */
int same_canonical(const int32_t *a, size_t na, const int32_t *b, size_t nb);

/* A row of a comparison: an engine strategy, "cgal" or "cgal-rnd". */
typedef struct row {
    const char *name;
    int kind;            /* ROW_ENGINE, ROW_CGAL, ROW_CGAL_RND */
} row;
enum { ROW_ENGINE, ROW_CGAL, ROW_CGAL_RND };

/* Fills rows[] with every engine strategy then cgal, cgal-rnd; returns
 * the count (at most max).                                               */
size_t all_rows(row *rows, size_t max);
/* Looks a row up by name; 0 if unknown. */
int find_row(const char *name, row *out);
/* Deletes input vertex v in the row's triangulation (t for the engine, g
 * for CGAL); returns 0 on success.  Reinsert undoes it.                  */
int row_delete(const row *r, dd_tri *t, dd_cgal *g, uint32_t v, uint64_t seed);
int row_reinsert(const row *r, dd_tri *t, dd_cgal *g, uint32_t v);
/* The canonical form of the row's triangulation (malloc'd); 0 on
 * success.                                                              */
int row_canonical(const row *r, dd_tri *t, dd_cgal *g, int32_t **a, size_t *n);

/* The seeded draws of the commands (bench and check samples, seq-bench's
 * shuffle): one xorshift64 step of *x, then a number below m.  Its own
 * copy of the engine's dd_xorshift (mesh.h), which the commands cannot
 * see: they use the public headers only.                                */
static inline uint32_t rand_below(uint64_t *x, uint32_t m)
{
    *x ^= *x << 13; *x ^= *x >> 7; *x ^= *x << 17;
    return (uint32_t)((*x >> 11) % m);
}
/* A vertex of t among input indices below np not yet used (used[v] then
 * set), drawn with rand_below; t must have one left.                    */
uint32_t draw_vertex(const dd_tri *t, uint64_t *x, uint32_t np, unsigned char *used);
/* The median of a[0..n), n > 0; sorts a. */
double median_of(double *a, size_t n);

#endif
