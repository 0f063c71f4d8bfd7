/*
 * options.c -- what the bench commands parse alike (bench.h): numeric
 * options, --dataset and --seed, and the generated points they name.
 */
#include "bench/bench.h"

#include <string.h>

int parse_num_opts(const char *cmd, int argc, char **argv, const num_opt *opts, int n)
{
    for (int i = 1; i < argc; i++) {
        const int positional = argv[i][0] != '-';
        int k = 0;
        while (k < n && (positional ? opts[k].flag != NULL : !opts[k].flag || strcmp(argv[i], opts[k].flag))) k++;
        if (k == n) return usage_error(cmd, "unknown option '%s'", argv[i]);
        const char *val = positional ? argv[i] : i + 1 < argc ? argv[++i] : NULL;
        if (!val || parse_u64(val, opts[k].dst) || *opts[k].dst > 50000000)
            return usage_error(cmd, "bad number for '%s'", argv[i]);
    }
    return 0;
}

int take_dataset_option(const char *cmd, int argc, char **argv, int *i, const char **dataset, uint64_t *seed,
                        int *rc)
{
    *rc = 0;
    if (!strcmp(argv[*i], "--seed")) {
        if (++*i >= argc || parse_u64(argv[*i], seed))
            *rc = usage_error(cmd, "--seed needs a non-negative integer%s", "");
        return 1;
    }
    if (!strcmp(argv[*i], "--dataset")) {
        if (++*i >= argc) *rc = usage_error(cmd, "--dataset needs a name%s", "");
        else *dataset = argv[*i];
        return 1;
    }
    return 0;
}

int gen_points(const char *cmd, const char *dataset, uint64_t n, uint64_t seed, double **xyz, uint32_t *np)
{
    char msg[512];
    dd_status s = dd_gen(dataset, (uint32_t)n, seed, xyz, np, msg, sizeof msg);
    if (s == DD_OK) return 0;
    fprintf(stderr, "dtdel %s: %s\n", cmd, msg);
    return s == DD_ERR_PARSE ? EXIT_USAGE : EXIT_INPUT;
}
