/*
 * qsmall.c -- the compact conflict DT (see qsmall.h).
 *
 * Owns: struct dd_qs (kept in d's scratch across deletions, so the hot path does
 * not allocate once warm), its cell storage, CREATEQCONFLICTDT and
 * QCONFLICTDTINSERT on it, the scan location, and the export of the fill.
 *
 * Conventions are mesh.h's (orientation, dd_facet, 4c+i neighbours, the
 * dummy-cell swap of dd_cell_conflict), with 8-bit vertices and 16-bit
 * neighbour references.
 */
#include "delete/qsmall.h"
#include "geom/expansion.h"

#include <math.h>

#include <stdlib.h>
#include <string.h>

#define QS_INF  62u
#define QS_QD   63u
#define QS_DEAD 255u
#define QS_NONE 0xFFFFu
#define QS_MAXC 16000u            /* cells; 4 * cell + facet + 1 fits in
                                     16 bits, spare cell included      */

typedef struct qs_cell {
    uint8_t v[4];
    uint16_t n[4];
} qs_cell;

struct dd_qs {
    double pt[64][3];             /* local vertex -> point (QS_QD: q)   */
    double lift[64][4];           /* (x - q, |x - q|^2), rounded; QS_QD: 0 */
    double lift_err;              /* the filter's error bound (+inf: off) */
    double lift_m;                /* max |x_k - q_k| over the cavity      */
    uint32_t nlift, nexact;       /* points lifted; exact tests so far    */
    int shifted;                  /* the shifted lifts were tried         */
    uint16_t edge[64 * 64];       /* a*64+b, a<b -> 1 + facet awaiting its
                                     partner, 0 when none               */
    qs_cell *c;
    uint32_t *stamp;
    uint16_t *stack, *conflict, *boundary;
    uint32_t *map;                /* export: cell -> fill index or NONE  */
    uint32_t cap, ncell, free_head, epoch, created;
};

void dd_qs_free(struct dd_qs *s)
{
    if (!s) return;
    free(s->c); free(s->stamp); free(s->stack); free(s->conflict); free(s->boundary); free(s->map);
    free(s);
}

static void qs_free_scratch(void *s) { dd_qs_free(s); }
static const dd_scratch_kind qs_kind = {"compact conflict DT", qs_free_scratch};

static dd_status qs_get(dd_del *d, struct dd_qs **out)
{
    struct dd_qs *s = dd_del_scratch(d, &qs_kind);
    if (!s) {
        s = calloc(1, sizeof *s);
        if (!s) return DD_ERR_NOMEM;
        dd_status st = dd_del_keep_scratch(d, &qs_kind, s);
        if (st != DD_OK) return st;
    }
    *out = s;
    return DD_OK;
}

/* Room for k more cells than ncell (free cells are not counted). */
static dd_status qs_reserve(struct dd_qs *s, uint32_t k)
{
    uint32_t need = s->ncell + k;
    if (need <= s->cap) return DD_OK;
    if (need > QS_MAXC) return DD_ERR_NOMEM;
    uint32_t cap = s->cap ? s->cap : 256;
    while (cap < need) cap *= 2;
    if (cap > QS_MAXC) cap = QS_MAXC;
    qs_cell *c = realloc(s->c, (cap + 1) * sizeof *c);   /* + the spare */
    if (!c) return DD_ERR_NOMEM;
    s->c = c;
    uint32_t *st = realloc(s->stamp, cap * sizeof *st);
    if (!st) return DD_ERR_NOMEM;
    s->stamp = st;
    uint16_t *a = realloc(s->stack, cap * sizeof *a), *b, *e;
    if (!a) return DD_ERR_NOMEM;
    s->stack = a;
    if (!(b = realloc(s->conflict, cap * sizeof *b))) return DD_ERR_NOMEM;
    s->conflict = b;
    if (!(e = realloc(s->boundary, 4 * cap * sizeof *e))) return DD_ERR_NOMEM;
    s->boundary = e;
    uint32_t *mp = realloc(s->map, cap * sizeof *mp);
    if (!mp) return DD_ERR_NOMEM;
    s->map = mp;
    memset(s->stamp + s->cap, 0, (cap - s->cap) * sizeof *st);
    s->cap = cap;
    return DD_OK;
}

