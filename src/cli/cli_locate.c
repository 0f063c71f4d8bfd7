/*
 * cli_locate.c -- `dtdel locate FILE X Y Z`: where a point lies in DT of
 * FILE's points (dd_locate) and its nearest vertex (dd_nearest_vertex);
 * `dtdel move FILE --vertex I --to X,Y,Z` (dd_move).
 */
#include "cli/cli.h"
#include "dtdel/alloc.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A coordinate: a whole argument read by strtod (NaN and inf included,
 * which dd_locate then refuses by its status); 0 on success.  A
 * number beyond DBL_MAX is refused here; one below the normal range is
 * its subnormal (or zero), as the point readers take it (strtod's ERANGE
 * on underflow is no error: every finite double is valid input).        */
static int parse_coord(const char *s, double *x)
{
    char *end;
    errno = 0;
    *x = strtod(s, &end);
    return end == s || *end != 0 || (errno == ERANGE && isinf(*x));
}

int cmd_locate(int argc, char **argv)
{
    if (argc != 5) return usage_error("locate", "expected FILE X Y Z%s", "");
    double p[3];
    for (int c = 0; c < 3; c++)
        if (parse_coord(argv[2 + c], &p[c])) return usage_error("locate", "not a number: '%s'", argv[2 + c]);
    dd_tri *t;
    int rc = build_file("locate", argv[1], &t);
    if (rc) return rc;
    int32_t cell[4];
    dd_status s = dd_locate(t, p, cell);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel locate: cannot locate the point: %s\n", dd_status_name(s));
        dd_free(t);
        return EXIT_INPUT;
    }
    uint32_t v = 0;
    if ((s = dd_nearest_vertex(t, p, &v)) != DD_OK) {
        fprintf(stderr, "dtdel locate: no nearest vertex: %s\n", dd_status_name(s));   /* a read: no dd_errmsg */
        dd_free(t);
        return EXIT_INPUT;
    }
    printf("cell: %d %d %d %d%s\n", cell[0], cell[1], cell[2], cell[3],
           cell[0] < 0 || cell[1] < 0 || cell[2] < 0 || cell[3] < 0 ? " (outside the hull)" : "");
    printf("nearest: %u\n", v);
    dd_free(t);
    return 0;
}

/* `dtdel move FILE --vertex I --to X,Y,Z`: the canonical form after the
 * move (as `delete` writes it).                                          */
int cmd_move(int argc, char **argv)
{
    const char *file = NULL, *vs = NULL, *to = NULL, *ws = NULL;
    unsigned flags = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--vertex") && i + 1 < argc) vs = argv[++i];
        else if (!strcmp(argv[i], "--to") && i + 1 < argc) to = argv[++i];
        else if (!strcmp(argv[i], "--weight") && i + 1 < argc) ws = argv[++i];
        else if (!strcmp(argv[i], "--discard-hidden")) flags |= DD_DISCARD_HIDDEN;
        else if (argv[i][0] != '-' && !file) file = argv[i];
        else return usage_error("move", "unexpected argument '%s'", argv[i]);
    }
    if (!file || !vs || !to) return usage_error("move", "expected FILE --vertex I --to X,Y,Z%s", "");
    uint64_t v;
    if (parse_u64(vs, &v) || v >= UINT32_MAX) return usage_error("move", "bad vertex index '%s'", vs);
    double p[3];
    char buf[256];
    snprintf(buf, sizeof buf, "%s", to);
    char *save = NULL, *tok = strtok_r(buf, ",", &save);
    for (int c = 0; c < 3; c++, tok = strtok_r(NULL, ",", &save))
        if (!tok || parse_coord(tok, &p[c])) return usage_error("move", "--to expects X,Y,Z, got '%s'", to);
    if (tok) return usage_error("move", "--to expects X,Y,Z, got '%s'", to);
    double w = 0;
    if (ws && parse_coord(ws, &w)) return usage_error("move", "--weight expects a number, got '%s'", ws);
    dd_tri *t;
    int rc = build_weighted_file("move", file, flags, &t);
    if (rc) return rc;
    if (ws && !dd_is_weighted(t)) {
        fprintf(stderr, "dtdel move: --weight needs weighted points (%s has none)\n", file);
        dd_free(t);
        return EXIT_INPUT;
    }
    int32_t *tets = NULL;
    size_t n = 0;
    dd_status s;
    if ((s = ws ? dd_move_weighted(t, (uint32_t)v, p, w) : dd_move(t, (uint32_t)v, p)) != DD_OK) {
        fprintf(stderr, "dtdel move: cannot move vertex %llu: %s\n", (unsigned long long)v, dd_errmsg(t));
        rc = EXIT_INPUT;
    } else if (dd_canonical(t, &tets, &n) != DD_OK) {
        fprintf(stderr, "dtdel move: out of memory\n");
        rc = EXIT_INPUT;
    } else {
        write_tets(tets, n);
    }
    dd_mfree(tets);
    dd_free(t);
    return rc;
}
