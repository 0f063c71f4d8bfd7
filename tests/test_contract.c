/*
 * test_contract.c -- the promises of dtdel.h's conventions, one by one:
 *  - the version macros and dd_version agree;
 *  - dd_create_ex refuses unknown flag bits (DD_ERR_ARG) with a message;
 *    with no flags, and with zero weights (the regular triangulation of
 *    weight-0 points, DESIGN 12), it builds what dd_create builds;
 *  - dd_errmsg is the last failure's message: a later success keeps it,
 *    a read-only call does not touch it, the next failure replaces it;
 *  - a list truncated at `max` returns the full count (snprintf's rule),
 *    writes no more than max entries, and max 0 with a NULL array counts;
 *  - counts, yes/no answers and names of a bad index or past the end;
 *  - dd_nearest_vertex reports by status;
 *  - a set listing a vertex twice is DD_ERR_ARG and changes nothing;
 *  - index policy: by default dd_insert reuses a deleted index and
 *    dd_num_input stays; with DD_STABLE_INDICES it takes a new one, the
 *    old stays deleted and dd_reinsert of it works, the result is DT of
 *    the points with their indices, and memory grows with the churn.
 */
#include "testlib.h"
#include "testcgal.h"

#include <math.h>

#include "../datasets/datasets.h"

static int same_canonical(const dd_tri *a, const dd_tri *b)
{
    int32_t *x = NULL, *y = NULL;
    size_t nx = 0, ny = 0;
    int same = dd_canonical(a, &x, &nx) == DD_OK && dd_canonical(b, &y, &ny) == DD_OK && nx == ny &&
               !memcmp(x, y, 4 * nx * sizeof *x);
    free(x), free(y);
    return same;
}

static void version(tl_state *st)
{
    char want[64];
    snprintf(want, sizeof want, "%d.%d.%d", DD_VERSION_MAJOR, DD_VERSION_MINOR, DD_VERSION_PATCH);
    tl_check(st, !strcmp(dd_version(), DD_VERSION) && !strcmp(DD_VERSION, want), "contract/version",
             "dd_version '%s', DD_VERSION '%s', macros %s", dd_version(), DD_VERSION, want);
}

static void create_ex(tl_state *st, const double *p, uint32_t np)
{
    char msg[256];
    dd_tri *t = (dd_tri *)1, *u = NULL, *v = NULL;
    double *w = calloc(np, sizeof *w);
    dd_status sz = w ? dd_create_ex(&t, p, w, np, 0, msg, sizeof msg) : DD_ERR_NOMEM;
    dd_tri *z = sz == DD_OK ? t : NULL;
    free(w);
    t = (dd_tri *)1;
    dd_status s = dd_create_ex(&t, p, NULL, np, 1u << 7, msg, sizeof msg);
    tl_check(st, s == DD_ERR_ARG && !t && strstr(msg, "flag"), "contract/create-ex-flags",
             "status %s, message '%s'", dd_status_name(s), msg);
    s = dd_create_ex(&t, p, NULL, np, 0, msg, sizeof msg);
    dd_status s2 = dd_create(&u, p, np, msg, sizeof msg);
    dd_status s3 = dd_create_ex(&v, p, NULL, np, DD_STABLE_INDICES, msg, sizeof msg);
    tl_check(st, s == DD_OK && s2 == DD_OK && s3 == DD_OK && same_canonical(t, u) && same_canonical(t, v),
             "contract/create-ex-same", "statuses %s %s %s", dd_status_name(s), dd_status_name(s2),
             dd_status_name(s3));
    tl_check(st, sz == DD_OK && s2 == DD_OK && same_canonical(z, u), "contract/create-ex-zero-weights",
             "status %s", dd_status_name(sz));
    dd_free(t), dd_free(u), dd_free(v), dd_free(z);
}

static void errmsg(tl_state *st, dd_tri *t)
{
    char first[256], after[256];
    const int empty = dd_errmsg(t)[0] == 0;
    dd_status s1 = dd_delete(t, 999999);
    snprintf(first, sizeof first, "%s", dd_errmsg(t));
    double q[3] = {0.5, 0.5, 0.5}, x[3];
    uint32_t idx, near;
    int32_t cell[4];
    dd_status ok = dd_insert(t, q, &idx);                  /* successes, all kinds */
    if (ok == DD_OK) ok = dd_delete(t, idx);
    if (ok == DD_OK) ok = dd_locate(t, q, cell);
    if (ok == DD_OK) ok = dd_nearest_vertex(t, q, &near);
    if (ok == DD_OK) ok = dd_check(t);
    dd_status ro = dd_point(t, 999999, x);                 /* a read-only failure */
    snprintf(after, sizeof after, "%s", dd_errmsg(t));
    tl_check(st, empty && s1 == DD_ERR_UNKNOWN_VERTEX && strstr(first, "999999") && ok == DD_OK &&
                     ro == DD_ERR_UNKNOWN_VERTEX && !strcmp(first, after),
             "contract/errmsg-kept", "empty at first %d, '%s' then '%s' (successes: %s)", empty, first, after,
             dd_status_name(ok));
    dd_status s2 = dd_delete_with(t, 0, "no-such-variant");
    tl_check(st, s2 == DD_ERR_UNKNOWN_VARIANT && strstr(dd_errmsg(t), "no-such-variant"), "contract/errmsg-next",
             "status %s, message '%s'", dd_status_name(s2), dd_errmsg(t));
}