static uint32_t qs_new_cell(struct dd_qs *s)
{
    uint32_t c;
    if (s->free_head != QS_NONE) {
        c = s->free_head;
        s->free_head = s->c[c].n[0];
    } else {
        c = s->ncell++;
    }
    s->stamp[c] = 0;
    s->created++;
    return c;
}

static void qs_kill(struct dd_qs *s, uint32_t c)
{
    s->c[c].v[0] = QS_DEAD;
    s->c[c].n[0] = (uint16_t)s->free_head;
    s->free_head = c;
}

static inline void qs_glue(struct dd_qs *s, uint32_t f, uint32_t g)
{
    s->c[f >> 2].n[f & 3] = (uint16_t)g;
    s->c[g >> 2].n[g & 3] = (uint16_t)f;
}

static uint32_t qs_new_epoch(struct dd_qs *s)
{
    if (s->epoch > UINT32_MAX - 8) {
        memset(s->stamp, 0, s->cap * sizeof *s->stamp);
        s->epoch = 0;
    }
    s->epoch += 2;
    return s->epoch - 1;
}

static inline int qs_has(const qs_cell *c, uint32_t x)
{
    return c->v[0] == x || c->v[1] == x || c->v[2] == x || c->v[3] == x;
}

/* The filter.  For a cell with rows v0..v3 (dd_cell_conflict's order)
 * and a point p, the in-sphere determinant equals
 *     det4( lift[vi] - lift[p] ),  i = 0..3,
 * exactly, when the lifts are exact: lift[x] = (x - q, |x - q|^2) moves
 * every point by -q and adds to the fourth column a combination of the
 * first three, which changes no determinant.  Computed in doubles, with
 * m = max |x_k - q_k| over the points of the cavity: the entries are at
 * most 2m (columns 0-2) and 3m^2 (column 3) with absolute errors at most
 * 2u*2m and 12u*3m^2 (u = 2^-53; the lifts are rounded once per point),
 * so the determinant's error from its entries is at most
 * 24 * (2m)^3 * 3m^2 * 18u, and its evaluation (10 roundings on any
 * product path) adds at most gamma_10 * 576 m^5: in all below
 * 1.8e-12 m^5.  The filter answers only when |det| > 1e-11 m^5, and only
 * when 1e-55 <= m <= 1e55 (no overflow; underflow errors negligible);
 * otherwise the exact perturbed predicate decides.  A filter answer is the
 * sign of the exact determinant, hence the predicate's (det4 < 0: p
 * inside the sphere of the positively oriented v0..v3).                   */
static double det4_rows(const double *r[4], const double *p)
{
    double a[4][4];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) a[i][k] = r[i][k] - p[k];
    double m01 = a[0][0] * a[1][1] - a[1][0] * a[0][1], m02 = a[0][0] * a[2][1] - a[2][0] * a[0][1];
    double m03 = a[0][0] * a[3][1] - a[3][0] * a[0][1], m12 = a[1][0] * a[2][1] - a[2][0] * a[1][1];
    double m13 = a[1][0] * a[3][1] - a[3][0] * a[1][1], m23 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
    double n01 = a[0][2] * a[1][3] - a[1][2] * a[0][3], n02 = a[0][2] * a[2][3] - a[2][2] * a[0][3];
    double n03 = a[0][2] * a[3][3] - a[3][2] * a[0][3], n12 = a[1][2] * a[2][3] - a[2][2] * a[1][3];
    double n13 = a[1][2] * a[3][3] - a[3][2] * a[1][3], n23 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
    return ((m01 * n23 - m02 * n13) + (m03 * n12 + m12 * n03)) - (m13 * n02 - m23 * n01);
}

