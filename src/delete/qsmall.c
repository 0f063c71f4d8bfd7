/*
 * qsmall.c -- the compact conflict DT (see qsmall.h; paper 4.1).
 *
 * Owns: struct dd_qs (kept in d's scratch across deletions, so the hot path does
 * not allocate once warm), its cell storage, CREATEQCONFLICTDT and
 * QCONFLICTDTINSERT on it, the scan location, and the export of the fill.
 *
 * Invariant: every conflict answer is dd_cell_conflict's on the same cell
 * (a lifted-filter sign certified by lift.h, else pred.c's predicates);
 * the free cells form a list through n[0]; the edge table is empty
 * between two stars.  Conventions are mesh.h's (orientation, dd_facet,
 * 4c+i neighbours, the dummy-cell swap of dd_cell_conflict), with 8-bit
 * vertices and 16-bit neighbour references.
 */
#include "delete/qsmall.h"
#include "delete/qdt.h"
#include "dtdel/alloc.h"

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
    double lift[64][4];           /* dd_lift_row of x relative to q; QS_QD: 0 */
    double w[64];                 /* weighted t: local vertex -> weight   */
    double lift_err;              /* the in-sphere bound (0: exact, +inf: off) */
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
    dd_mfree(s->c); dd_mfree(s->stamp); dd_mfree(s->stack); dd_mfree(s->conflict); dd_mfree(s->boundary); dd_mfree(s->map);
    dd_mfree(s);
}

static void qs_free_scratch(void *s) { dd_qs_free(s); }
static const dd_scratch_kind qs_kind = {"compact conflict DT", qs_free_scratch};

static dd_status qs_get(dd_del *d, struct dd_qs **out)
{
    struct dd_qs *s = dd_del_scratch(d, &qs_kind);
    if (!s) {
        s = dd_calloc(1, sizeof *s);
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
    qs_cell *c = dd_realloc(s->c, (cap + 1) * sizeof *c);   /* + the spare */
    if (!c) return DD_ERR_NOMEM;
    s->c = c;
    uint32_t *st = dd_realloc(s->stamp, cap * sizeof *st);
    if (!st) return DD_ERR_NOMEM;
    s->stamp = st;
    uint16_t *a = dd_realloc(s->stack, cap * sizeof *a), *b, *e;
    if (!a) return DD_ERR_NOMEM;
    s->stack = a;
    if (!(b = dd_realloc(s->conflict, cap * sizeof *b))) return DD_ERR_NOMEM;
    s->conflict = b;
    if (!(e = dd_realloc(s->boundary, 4 * cap * sizeof *e))) return DD_ERR_NOMEM;
    s->boundary = e;
    uint32_t *mp = dd_realloc(s->map, cap * sizeof *mp);
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

/* Shifted lifts (lift.h) once the plain filter has left four tests to the
 * exact predicates: nearly cospherical cavities, where it abstains on most. */
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

/* dd_cell_conflict on a compact cell: the lifted filter (dd_lift_det4 of
 * the cell's lifts and x's: negative when x is inside), else the same
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
    double det = sign * dd_lift_det4(l, s->lift[x]);
    if (det < -s->lift_err) return 1;      /* negative: inside */
    if (det > s->lift_err) return 0;
    if (++s->nexact == 4 && !s->shifted && s->nlift >= DD_SHIFT_FROM) qs_shift(s);
    return qs_conflict_exact(s, pr, c, x);
}

/* The weighted counterpart of qs_conflict (issue 44): qdt.h's rule on
 * the local points and weights, CGAL's perturbed power predicates (their
 * own semi-static filter; the lifted filter is the unweighted one's).   */
static int qs_conflict_power(struct dd_qs *s, dd_pred *pr, uint32_t c, uint32_t x)
{
    const uint8_t *v = s->c[c].v;
    const double *q[4];
    double w[5];
    int k = -1, kd = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] == QS_INF) k = i;
        else if (v[i] == QS_QD) kd = i;
        q[i] = v[i] == QS_INF ? NULL : s->pt[v[i]];
        w[i] = v[i] == QS_INF ? 0 : s->w[v[i]];
    }
    if (kd >= 0) {               /* dummy cell: swap the first two others */
        int a = kd == 0 ? 1 : 0, b = kd <= 1 ? 2 : 1;
        const double *t = q[a]; q[a] = q[b]; q[b] = t;
        double wt = w[a]; w[a] = w[b]; w[b] = wt;
        if (k == a) k = b; else if (k == b) k = a;
    }
    w[4] = s->w[x];
    if (k < 0) return dd_power_perturbed(pr, q[0], q[1], q[2], q[3], s->pt[x], w) > 0;
    const int a = dd_facet[k][0], b = dd_facet[k][1], e = dd_facet[k][2];
    const double wf[4] = {w[a], w[b], w[e], w[4]};
    return dd_power_infinite(pr, q[a], q[b], q[e], s->pt[x], wf) > 0;
}