/* dd_neighbors and dd_incident_cells of vertex v, whole and cut at max. */
static void truncation(tl_state *st, dd_tri *t, uint32_t v)
{
    uint32_t all[512], cut[4];
    int32_t cells[1024][4], few[3][4];
    const uint32_t n = dd_neighbors(t, v, all, 512), c = dd_incident_cells(t, v, cells, 1024);
    memset(cut, 0xAB, sizeof cut);
    memset(few, 0xAB, sizeof few);
    const uint32_t n2 = dd_neighbors(t, v, cut, 2), n0 = dd_neighbors(t, v, NULL, 0);
    const uint32_t c2 = dd_incident_cells(t, v, few, 2), c0 = dd_incident_cells(t, v, NULL, 0);
    int ok = n > 2 && n <= 512 && c > 2 && c <= 1024 && n2 == n && n0 == n && c2 == c && c0 == c;
    ok = ok && cut[0] == all[0] && cut[1] == all[1] && cut[2] == 0xABABABABu && cut[3] == 0xABABABABu;
    ok = ok && !memcmp(few, cells, 2 * sizeof few[0]) && few[2][0] == (int32_t)0xABABABAB;
    tl_check(st, ok, "contract/truncation",
             "neighbours %u, cut at 2: %u, at 0: %u; cells %u, cut at 2: %u, at 0: %u", n, n2, n0, c, c2, c0);
}

static void bad_index(tl_state *st, dd_tri *t)
{
    const uint32_t bad = dd_num_input(t) + 5;
    uint32_t out[4];
    int32_t cells[4][4];
    int ok = dd_alias(t, bad) == UINT32_MAX && dd_is_vertex(t, bad) == 0 && dd_on_hull(t, bad) == 0 &&
             dd_degree(t, bad) == 0 && dd_neighbors(t, bad, out, 4) == 0 && dd_incident_cells(t, bad, cells, 4) == 0;
    size_t k = 0;
    while (dd_variant_name(k)) k++;
    ok = ok && k > 0 && dd_variant_description(k) == NULL && dd_variant_name(k + 3) == NULL;
    for (int s = 0; s < DD_NUM_STATUS; s++) ok = ok && strcmp(dd_status_name((dd_status)s), "unknown status");
    ok = ok && !strcmp(dd_status_name(DD_NUM_STATUS), "unknown status");
    tl_check(st, ok, "contract/bad-index", "a count, yes/no or name of a bad index is not 0 / NULL");
}

static void nearest(tl_state *st, dd_tri *t)
{
    const double nanp[3] = {0, NAN, 0}, infp[3] = {0, 0, -INFINITY}, q[3] = {0.25, 0.5, 0.75};
    uint32_t v = 77, w = 77, x = UINT32_MAX;
    dd_status a = dd_nearest_vertex(t, nanp, &v), b = dd_nearest_vertex(t, infp, &w), c = dd_nearest_vertex(t, q, &x);
    tl_check(st, a == DD_ERR_NAN && b == DD_ERR_INFINITE && c == DD_OK && dd_is_vertex(t, x), "contract/nearest-status",
             "statuses %s %s %s, vertex %u", dd_status_name(a), dd_status_name(b), dd_status_name(c), x);
}

static void set_twice(tl_state *st, dd_tri *t)
{
    int32_t *before = NULL, *after = NULL;
    size_t nb = 0, na = 0;
    dd_canonical(t, &before, &nb);
    const uint32_t vs[4] = {3, 9, 5, 9};
    dd_status s = dd_delete_set(t, vs, 4);
    dd_canonical(t, &after, &na);
    const int same = nb > 0 && na == nb && !memcmp(before, after, 4 * nb * sizeof *after);
    tl_check(st, s == DD_ERR_ARG && strstr(dd_errmsg(t), "twice") && same, "contract/set-twice",
             "status %s, message '%s', unchanged %d", dd_status_name(s), dd_errmsg(t), same);
    free(before), free(after);
}

/* Deletes vertex 7, inserts a new point; the index policy decides what
 * the new point is called and what becomes of 7.                        */