/* The exact test: dd_cell_conflict's rule on the cell's points. */
static int qs_conflict_exact(struct dd_qs *s, dd_pred *pr, uint32_t c, uint32_t x)
{
    const uint8_t *v = s->c[c].v;
    const double *q[4];
    int k = -1, kd = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] == QS_INF) k = i;
        else if (v[i] == QS_QD) kd = i;
        q[i] = v[i] == QS_INF ? NULL : s->pt[v[i]];
    }
    return dd_points_conflict(pr, q, k, kd, s->pt[x]);
}

/* 1 if one of the four bytes of w is 62 or 63 (QS_INF, QS_QD) or 255
 * (QS_DEAD): the bytes with bits 0x3E all set.                           */
static inline uint32_t qs_outer_bytes(uint32_t w)
{
    uint32_t y = (w & 0x3E3E3E3Eu) ^ 0x3E3E3E3Eu;
    return (y - 0x01010101u) & ~y & 0x80808080u;
}

/* Shifted lifts, for nearly cospherical cavities (points sampled on a
 * sphere), where every determinant is tiny next to m^5 and the plain
 * filter always abstains.  Replacing the fourth column by
 *     w'[x] = |x - q|^2 - 2 (x - q).C
 * for any fixed C subtracts multiples of the first three columns: the
 * determinant is unchanged.  With C the centre (relative to q) of the
 * sphere through q and points 0, 1, 2, w' is about the distance of x from
 * that sphere, far below m^2.  Each w' is computed from its exact
 * expansion within 4u |w'|, so with M = max |w'| the entries of column 3
 * are at most 2M with errors at most 10u M; with the 6u of columns 0-2
 * and the 10u of the evaluation, the error is below
 *     21u * 24 * (2m)^3 * 2M < 9e-13 m^3 M,
 * and the filter answers only when |det| > 5e-12 m^3 M (and that bound
 * is at least 1e-290: underflow negligible).  Kept only when it is
 * tighter than the plain bound.  Tried once per deletion, after the
 * fourth exact fallback, and only with at least DD_SHIFT_FROM (finite)
 * points: it costs an exact expansion a point, which the few tests left
 * below that do not pay back.  Measured on the sphere dataset (hull
 * vertices: one neighbour is infinite), warm deletions with and without
 * shifting: degree 6 1.98 vs 1.53 us, 7 2.68 vs 2.65, 8 3.15 vs 4.29,
 * 9 3.63 vs 6.20.                                                        */
double dd_shift_lifts(const double *const *pts, uint32_t n, const double *q, const double *a, const double *b,
                      const double *c, double m, double err, double *w)
{
    double bc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
    double ca[3] = {c[1] * a[2] - c[2] * a[1], c[2] * a[0] - c[0] * a[2], c[0] * a[1] - c[1] * a[0]};
    double ab[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double den = 2 * (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]), C[3], M = 0;
    for (int i = 0; i < 3; i++) {
        C[i] = (a[3] * bc[i] + b[3] * ca[i] + c[3] * ab[i]) / den;
        if (!(fabs(C[i]) <= 1e50)) return 0;       /* also NaN, inf */
    }
    for (uint32_t k = 0; k < n; k++) {
        w[k] = dd_exp_shifted_lift(pts[k], q, C);
        if (fabs(w[k]) > M) M = fabs(w[k]);
    }
    double e = 5e-12 * m * m * m * M;
    return e >= 1e-290 && e < err ? e : 0;
}

static void qs_shift(struct dd_qs *s)
{
    s->shifted = 1;
    const double *pts[DD_QS_MAXV];
    double w[DD_QS_MAXV];
    for (uint32_t k = 0; k < s->nlift; k++) pts[k] = s->pt[k];
    double err = dd_shift_lifts(pts, s->nlift, s->pt[QS_QD], s->lift[0], s->lift[1], s->lift[2], s->lift_m,
                                s->lift_err, w);
    if (err == 0) return;
    for (uint32_t k = 0; k < s->nlift; k++) s->lift[k][3] = w[k];
    s->lift_err = err;
}

