/*
 * bench.h -- the benchmark harness: the bench commands, which the
 * dispatcher (src/cli/cli.c) runs from its table, and what they share
 * beyond tool.h: numeric options, the --dataset and --seed of the
 * commands that generate their points, the generated points, and the
 * comparison with a CGAL triangulation of the query benches.
 *
 * Its layer is between src/tool/ and src/cli/ (scripts/layers.sh): it
 * uses the public headers, datasets/, src/cgal/ and src/tool/, never
 * src/cli/.
 */
#ifndef DD_BENCH_H
#define DD_BENCH_H

#include "tool/tool.h"

/* A numeric option of a bench command: its flag, or NULL for the
 * positional N, and where its value goes.                               */
typedef struct num_opt {
    const char *flag;
    uint64_t *dst;
} num_opt;
/* Parses argv[1..argc) into opts[0..n): each a number at most 5e7;
 * 0, or usage_error's status naming the option.                         */
int parse_num_opts(const char *cmd, int argc, char **argv, const num_opt *opts, int n);
/* --seed S and --dataset NAME of the commands that generate their points
 * (build-bench, seq-bench): 1 when argv[*i] is one of them (taken, *i on
 * its value; *rc a usage error when that is missing or bad, else 0), 0
 * when it is neither.                                                    */
int take_dataset_option(const char *cmd, int argc, char **argv, int *i, const char **dataset, uint64_t *seed,
                        int *rc);
/* Points of a generated dataset (dd_gen); 0, or the exit status after a
 * message on stderr: EXIT_USAGE for an unknown dataset, else EXIT_INPUT. */
int gen_points(const char *cmd, const char *dataset, uint64_t n, uint64_t seed, double **xyz, uint32_t *np);
/* Whether t's triangulation is the CGAL one's (cgal/cgal_query.h),
 * simplex for simplex.                                                  */
struct dd_cgalq;
int same_as_cgalq(dd_tri *t, const struct dd_cgalq *g);

/* build-bench --threads N (pbuild_bench.c): the parallel rows; 0 or an
 * exit status.                                                          */
int build_bench_threads(const char *dataset, uint64_t n, uint64_t seed, unsigned threads, unsigned reps);

/* The bench commands (dtdel COMMAND --help): argc and argv from the
 * command's name on; an exit status, or EXIT_SHOW_USAGE.                */
int cmd_bench(int argc, char **argv);
int cmd_seq_bench(int argc, char **argv);
int cmd_build_bench(int argc, char **argv);
int cmd_edit_bench(int argc, char **argv);
int cmd_query_bench(int argc, char **argv);
int cmd_batch_bench(int argc, char **argv);
int cmd_refine_bench(int argc, char **argv);
int cmd_regular_bench(int argc, char **argv);
int cmd_wbench(int argc, char **argv);
int cmd_wedits_bench(int argc, char **argv);

#endif
