/*
 * cli.c -- the dtdel command line: the command table and its dispatcher.
 * The command (src/cli/, src/bench/, src/tool/) is the only code that
 * prints to the user and picks exit codes: 0 success, 1 bad input, 2 bad
 * usage.  The table holds every command's usage and help; the dispatcher
 * answers --help and, when a command returns EXIT_SHOW_USAGE
 * (usage_error, src/tool/tool.h), prints its usage line.
 *
 *   dtdel gen DATASET N [--seed S]   points of a dataset as .xyz (.xyzw) on stdout
 *   dtdel tets FILE [--out F]        canonical DT(points of FILE), or a mesh file
 *                                    (the regular triangulation for weights)
 *   dtdel cgal-tets FILE             the same computed by CGAL
 *   dtdel variants                   the deletion strategies and CGAL rows
 *   (hidden, cgal-hidden: cli_regular.c; delete, time, check: cli_delete.c;
 *   locate, move: cli_locate.c; the bench commands: src/bench/)
 */
#include "cli/cli.h"
#include "bench/bench.h"
#include "dtdel/alloc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- gen ------------------------------------------------------------------ */

static int cmd_gen(int argc, char **argv)
{
    const char *name = NULL, *nstr = NULL;
    uint64_t n = 0, seed = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seed")) {
            if (++i >= argc || parse_u64(argv[i], &seed))
                return usage_error("gen", "--seed needs a non-negative integer%s", "");
        } else if (!name) name = argv[i];
        else if (!nstr) nstr = argv[i];
        else return usage_error("gen", "unexpected argument '%s'", argv[i]);
    }
    if (!name || !nstr) return usage_error("gen", "missing DATASET or N%s", "");
    if (parse_u64(nstr, &n) || n > UINT32_MAX / 4)
        return usage_error("gen", "N must be a non-negative integer, got '%s'", nstr);
    double *xyz = NULL, *w = NULL;
    uint32_t np = 0;
    char msg[512];
    dd_status s = dd_gen_weighted(name, (uint32_t)n, seed, &xyz, &w, &np, msg, sizeof msg);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel gen: %s\n", msg);
        return s == DD_ERR_PARSE ? EXIT_USAGE : EXIT_INPUT;
    }
    for (uint32_t i = 0; i < np; i++) {
        printf("%.17g %.17g %.17g", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        if (w) printf(" %.17g", w[i]);
        printf("\n");
    }
    dd_mfree(xyz);
    dd_mfree(w);
    return 0;
}

/* ---- tets ----------------------------------------------------------------- */

int load_file(const char *cmd, const char *path, double **xyz, uint32_t *np)
{
    char msg[512];
    dd_status s = dd_read_points(path, xyz, np, msg, sizeof msg);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel %s: %s\n", cmd, msg);
        return EXIT_INPUT;
    }
    return 0;
}

void write_tets(const int32_t *tets, size_t n)
{
    for (size_t k = 0; k < n; k++)
        printf("%d %d %d %d\n", tets[4 * k], tets[4 * k + 1], tets[4 * k + 2], tets[4 * k + 3]);
}

int build_file(const char *cmd, const char *path, dd_tri **t)
{
    double *xyz;
    uint32_t np;
    int rc = load_file(cmd, path, &xyz, &np);
    if (rc) return rc;
    char msg[512];
    dd_status s = dd_create(t, xyz, np, msg, sizeof msg);
    dd_mfree(xyz);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel %s: %s: %s\n", cmd, path, msg);
        return EXIT_INPUT;
    }
    return 0;
}

/* `tets FILE --out OUT [--ascii]`: the mesh file instead of the
 * canonical form.                                                       */
static int write_mesh_file(dd_tri *t, const char *out, unsigned wflags)
{
    const dd_status s = dd_write_ex(t, out, wflags);
    dd_free(t);
    if (s == DD_OK) return 0;
    if (s == DD_ERR_UNKNOWN_FORMAT) {
        fprintf(stderr, "dtdel tets: %s: unknown mesh format (the name must end in .vtu or .mesh)\n", out);
        return EXIT_USAGE;
    }
    fprintf(stderr, "dtdel tets: %s: %s\n", out, s == DD_ERR_IO ? "cannot write the file" : dd_status_name(s));
    return EXIT_INPUT;
}

