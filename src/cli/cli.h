/*
 * cli.h -- what the dtdel subcommands share: exit codes, argument parsing,
 * file loading, output, timing, and the "rows" of a comparison (the
 * engine's strategies plus CGAL's remove() and CGAL-rnd through the shim).
 */
#ifndef DD_CLI_H
#define DD_CLI_H

#include "dtdel.h"
#include "dtdel_stats.h"
#include "cgal/cgal_shim.h"
#include "datasets/datasets.h"

#include <stdint.h>
#include <stdio.h>

#define EXIT_INPUT 1
#define EXIT_USAGE 2

typedef struct command {
    const char *name;
    const char *usage;
    const char *help;
    int (*run)(int argc, char **argv);
} command;

/* Says "dtdel CMD: " and fmt (with arg) on stderr, then CMD's usage;
 * returns EXIT_USAGE.                                                   */
int usage_error(const char *cmd, const char *fmt, const char *arg);
/* 1 when an argument is --help or -h. */
int wants_help(int argc, char **argv);
/* Prints CMD's usage and help on stdout; returns 0. */
int print_help(const char *cmd);
/* Parses a non-negative decimal integer, all of s; 0 on success. */
int parse_u64(const char *s, uint64_t *out);
/* A numeric option of a bench command: its flag, or NULL for the
 * positional N, and where its value goes.                               */
typedef struct num_opt {
    const char *flag;
    uint64_t *dst;
} num_opt;
/* Parses argv[1..argc) into opts[0..n): each a number at most 5e7;
 * 0, or usage_error's status naming the option.                         */
int parse_num_opts(const char *cmd, int argc, char **argv, const num_opt *opts, int n);
/* Whether t's triangulation is the CGAL one's (cgal/cgal_query.h),
 * simplex for simplex.                                                  */
struct dd_cgalq;
int same_as_cgalq(dd_tri *t, const struct dd_cgalq *g);
/* A monotonic clock, in seconds. */
double now_seconds(void);
/* The points of FILE (.xyz or .off, dd_read_points); 0, or EXIT_INPUT
 * after a message naming the problem.                                   */
int load_file(const char *cmd, const char *path, double **xyz, uint32_t *np);
/* Reads FILE and builds its DT in *t; 0, or the exit status after a
 * message on stderr naming the file and the problem.                    */
int build_file(const char *cmd, const char *path, dd_tri **t);
/* The points and weights of FILE (dd_read_weighted: *w NULL for a file
 * without weights); 0, or EXIT_INPUT after a message.                   */
int load_weighted_file(const char *cmd, const char *path, double **xyz, double **w, uint32_t *np);
/* Reads FILE and builds its regular triangulation (its DT when it has no
 * weights) with dd_create_ex and flags; 0, or the exit status after a
 * message naming the file and the problem.                              */
int build_weighted_file(const char *cmd, const char *path, unsigned flags, dd_tri **t);
/* `cgal-tets FILE`: CGAL's canonical form on stdout (regular for weights,
 * discard selecting Discard_hidden_points); 0 or EXIT_INPUT.            */
int cgal_tets_file(const char *path, int discard);
/* A canonical form on stdout, one line "a b c d" a cell. */
void write_tets(const int32_t *tets, size_t n);

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
/* Whether two canonical forms are the same list of cells. */
int same_canonical(const int32_t *a, size_t na, const int32_t *b, size_t nb);
/* Points of a generated dataset (dd_gen); 0, or the exit status after a
 * message on stderr: EXIT_USAGE for an unknown dataset, else EXIT_INPUT. */
int gen_points(const char *cmd, const char *dataset, uint64_t n, uint64_t seed, double **xyz, uint32_t *np);
/* --seed S and --dataset NAME of the commands that generate their points
 * (build-bench, seq-bench): 1 when argv[*i] is one of them (taken, *i on
 * its value; *rc a usage error when that is missing or bad, else 0), 0
 * when it is neither.                                                    */
int take_dataset_option(const char *cmd, int argc, char **argv, int *i, const char **dataset, uint64_t *seed,
                        int *rc);
/* The seeded draws of the CLI (bench and check samples, seq-bench's
 * shuffle): one xorshift64 step of *x, then a number below m.  Its own
 * copy of the engine's dd_xorshift (mesh.h), which the CLI cannot see:
 * it uses the public headers only.                                     */
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

/* Subcommands living in other files. */
int cmd_delete(int argc, char **argv);
int cmd_time(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_seq_bench(int argc, char **argv);
int cmd_locate(int argc, char **argv);
int cmd_move(int argc, char **argv);
int cmd_edit_bench(int argc, char **argv);
int cmd_query_bench(int argc, char **argv);
int cmd_batch_bench(int argc, char **argv);
int cmd_refine_bench(int argc, char **argv);
int cmd_hidden(int argc, char **argv);
int cmd_cgal_hidden(int argc, char **argv);
int cmd_regular_bench(int argc, char **argv);
int cmd_wbench(int argc, char **argv);
int cmd_wedits_bench(int argc, char **argv);


#endif
