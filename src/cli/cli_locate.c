/*
 * cli_locate.c -- `dtdel locate FILE X Y Z`: where a point lies in DT of
 * FILE's points (dd_locate) and its nearest vertex (dd_nearest_vertex).
 */
#include "cli/cli.h"

#include <errno.h>
#include <stdlib.h>

/* A coordinate: a whole argument read by strtod (NaN and inf included,
 * which dd_locate then refuses with its own message); 0 on success.      */
static int parse_coord(const char *s, double *x)
{
    char *end;
    errno = 0;
    *x = strtod(s, &end);
    return end == s || *end != 0 || errno == ERANGE;
}

int cmd_locate(int argc, char **argv)
{
    if (wants_help(argc, argv)) return print_help("locate");
    if (argc != 5) return usage_error("locate", "expected FILE X Y Z%s", "");
    double p[3];
    for (int c = 0; c < 3; c++)
        if (parse_coord(argv[2 + c], &p[c])) return usage_error("locate", "not a number: '%s'", argv[2 + c]);
    double *xyz;
    uint32_t np;
    int rc = load_file("locate", argv[1], &xyz, &np);
    if (rc) return rc;
    dd_tri *t;
    char msg[512];
    dd_status s = dd_create(&t, xyz, np, msg, sizeof msg);
    free(xyz);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel locate: %s: %s\n", argv[1], msg);
        return EXIT_INPUT;
    }
    int32_t cell[4];
    s = dd_locate(t, p, cell);
    if (s != DD_OK) {
        fprintf(stderr, "dtdel locate: %s\n", dd_errmsg(t));
        dd_free(t);
        return EXIT_INPUT;
    }
    const uint32_t v = dd_nearest_vertex(t, p);
    printf("cell: %d %d %d %d%s\n", cell[0], cell[1], cell[2], cell[3],
           cell[0] < 0 || cell[1] < 0 || cell[2] < 0 || cell[3] < 0 ? " (outside the hull)" : "");
    printf("nearest: %u\n", v);
    dd_free(t);
    return 0;
}