static int cmd_tets(int argc, char **argv)
{
    const char *file = NULL, *out = NULL;
    unsigned flags = 0, wflags = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--out")) {
            if (++i >= argc) return usage_error("tets", "--out needs a file name%s", "");
            out = argv[i];
        } else if (!strcmp(argv[i], "--ascii")) {
            wflags |= DD_WRITE_ASCII;
        } else if (!strcmp(argv[i], "--discard-hidden")) {
            flags |= DD_DISCARD_HIDDEN;
        } else if (!file) {
            file = argv[i];
        } else {
            return usage_error("tets", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!file) return usage_error("tets", "expected one FILE%s", "");
    if (wflags && !out) return usage_error("tets", "--ascii needs --out%s", "");
    dd_tri *t;
    int rc = build_weighted_file("tets", file, flags, &t);
    if (rc) return rc;
    if (dd_num_duplicates(t))
        fprintf(stderr, "dtdel tets: note: %u duplicate points merged into their first occurrence\n",
                dd_num_duplicates(t));
    if (out) return write_mesh_file(t, out, wflags);
    int32_t *tets;
    size_t n;
    if (dd_canonical(t, &tets, &n) != DD_OK) {
        fprintf(stderr, "dtdel tets: out of memory\n");
        dd_free(t);
        return EXIT_INPUT;
    }
    write_tets(tets, n);
    dd_mfree(tets);
    dd_free(t);
    return 0;
}

static int cmd_cgal_tets(int argc, char **argv)
{
    const char *file = NULL;
    int discard = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--discard-hidden")) discard = 1;
        else if (!file) file = argv[i];
        else return usage_error("cgal-tets", "expected exactly one FILE%s", "");
    }
    if (!file) return usage_error("cgal-tets", "expected exactly one FILE%s", "");
    return cgal_tets_file(file, discard);
}

static int cmd_variants(int argc, char **argv)
{
    (void)argc;                 /* arguments other than --help are ignored */
    (void)argv;
    for (size_t i = 0; dd_variant_name(i); i++)
        printf("%-14s %s%s\n", dd_variant_name(i), dd_variant_description(i), i == 0 ? " [default]" : "");
    printf("%-14s %s\n", "cgal", "CGAL's own remove() (triangulate and sew), the reference");
    printf("%-14s %s\n", "cgal-rnd", "CGAL's temporary DT of the neighbours in random order, sewn in the shim");
    return 0;
}

/* ---- dispatch ------------------------------------------------------------- */

/* A command: its name, its usage line and help (dtdel NAME --help), and
 * what runs it, with argv from the name on.                             */
typedef struct command {
    const char *name;
    const char *usage;
    const char *help;
    int (*run)(int argc, char **argv);
} command;

