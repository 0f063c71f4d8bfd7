/*
 * cli_regular.c -- weighted files on the command line (DESIGN 12):
 *
 *   dtdel tets FILE [--discard-hidden]         (cli.c; built here)
 *   dtdel hidden FILE [--discard-hidden]       sorted hidden indices
 *   dtdel cgal-tets FILE [--discard-hidden]    (cli.c; CGAL's, here)
 *   dtdel cgal-hidden FILE [--discard-hidden]  the same by CGAL
 *
 * A file with weights (.xyzw, .xyzr, .ply with `weight` or `radius`)
 * gives the regular triangulation, by dd_create_ex with its weights, or
 * by CGAL's Regular_triangulation_3 through cgal/cgal_regular.h; a file
 * without weights gives the Delaunay triangulation, as before.
 */
#include "cli/cli.h"
#include "dtdel/alloc.h"
#include "cgal/cgal_regular.h"

#include <stdlib.h>
#include <string.h>

int load_weighted_file(const char *cmd, const char *path, double **xyz, double **w, uint32_t *np)
{
    char msg[512];
    dd_status s = dd_read_weighted(path, xyz, w, np, msg, sizeof msg);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel %s: %s\n", cmd, msg);
        return EXIT_INPUT;
    }
    return 0;
}

int build_weighted_file(const char *cmd, const char *path, unsigned flags, dd_tri **t)
{
    double *xyz, *w;
    uint32_t np;
    int rc = load_weighted_file(cmd, path, &xyz, &w, &np);
    if (rc) return rc;
    char msg[512] = "";
    dd_status s = dd_create_ex(t, xyz, w, np, flags, msg, sizeof msg);
    dd_mfree(xyz);
    dd_mfree(w);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel %s: %s: %s\n", cmd, path, *msg ? msg : dd_status_name(s));
        return EXIT_INPUT;
    }
    return 0;
}

/* CGAL's regular triangulation of a weighted file's points; for a file
 * without weights, *c stays NULL and *xyz, *np hold the points.         */
static int cgal_weighted_file(const char *cmd, const char *path, int discard, dd_cgal_rt **c, double **xyz,
                              uint32_t *np)
{
    double *w;
    *c = NULL;
    int rc = load_weighted_file(cmd, path, xyz, &w, np);
    if (rc || w == NULL) return rc;
    *c = dd_cgal_rt_build(*xyz, w, *np, discard);
    dd_mfree(w);
    dd_mfree(*xyz);
    *xyz = NULL;
    if (*c == NULL) {
        fprintf(stderr, "dtdel %s: %s: CGAL cannot build a 3D regular triangulation of these points\n", cmd,
                path);
        return EXIT_INPUT;
    }
    return 0;
}

int cgal_tets_file(const char *path, int discard)
{
    dd_cgal_rt *rt;
    double *xyz;
    uint32_t np;
    int rc = cgal_weighted_file("cgal-tets", path, discard, &rt, &xyz, &np);
    if (rc) return rc;
    int32_t *tets = NULL;
    size_t n = 0;
    if (rt != NULL) {
        rc = dd_cgal_rt_canonical(rt, &tets, &n) ? EXIT_INPUT : 0;
        dd_cgal_rt_free(rt);
    } else {
        dd_cgal *c = dd_cgal_build(xyz, np);
        dd_mfree(xyz);
        if (!c) {
            fprintf(stderr, "dtdel cgal-tets: %s: CGAL cannot build a 3D triangulation of these points\n", path);
            return EXIT_INPUT;
        }
        rc = dd_cgal_canonical(c, &tets, &n) ? EXIT_INPUT : 0;
        dd_cgal_free(c);
    }
    if (!rc) write_tets(tets, n);
    dd_mfree(tets);
    return rc;
}

/* FILE and --discard-hidden of hidden and cgal-hidden; 0 or a usage error. */
static int parse_file_args(const char *cmd, int argc, char **argv, const char **file, int *discard)
{
    *file = NULL;
    *discard = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--discard-hidden")) *discard = 1;
        else if (!*file && argv[i][0] != '-') *file = argv[i];
        else return usage_error(cmd, "unexpected argument '%s'", argv[i]);
    }
    return *file ? 0 : usage_error(cmd, "expected one FILE%s", "");
}

static void write_indices(const uint32_t *idx, size_t n)
{
    for (size_t i = 0; i < n; i++) printf("%u\n", idx[i]);
}

int cmd_hidden(int argc, char **argv)
{
    const char *file;
    int discard;
    int rc = parse_file_args("hidden", argc, argv, &file, &discard);
    if (rc) return rc;
    dd_tri *t;
    rc = build_weighted_file("hidden", file, discard ? DD_DISCARD_HIDDEN : 0, &t);
    if (rc) return rc;
    uint32_t *idx;
    size_t n;
    dd_status s = dd_hidden(t, &idx, &n);
    dd_free(t);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel hidden: %s: %s\n", file, dd_status_name(s));
        return EXIT_INPUT;
    }
    write_indices(idx, n);
    dd_mfree(idx);
    return 0;
}

int cmd_cgal_hidden(int argc, char **argv)
{
    const char *file;
    int discard;
    int rc = parse_file_args("cgal-hidden", argc, argv, &file, &discard);
    if (rc) return rc;
    dd_cgal_rt *rt;
    double *xyz;
    uint32_t np;
    rc = cgal_weighted_file("cgal-hidden", file, discard, &rt, &xyz, &np);
    if (rc) return rc;
    dd_mfree(xyz);
    if (rt == NULL) return 0;                  /* no weights: nothing hidden */
    uint32_t *idx = NULL;
    size_t n = 0;
    rc = dd_cgal_rt_hidden(rt, &idx, &n) ? EXIT_INPUT : 0;
    dd_cgal_rt_free(rt);
    if (!rc) write_indices(idx, n);
    dd_mfree(idx);
    return rc;
}