/* dd_cell_conflict on a compact cell: the filter above, else the same
 * predicates on the same points in the same order, so the same answer.
 * A dummy cell (a,b,c,QD) is tested as (b,a,c,q): one row swap, so the
 * determinant of the stored order with lift[QD] = lift[q] = 0, negated. */
static int qs_conflict(struct dd_qs *s, dd_pred *pr, uint32_t c, uint32_t x)
{
    const uint8_t *v = s->c[c].v;
    uint32_t w;
    memcpy(&w, v, 4);
    double sign = 1;
    if (qs_outer_bytes(w)) {
        if (v[0] == QS_INF || v[1] == QS_INF || v[2] == QS_INF || v[3] == QS_INF)
            return qs_conflict_exact(s, pr, c, x);
        sign = -1;
    }
    const double *l[4] = {s->lift[v[0]], s->lift[v[1]], s->lift[v[2]], s->lift[v[3]]};
    double det = sign * det4_rows(l, s->lift[x]);
    if (det < -s->lift_err) return 1;      /* negative: inside */
    if (det > s->lift_err) return 0;
    if (++s->nexact == 4 && !s->shifted && s->nlift >= DD_SHIFT_FROM) qs_shift(s);
    return qs_conflict_exact(s, pr, c, x);
}

/* Lifts the points 0..n-1 and q, and sets the filter's bound. */
static void qs_lift(struct dd_qs *s, uint32_t n)
{
    const double *q = s->pt[QS_QD];
    double m = 0;
    for (uint32_t k = 0; k < n; k++) {
        double *l = s->lift[k];
        for (int i = 0; i < 3; i++) {
            l[i] = s->pt[k][i] - q[i];
            double a = l[i] < 0 ? -l[i] : l[i];
            if (a > m) m = a;
        }
        l[3] = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
    }
    memset(s->lift[QS_QD], 0, sizeof s->lift[QS_QD]);
    /* Outside the range (or NaN): +inf, so the filter never answers. */
    s->lift_err = dd_lift_err(m);
    s->lift_m = m;
    s->nlift = n;
    s->nexact = 0;
    s->shifted = s->lift_err == 1.0 / 0.0;
}

/* The star of local vertex x over the boundary facets s->boundary[0..nb)
 * of the marked region s->conflict[0..nc); returns DD_ERR_INTERNAL if the
 * boundary is not a closed surface (then nothing usable is left).        */
static dd_status qs_fill_star(struct dd_qs *s, uint32_t nb, uint32_t nc, uint32_t x)
{
    /* Edge slots hold facet + 1 (0: empty).  Branch-free matching: the
     * first facet of an edge is glued to the spare cell s->cap (its
     * entry is overwritten when the partner comes), the second to the
     * first.                                                             */
    int open = 0;
    for (uint32_t b = 0; b < nb; b++) {
        uint32_t f = s->boundary[b], i = f & 3;
        uint32_t n = qs_new_cell(s);
        qs_cell *nc_ = &s->c[n];
        const qs_cell *src = &s->c[f >> 2];
        memcpy(nc_->v, src->v, 4);
        nc_->v[i] = (uint8_t)x;
        qs_glue(s, 4 * n + i, src->n[i]);
        for (uint32_t j = 0; j < 4; j++) {
            if (j == i) continue;
            uint32_t a = nc_->v[dd_edge_of[i][j][0]], e = nc_->v[dd_edge_of[i][j][1]];
            uint16_t *slot = &s->edge[a < e ? 64 * a + e : 64 * e + a];
            uint32_t o = *slot, g = o ? o - 1 : 4 * s->cap;
            qs_glue(s, 4 * n + j, g);
            *slot = (uint16_t)(o ? 0 : 4 * n + j + 1);
            open += o ? -1 : 1;
        }
    }
    for (uint32_t k = 0; k < nc; k++) qs_kill(s, s->conflict[k]);
    if (open) {                  /* cannot happen for a valid cavity */
        memset(s->edge, 0, sizeof s->edge);
        return DD_ERR_INTERNAL;
    }
    return DD_OK;
}