static const command commands[] = {
    {"gen", "gen DATASET N [--seed S]",
     "Writes N points of DATASET as .xyz (x y z per line) to stdout.\n"
     "Datasets: moment, helix, uniform, sphere, grid, cosphere, layers,\n"
     "grid-perturbed, and real models (bunny, elephant, armadillo, ...; N is\n"
     "then a maximum, 0 = all).  Weighted datasets, written as .xyzw (x y z w\n"
     "per line): wuniform-few, wuniform, wuniform-most (few to most points\n"
     "hidden), protecting (Mesh_3-like protecting balls on the cube's edges),\n"
     "molecule (atoms, weight = radius^2), wgrid (integer grid and weights:\n"
     "power ties, equal positions), wmoment, whelix.", cmd_gen},
    {"tets", "tets FILE [--out OUT.vtu|OUT.mesh [--ascii]] [--discard-hidden]",
     "Writes the canonical form of DT(points in FILE) to stdout: one line\n"
     "'a b c d' per tetrahedron (finite and infinite), input indices sorted\n"
     "ascending, -1 for the infinite vertex, lines sorted.  FILE is read by\n"
     "its extension: .off (vertices; faces ignored), .ply (ascii or binary,\n"
     "either endian: the x, y, z of the vertex element), .obj (the 'v'\n"
     "lines), anything else .xyz (x y z per line, # comments); input index =\n"
     "0-based order of the points in the file.\n"
     "--out OUT: instead (nothing on stdout), the finite tetrahedra as a mesh\n"
     "file, by OUT's extension: .vtu (VTK XML, ParaView; point data\n"
     "'input_index'; binary, appended raw data) or .mesh (Medit, Gmsh); points\n"
     "in input index order, coordinates exact (dd_write).  Readable by meshio.\n"
     "--ascii: the .vtu's data arrays in ASCII (as a name ending .ascii.vtu).\n"
     "Weighted points: .xyzw (x y z w per line), .xyzr (x y z radius, weight =\n"
     "radius^2), .ply with a vertex property 'weight' or 'radius'; then the\n"
     "regular triangulation (dd_create_ex), hidden points kept, or forgotten\n"
     "with --discard-hidden (DD_DISCARD_HIDDEN).", cmd_tets},
    {"cgal-tets", "cgal-tets FILE [--discard-hidden]",
     "As tets, computed by CGAL (the reference; Regular_triangulation_3 for\n"
     "weighted points).", cmd_cgal_tets},
    {"hidden", "hidden FILE [--discard-hidden]",
     "The input indices of the hidden points of FILE's regular triangulation\n"
     "(weighted points, as tets reads them), sorted, one per line; none with\n"
     "--discard-hidden (forgotten) or for a file without weights.", cmd_hidden},
    {"cgal-hidden", "cgal-hidden FILE [--discard-hidden]",
     "As hidden, computed by CGAL's Regular_triangulation_3.", cmd_cgal_hidden},
    {"delete", "delete FILE --vertex I[,J,...] [--variant NAME] [--stats] [--set]",
     "Deletes the input vertices I, J, ... in that order from DT(points in\n"
     "FILE) and writes the canonical form (as tets).  NAME: an engine\n"
     "strategy (dtdel variants), cgal or cgal-rnd; default: the fastest.\n"
     "--set: as one set (dd_delete_set: the engine's own order, all or\n"
     "nothing).\n"
     "--stats: per deletion on stderr, cells built, fallbacks, location tests,\n"
     "link deletions by degree, gift wrapping's course and lifts (integer:\n"
     "every test exact in doubles) and its tests left to the exact\n"
     "predicates (and predicate counts in build/count/dtdel).", cmd_delete},
    {"time", "time FILE --vertex I --variant NAME [--repeat R]",
     "Prints one number: the median microseconds of deleting vertex I alone\n"
     "over R repetitions (default 5); the vertex is re-inserted, untimed,\n"
     "between repetitions, so each starts from DT(S).  NAME: an engine\n"
     "strategy, cgal or cgal-rnd; or insert, our re-insertion of vertex I\n"
     "alone, each repetition deleting it untimed first (the bench's insert\n"
     "row: deleting should cost at most twice that).", cmd_time},
    {"check", "check FILE [--variant NAME|all] [--deletions K] [--seed S] [--sequence]",
     "Deletes K sampled vertices (default 20), each from DT(S), with each\n"
     "variant (default all: the engine's strategies and cgal-rnd), and\n"
     "compares every result with CGAL's remove(), the reference (so cgal\n"
     "itself is no variant here); --sequence deletes them one after another\n"
     "without re-inserting.  Prints matched/total per variant; exit 1 on any\n"
     "mismatch.", cmd_check},
    {"locate", "locate FILE X Y Z",
     "Locates the point (X, Y, Z) in DT of FILE's points: prints 'cell: a b c\n"
     "d', the input indices of a cell whose closure holds it (-1: the infinite\n"
     "vertex, for a point outside the hull: a hull facet it sees), then\n"
     "'nearest: v', a vertex nearest to it.  Exact.", cmd_locate},
    {"move", "move FILE --vertex I --to X,Y,Z [--weight W] [--discard-hidden]",
     "Moves vertex I to (X, Y, Z) and writes the canonical form of the new\n"
     "triangulation (as delete does); exit 1 if the point is another\n"
     "vertex's or the move would leave only coplanar points.  Weighted\n"
     "points (.xyzw, ...): I keeps its weight, or takes W (dd_move_weighted:\n"
     "it may end hidden, and may hide others; a hidden point I moves too).", cmd_move},
    {"edit-bench", "edit-bench [N] [--passes P] [--set M] [--seed S]",
     "Against CGAL, each result compared: smoothing, every vertex of N\n"
     "uniform points (default 100000) moved by a random step of 5% of the\n"
     "mean spacing, P passes (default 2), with dd_move and CGAL's\n"
     "move_if_no_collision, the vertices visited in input order (random in\n"
     "space; line \"smoothing:\"), then the same moves along a Morton curve\n"
     "(line \"smoothing (Morton order):\"), each run on fresh triangulations;\n"
     "then dd_delete_set of a random 10%, 50% and 90% of M uniform points\n"
     "(default 200000) and CGAL's remove(first, last).", cmd_edit_bench},
    {"batch-bench", "batch-bench [N] [--inserts M] [--queries Q] [--weighted NW] [--passes P] [--seed S]",
     "Against CGAL's best for a batch, each result compared: dd_insert_many\n"
     "of M new uniform points (default 50000) into N (default 200000) and\n"
     "CGAL's insert(first, last); dd_locate_many of Q queries (default\n"
     "1000000) and CGAL's spatial_sort + hinted locate loop; the same\n"
     "insertion of wuniform weighted points against Regular_triangulation_3;\n"
     "dd_move_many of every vertex of NW wuniform weighted points (default\n"
     "100000), P passes (default 2), against CGAL's move loop.", cmd_batch_bench},
    {"query-bench", "query-bench [N] [--inserts M] [--queries Q] [--live L] [--rounds R] [--seed S]",
     "Against CGAL (its default location and Fast_location): inserting M new\n"
     "points one at a time into DT of N uniform points (default 200000,\n"
     "50000), then Q locate and Q nearest-vertex queries; checks the\n"
     "insertions' result equals CGAL's and every answer agrees.  Then churn:\n"
     "R rounds (default 12) of deleting a random half of L live vertices\n"
     "(default 100000) and inserting as many new points; exit 1 if the\n"
     "resident memory after the last round passes 1.3 times round 2's.", cmd_query_bench},
    {"refine-bench", "refine-bench [N] [--inserts K] [--seed S]",
     "Against CGAL: a refinement loop on N uniform points in the unit cube\n"
     "(default 100000) inserting K times (default 100000) the circumcentre of\n"
     "the largest cell (circumradius; finite cells whose circumcentre is in\n"
     "the cube), our queue fed by dd_created_cells, CGAL's by find_conflicts\n"
     "and insert_in_hole; the same rule on both sides, so both must end in the\n"
     "same triangulation (exit 1 on a mismatch).", cmd_refine_bench},
    {"regular-bench", "regular-bench [N] [--base N0] [--inserts M] [--reps R] [--seed S]",
     "Regular triangulations against CGAL's Regular_triangulation_3, hidden\n"
     "points kept: construction of N weighted points of wuniform (default\n"
     "10^6; dd_create_ex against CGAL's range insert, R times each, default 3,\n"
     "medians), then M new weighted points (default 50000) inserted into N0\n"
     "(default 200000), dd_insert_weighted against CGAL's hinted insert.  The\n"
     "cells and hidden sets are compared (after each construction and at five\n"
     "checkpoints of the insertions); mismatches are printed, exit 1 on any.\n"
     "While the engine refuses weights, its figures read n/a.", cmd_regular_bench},
    {"wbench", "wbench [--mode quick|full|tiny] [--scale F] [--out DIR] [--dataset NAME] [--seed S] [--discard-hidden]",
     "Weighted deletions (make bench runs it): every strategy (dtdel variants)\n"
     "against CGAL's Regular_triangulation_3::remove() on the weighted datasets\n"
     "(wuniform, wuniform-most, molecule, wgrid, wmoment up to n = 256, whelix\n"
     "up to n = 16000), hidden points kept (--discard-hidden: forgotten), each\n"
     "deletion timed alone and compared with CGAL's (the cells it made and\n"
     "the hidden set), the vertex put back untimed; one CSV per dataset in\n"
     "DIR (default results/weighted), as dtdel bench writes them.  A\n"
     "strategy refusing weighted points prints n/a.  --mode tiny: a few\n"
     "deletions on small sets, for tests.  Exit 1 on any mismatch.", cmd_wbench},
    {"wedits-bench", "wedits-bench [N] [--passes P] [--set M] [--seed S] [--discard-hidden] [--set-only] [--interleaved]",
     "Weighted edits against CGAL's Regular_triangulation_3, hidden points\n"
     "kept (--discard-hidden: forgotten): every vertex of N wuniform weighted\n"
     "points (default 100000) re-weighted by a random factor in [0.9, 1.1)\n"
     "(dd_move_weighted; CGAL's remove and insert), then moved by 5% of the\n"
     "mean spacing in a random direction, P passes (default 2; dd_move;\n"
     "CGAL's move(), or remove and insert where move() would not give the\n"
     "reference result: counted); then dd_delete_set of a random 10% and 90%\n"
     "of the vertices of M wuniform weighted points (default 200000) against\n"
     "CGAL's remove() one by one (--set-only: these alone).  The passes run\n"
     "in batches, ours then CGAL's, each library alone with its data in\n"
     "cache (--interleaved: each edit on both sides in turn).  Results\n"
     "compared whole (cells and hidden set) at five checkpoints a pass; exit\n"
     "1 on a mismatch.  Calls the engine refuses read n/a.", cmd_wedits_bench},
    {"variants", "variants", "Lists the deletion strategies (the first is the default), then the\n"
     "two CGAL rows.", cmd_variants},
    {"bench", "bench [--mode quick|full] [--scale F] [--reps R] [--bucket-min M] [--out DIR] [--phases DIR] [--dataset NAME] [--seed S]",
     "The deletion benchmark (make bench runs it): every row (dtdel variants)\n"
     "on the mode's datasets, each deletion timed alone and compared with\n"
     "CGAL's result; then an insert row (our re-insertion of the vertex)\n"
     "and an auto-paired row (the default's deletion, timed right before\n"
     "each of those re-insertions); one CSV per dataset in DIR (default\n"
     "results/).  --scale multiplies the number of deletions per case\n"
     "(larger runs: --scale 4).  Degree buckets left with few deletions\n"
     "by the random draw get more, drawn among their vertices, up to the\n"
     "case's minimum times F; --bucket-min M sets that minimum (0: none).\n"
     "--reps R (1-5, default 5): repetitions per timing, the median kept,\n"
     "after one warm-up run (dropped; a row of 20 ms or more keeps its one\n"
     "run); --reps 1 times only first runs (cold branch predictors and\n"
     "caches), with no warm-up.\n"
     "A counting build (build/count/dtdel) writes the phase split instead;\n"
     "--phases DIR merges such a run's phase columns into this one.", cmd_bench},
    {"build-bench", "build-bench [N] [--dataset NAME] [--seed S] [--reps R] [--write FILE] [--threads T]",
     "Builds DT of N points (default 10^6 uniform) with dtdel and with CGAL's\n"
     "range insert in the same run, R times each (default 3, at most 9),\n"
     "alternated; prints the median times in points/s, their ratio, bytes\n"
     "per cell, and whether the two triangulations are identical.\n"
     "--write FILE: then writes DT to FILE (dd_write, by its extension), once,\n"
     "and prints the file's size and the time it took.\n"
     "--threads T (T > 1): instead, dtdel on 1 and on T threads and CGAL's\n"
     "Parallel_tag construction on T threads, in turns, each checked\n"
     "against CGAL; then weighted points (wuniform) on 1 and on T threads.", cmd_build_bench},
    {"seq-bench", "seq-bench [N] [--dataset NAME] [--fraction F] [--variant NAME] [--seed S]",
     "Builds DT of N points (default 10^6 uniform) with dtdel and with CGAL,\n"
     "then deletes the same seeded random sequence of a fraction F of the\n"
     "vertices (default 0.1, at most 0.9) one after another, no re-insertion,\n"
     "with strategy NAME (default auto) and with CGAL's remove(); prints each\n"
     "engine's time for the whole sequence, the ratio, the time of deleting\n"
     "the same points as one set (dd_delete_set), and whether the final\n"
     "triangulations are identical (exit 1 if not).", cmd_seq_bench},
    {NULL, NULL, NULL, NULL}};