static void policy(tl_state *st, const double *p, uint32_t np)
{
    char msg[256];
    const double q[3] = {0.123, 0.456, 0.789};
    dd_tri *d, *s;
    dd_create_ex(&d, p, NULL, np, 0, msg, sizeof msg);
    dd_create_ex(&s, p, NULL, np, DD_STABLE_INDICES, msg, sizeof msg);
    uint32_t id = 0, is = 0;
    int ok = dd_delete(d, 7) == DD_OK && dd_insert(d, q, &id) == DD_OK;
    ok = ok && id == 7 && dd_num_input(d) == np && dd_reinsert(d, 7) == DD_ERR_DUPLICATE;
    tl_check(st, ok, "contract/default-reuses", "new index %u, num_input %u of %u", id, dd_num_input(d), np);

    ok = dd_delete(s, 7) == DD_OK && dd_insert(s, q, &is) == DD_OK;
    ok = ok && is == np && dd_num_input(s) == np + 1 && !dd_is_vertex(s, 7);
    const int stays = ok;
    ok = ok && dd_reinsert(s, 7) == DD_OK && dd_check(s) == DD_OK;
    /* DT of the n + 1 points, each with its index */
    double *all = malloc(3 * ((size_t)np + 1) * sizeof *all);
    memcpy(all, p, 3 * (size_t)np * sizeof *all);
    memcpy(all + 3 * (size_t)np, q, sizeof q);
    dd_tri *fresh;
    ok = ok && dd_create(&fresh, all, np + 1, msg, sizeof msg) == DD_OK && same_canonical(s, fresh);
    if (ok) dd_free(fresh);
    tl_check(st, ok, "contract/stable-new-index", "new index %u (want %u), 7 stays deleted %d, num_input %u", is, np,
             stays, dd_num_input(s));
    free(all);
    dd_free(d), dd_free(s);
}

/* Churn: delete a vertex, insert a new point, `rounds` times.  By default
 * the index range and memory stay; with DD_STABLE_INDICES they grow.    */
static void churn(tl_state *st, const double *p, uint32_t np, uint32_t rounds)
{
    char msg[256];
    dd_tri *t[2];
    size_t mem0[2], mem1[2];
    uint32_t bad = 0;
    for (int k = 0; k < 2; k++) {
        dd_create_ex(&t[k], p, NULL, np, k ? DD_STABLE_INDICES : 0, msg, sizeof msg);
        tl_rng r = {42};
        mem0[k] = dd_memory_bytes(t[k]);
        uint32_t live = 0;
        for (uint32_t i = 0; i < rounds; i++) {
            uint32_t v = (uint32_t)tl_int(&r, 0, dd_num_input(t[k]) - 1);
            while (!dd_is_vertex(t[k], v)) v = (v + 1) % dd_num_input(t[k]);
            const double q[3] = {tl_unif(&r), tl_unif(&r), tl_unif(&r)};
            uint32_t idx;
            bad += dd_delete(t[k], v) != DD_OK || dd_insert(t[k], q, &idx) != DD_OK;
            bad += k ? idx != np + i : idx != v;
        }
        for (uint32_t v = 0; v < dd_num_input(t[k]); v++) live += (uint32_t)dd_is_vertex(t[k], v);
        bad += live != np || dd_check(t[k]) != DD_OK;
        mem1[k] = dd_memory_bytes(t[k]);
    }
    tl_check(st, bad == 0 && dd_num_input(t[0]) == np && dd_num_input(t[1]) == np + rounds,
             "contract/churn-indices", "%u bad steps; num_input %u and %u", bad, dd_num_input(t[0]),
             dd_num_input(t[1]));
    tl_check(st, mem1[0] <= mem0[0] + mem0[0] / 4 && mem1[1] > mem1[0] + (size_t)rounds * 3 * sizeof(double),
             "contract/churn-memory", "default %zu -> %zu bytes, stable %zu -> %zu bytes", mem0[0], mem1[0], mem0[1],
             mem1[1]);
    dd_free(t[0]), dd_free(t[1]);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    const int small = argc > 1 && !strcmp(argv[1], "small");
    uint32_t np;
    double *p = tl_gen("uniform", small ? 300 : 2000, 5, &np);
    char msg[256];
    dd_tri *t;
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        printf("FAIL contract/create: %s\n", msg);
        return 1;
    }
    version(&st);
    create_ex(&st, p, np);
    errmsg(&st, t);
    truncation(&st, t, 11);
    bad_index(&st, t);
    nearest(&st, t);
    set_twice(&st, t);
    policy(&st, p, np);
    churn(&st, p, np, small ? 500 : 4000);
    dd_free(t);
    free(p);
    return tl_finish(&st);
}