/* QCONFLICTDTINSERT: the conflict region of local point x from cell c0. */
static dd_status qs_insert(struct dd_qs *s, dd_pred *pr, uint32_t x, uint32_t c0)
{
    uint32_t ep = qs_new_epoch(s), ns = 0, nc = 0, nb = 0;
    s->stamp[c0] = ep;
    s->stack[ns++] = (uint16_t)c0;
    while (ns > 0) {
        uint32_t c = s->stack[--ns];
        s->conflict[nc++] = (uint16_t)c;
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t nb_ = s->c[c].n[i] >> 2;
            if (s->stamp[nb_] == ep) continue;
            if (s->stamp[nb_] != ep + 1 && qs_conflict(s, pr, nb_, x)) {
                s->stamp[nb_] = ep;
                s->stack[ns++] = (uint16_t)nb_;
            } else {
                s->stamp[nb_] = ep + 1;
                s->boundary[nb++] = (uint16_t)(4 * c + i);
            }
        }
    }
    dd_status st = qs_reserve(s, nb);
    if (st != DD_OK) return st;
    return qs_fill_star(s, nb, nc, x);
}

/* CREATEQCONFLICTDT: the tetrahedron of local points 0..3 with its four
 * infinite cells, then the cells not in conflict with q replaced by the
 * dummy vertex's star.                                                   */
static dd_status qs_create(struct dd_qs *s, dd_pred *pr)
{
    s->ncell = 0;
    s->free_head = QS_NONE;
    s->created = 0;
    dd_status st = qs_reserve(s, 64);
    if (st != DD_OK) return st;
    uint8_t v[4] = {0, 1, 2, 3};
    if (dd_orient3d(pr, s->pt[0], s->pt[1], s->pt[2], s->pt[3]) < 0) { v[0] = 1; v[1] = 0; }
    uint32_t c = qs_new_cell(s), inf[4];
    memcpy(s->c[c].v, v, 4);
    for (int i = 0; i < 4; i++) {          /* as dd_make_first_cells */
        uint32_t e = inf[i] = qs_new_cell(s);
        uint8_t w[4] = {v[0], v[1], v[2], v[3]};
        w[i] = QS_INF;
        int a = dd_facet[i][0], b = dd_facet[i][1];
        uint8_t t = w[a]; w[a] = w[b]; w[b] = t;
        memcpy(s->c[e].v, w, 4);
        qs_glue(s, 4 * c + (uint32_t)i, 4 * e + (uint32_t)i);
    }
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) {
            uint32_t e = inf[i], x = s->c[e].v[k];
            if (x == QS_INF) continue;
            int xi = 0;
            while (v[xi] != x) xi++;
            uint32_t g = inf[xi];
            int j = 0;
            while (s->c[g].v[j] != v[i]) j++;
            s->c[e].n[k] = (uint16_t)(4 * g + (uint32_t)j);
        }
    /* The region to replace: the cells not in conflict with q. */
    uint32_t ep = qs_new_epoch(s), nc = 0, nb = 0;
    for (uint32_t k = 0; k < 5; k++)
        if (!qs_conflict(s, pr, k, QS_QD)) {
            s->stamp[k] = ep;
            s->conflict[nc++] = (uint16_t)k;
        }
    for (uint32_t k = 0; k < nc; k++) {
        uint32_t a = s->conflict[k];
        for (uint32_t i = 0; i < 4; i++)
            if (s->stamp[s->c[a].n[i] >> 2] != ep) s->boundary[nb++] = (uint16_t)(4 * a + i);
    }
    return qs_fill_star(s, nb, nc, QS_QD);
}

/* Unguided location: the first dummy cell in conflict with x. */
static dd_status qs_scan(dd_del *d, struct dd_qs *s, dd_pred *pr, uint32_t x, uint32_t *cell)
{
    for (uint32_t c = 0; c < s->ncell; c++) {
        const qs_cell *a = &s->c[c];
        if (a->v[0] == QS_DEAD || !qs_has(a, QS_QD)) continue;
        d->locate_steps++;
        if (qs_conflict(s, pr, c, x)) { *cell = c; return DD_OK; }
    }
    return dd_fail(d->t, DD_ERR_INTERNAL, "no dummy cell of the conflict DT conflicts with point %u",
                   d->t->v2in[d->order.a[x]]);
}