/* 1 when an argument is --help or -h. */
static int wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
    return 0;
}

static const command *find_command(const char *name)
{
    for (const command *c = commands; c->name; c++)
        if (!strcmp(c->name, name)) return c;
    return NULL;
}

static void main_usage(FILE *f)
{
    fprintf(f, "usage: dtdel COMMAND [ARGS]   (dtdel COMMAND --help for details)\n\ncommands:\n");
    for (const command *c = commands; c->name; c++) fprintf(f, "  dtdel %s\n", c->usage);
}

int main(int argc, char **argv)
{
#ifdef DD_TEST_BUILD
    /* Test builds: DTDEL_TEST_ALLOC_FAIL=k refuses the library's k-th
     * allocation (tests/test_cli.sh: out of memory exits 1 with one
     * message).  Release builds read no such variable.                  */
    const char *fail_at = getenv("DTDEL_TEST_ALLOC_FAIL");
    if (fail_at) dd_test_control(NULL, DD_TEST_ALLOC_FAIL, atol(fail_at));
#endif
    if (argc < 2) { main_usage(stderr); return EXIT_USAGE; }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        main_usage(stdout);
        return 0;
    }
    const command *c = find_command(argv[1]);
    if (!c) {
        fprintf(stderr, "dtdel: unknown command '%s'\n", argv[1]);
        main_usage(stderr);
        return EXIT_USAGE;
    }
    if (wants_help(argc - 1, argv + 1)) {
        printf("usage: dtdel %s\n\n%s\n", c->usage, c->help);
        return 0;
    }
    const int rc = c->run(argc - 1, argv + 1);
    if (rc != EXIT_SHOW_USAGE) return rc;
    fprintf(stderr, "usage: dtdel %s\n", c->usage);
    return EXIT_USAGE;
}