/* The conflict test of a compiled copy: pw (a constant) picks the power
 * test of a weighted t.                                                 */
__attribute__((always_inline)) static inline int qs_test(struct dd_qs *s, dd_pred *pr, uint32_t c, uint32_t x,
                                                         const int pw)
{
    return pw ? qs_conflict_power(s, pr, c, x) : qs_conflict(s, pr, c, x);
}

/* Lifts the points 0..n-1 relative to q and sets the filter's bound:
 * lift.h's for the frame, 0 with integer lifts (then no shift).          */
static void qs_lift(struct dd_qs *s, uint32_t n)
{
    const double *q = s->pt[QS_QD];
    double m = 0;
    for (uint32_t k = 0; k < n; k++) m = dd_lift_max(m, dd_lift_row(s->lift[k], s->pt[k], q));
    int integral = m <= DD_LIFT_INT_O && dd_lift_is_int3(q);   /* beyond the largest limit no mode holds */
    for (uint32_t k = 0; k < n && integral; k++) integral = dd_lift_is_int3(s->pt[k]);
    memset(s->lift[QS_QD], 0, sizeof s->lift[QS_QD]);
    dd_lift_frame f = dd_lift_classify(integral, m);
    s->lift_err = f.ierr;
    s->lift_m = m;
    s->nlift = n;
    s->nexact = 0;
    s->shifted = !(f.ierr > 0 && f.ierr < 1.0 / 0.0);   /* nothing to shift for */
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
__attribute__((always_inline)) static inline dd_status qs_insert_as(struct dd_qs *s, dd_pred *pr, uint32_t x,
                                                                    uint32_t c0, const int pw)
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
            if (s->stamp[nb_] != ep + 1 && qs_test(s, pr, nb_, x, pw)) {
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

static dd_status qs_insert(struct dd_qs *s, dd_pred *pr, uint32_t x, uint32_t c0)
{
    return qs_insert_as(s, pr, x, c0, 0);
}

static dd_status qs_insert_power(struct dd_qs *s, dd_pred *pr, uint32_t x, uint32_t c0)
{
    return qs_insert_as(s, pr, x, c0, 1);
}

/* CREATEQCONFLICTDT: the tetrahedron of local points 0..3 with its four
 * infinite cells, then the cells not in conflict with q replaced by the
 * dummy vertex's star; pw: the power test.                               */
static dd_status qs_create(struct dd_qs *s, dd_pred *pr, const int pw)
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
        if (!(pw ? qs_conflict_power(s, pr, k, QS_QD) : qs_conflict(s, pr, k, QS_QD))) {
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

/* Unguided location: the first dummy cell in conflict with x; pw: the
 * power test.                                                           */
static dd_status qs_scan(dd_del *d, struct dd_qs *s, dd_pred *pr, uint32_t x, uint32_t *cell, const int pw)
{
    for (uint32_t c = 0; c < s->ncell; c++) {
        const qs_cell *a = &s->c[c];
        if (a->v[0] == QS_DEAD || !qs_has(a, QS_QD)) continue;
        d->locate_steps++;
        if (pw ? qs_conflict_power(s, pr, c, x) : qs_conflict(s, pr, c, x)) { *cell = c; return DD_OK; }
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
    size_t n = d->nbr.n < d->order.n ? d->nbr.n : d->order.n;   /* the hidden sites stay last */
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

/* 1 if local site x has the point and weight of an earlier site that is
 * a vertex now (dd_insert_power's duplicate rule).                     */
static int qs_duplicate(const struct dd_qs *s, uint32_t x)
{
    for (uint32_t u = 0; u < x; u++) {
        if (dd_lex_cmp(s->pt[u], s->pt[x]) != 0 || s->w[u] != s->w[x]) continue;
        for (uint32_t c = 0; c < s->ncell; c++)
            if (s->c[c].v[0] != QS_DEAD && qs_has(&s->c[c], u)) return 1;
    }
    return 0;
}

/* The hidden sites nn..n-1 of a weighted t, after the neighbours (qdt.h):
 * a duplicate, or a site in conflict with no cell without the dummy
 * vertex (hidden), is skipped; the others go in from such a cell.      */
static dd_status qs_insert_hidden(dd_del *d, struct dd_qs *s, dd_pred *pr, uint32_t nn, uint32_t n)
{
    dd_status st = DD_OK;
    for (uint32_t x = nn; x < n && st == DD_OK; x++) {
        if (qs_duplicate(s, x)) continue;
        uint32_t c0 = QS_NONE;
        for (uint32_t c = 0; c < s->ncell && c0 == QS_NONE; c++) {
            const qs_cell *a = &s->c[c];
            if (a->v[0] == QS_DEAD || qs_has(a, QS_QD)) continue;
            d->locate_steps++;
            if (qs_conflict_power(s, pr, c, x)) c0 = c;
        }
        if (c0 != QS_NONE) st = qs_insert_power(s, pr, x, c0);
    }
    return st;
}

/* dd_qs_fill on a weighted t: the neighbours d->order[0 .. d->nbr.n)
 * (the base first), then the star's hidden points.                     */
static dd_status qs_fill_power(dd_del *d, struct dd_qs *s, size_t n)
{
    dd_pred *pr = &d->qdt->pred;
    const double *wt = d->t->wt;
    for (size_t k = 0; k < n; k++) s->w[k] = wt[d->order.a[k]];
    s->w[QS_QD] = d->qw;
    s->w[QS_INF] = 0;
    const uint32_t nn = (uint32_t)(d->nbr.n < n ? d->nbr.n : n);
    DD_PHASE_BEGIN(d);
    dd_status st = qs_create(s, pr, 1);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (uint32_t k = 4; k < nn && st == DD_OK; k++) {
        uint32_t c = 0;
        st = qs_scan(d, s, pr, k, &c, 1);
        DD_PHASE_END(d, DD_PH_LOCATE);
        if (st == DD_OK) st = qs_insert_power(s, pr, k, c);
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    if (st == DD_OK) st = qs_insert_hidden(d, s, pr, nn, (uint32_t)n);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return st;
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
    if (d->t->wt) {
        st = qs_fill_power(d, s, n);
    } else {
        qs_lift(s, (uint32_t)n);
        DD_PHASE_BEGIN(d);
        st = qs_create(s, pr, 0);
        DD_PHASE_END(d, DD_PH_CONFLICT);
        for (uint32_t k = 4; k < n && st == DD_OK; k++) {
            uint32_t c = 0;
            st = qs_scan(d, s, pr, k, &c, 0);
            DD_PHASE_END(d, DD_PH_LOCATE);
            if (st == DD_OK) st = qs_insert(s, pr, k, c);
            DD_PHASE_END(d, DD_PH_CONFLICT);
        }
    }
    if (st == DD_OK) st = qs_export(d, s);
    if (st == DD_ERR_INTERNAL && !d->t->err[0])
        dd_fail(d->t, st, "compact conflict DT: a cavity boundary is not closed (point %u)", d->t->v2in[d->q]);
    return st;
}

dd_status dd_qs_fill_nearest(dd_del *d)
{
    if (d->order.n > DD_QS_MAXV) return DD_ERR_INTERNAL;
    dd_qs_order_nearest(d);
    dd_status s = d->t->wt ? dd_qdt_weighted_base(d) : dd_del_pick_base(d, d->order.a, d->order.n);
    if (s == DD_ERR_COPLANAR && d->t->wt) return dd_full_fill_power(d);
    return s == DD_OK ? dd_qs_fill(d) : s;
}