/* Copies the non-dummy cells into d->qdt (vertex ids, DD_INF; neighbours
 * among them kept, the others DD_NONE for the sew) and lists them.       */
static dd_status qs_export(dd_del *d, struct dd_qs *s)
{
    dd_tri *x = d->qdt;
    dd_qdt_reset(d, 1);
    uint32_t nfill = 0;
    for (uint32_t c = 0; c < s->ncell; c++)
        s->map[c] = s->c[c].v[0] != QS_DEAD && !qs_has(&s->c[c], QS_QD) ? nfill++ : UINT32_MAX;
    dd_status st = dd_reserve_cells(x, nfill);
    if (st == DD_OK) st = dd_vec_reserve(&d->fill, nfill);
    if (st != DD_OK) return st;
    const uint32_t *gid = d->order.a;
    for (uint32_t c = 0; c < s->ncell; c++) {
        if (s->map[c] == UINT32_MAX) continue;
        uint32_t m = dd_new_cell(x);
        const qs_cell *a = &s->c[c];
        for (uint32_t i = 0; i < 4; i++) {
            dd_tv(x, m)[i] = a->v[i] == QS_INF ? DD_INF : gid[a->v[i]];
            uint32_t f = a->n[i], g = s->map[f >> 2];
            dd_tn(x, m)[i] = g == UINT32_MAX ? DD_NONE : 4 * g + (f & 3);
        }
        d->fill.a[d->fill.n++] = m;
    }
    x->tets_created = s->created;
    return DD_OK;
}

void dd_qs_order_nearest(dd_del *d)
{
    uint32_t *a = d->order.a;
    size_t n = d->order.n;
    double key[DD_QS_MAXV];
    const double *q = d->qp;
    for (size_t k = 0; k < n && k < DD_QS_MAXV; k++) {
        const double *p = dd_pt(d->t, a[k]);
        double x = p[0] - q[0], y = p[1] - q[1], z = p[2] - q[2];
        key[k] = x * x + y * y + z * z;
    }
    for (size_t i = 1; i < n && i < DD_QS_MAXV; i++) {      /* insertion sort: n is small */
        double kv = key[i];
        uint32_t v = a[i];
        size_t j = i;
        for (; j > 0 && key[j - 1] > kv; j--) { key[j] = key[j - 1]; a[j] = a[j - 1]; }
        key[j] = kv;
        a[j] = v;
    }
}

dd_status dd_qs_fill(dd_del *d)
{
    size_t n = d->order.n;
    if (n > DD_QS_MAXV) return DD_ERR_INTERNAL;
    struct dd_qs *s;
    dd_status st = qs_get(d, &s);
    if (st != DD_OK) return st;
    dd_pred *pr = &d->qdt->pred;
    for (size_t k = 0; k < n; k++) memcpy(s->pt[k], dd_pt(d->t, d->order.a[k]), sizeof s->pt[k]);
    memcpy(s->pt[QS_QD], d->qp, sizeof s->pt[QS_QD]);
    qs_lift(s, (uint32_t)n);
    DD_PHASE_BEGIN(d);
    st = qs_create(s, pr);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (uint32_t k = 4; k < n && st == DD_OK; k++) {
        uint32_t c = 0;
        st = qs_scan(d, s, pr, k, &c);
        DD_PHASE_END(d, DD_PH_LOCATE);
        if (st == DD_OK) st = qs_insert(s, pr, k, c);
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    if (st == DD_OK) st = qs_export(d, s);
    if (st == DD_ERR_INTERNAL && !d->t->err[0])
        dd_fail(d->t, st, "compact conflict DT: a cavity boundary is not closed (point %u)", d->t->v2in[d->q]);
    return st;
}
