/*
 * wrap.c -- gift wrapping of a cavity (see wrap.h).
 *
 * Owns: struct dd_wrap (kept in d->wrap across deletions: no allocation
 * once warm), the local numbering of the neighbours (the infinite vertex
 * is number n), the table of open facets, the scans that find the fill
 * cell on a facet, the cells it writes into d->qdt and the matching it
 * hands to the sew (d->sew_out).
 *
 * An open facet is a triangle (a, b, c) of local numbers whose fill cell
 * on the positive side (orient3d(a, b, c, p) > 0) is still unknown.  The
 * link triangles start open, oriented towards q (mesh.h: the facet
 * opposite q in a star cell, in dd_facet order, has q on its positive
 * side); each new cell (a, b, c, p) closes the facet it was found from
 * and, for each other facet, closes it if it is open already or opens it
 * reversed.  A triangle meets at most two cells, so a facet closed twice
 * means a broken input and the deletion stops before touching the mesh.
 * A hull vertex adds cells with the infinite vertex: a finite facet with
 * no point beyond it becomes a hull facet, and a facet through the
 * infinite vertex is wrapped around its hull edge (wrap_scan_inf).
 */
#include "wrap.h"
#include "qsmall.h"

#include <stdlib.h>
#include <string.h>

#define W_NONE UINT32_MAX
#define W_BAIL (UINT32_MAX - 1)   /* a degenerate hull case: not for wrap.c */
#define W_SHIFT (UINT32_MAX - 2)  /* try the shifted lifts, then scan again */

/* On degenerate cavities (integer points of a sphere: cosphere) the
 * filters abstain on most tests and a wrap makes about n^2/2 exact ones
 * (n = 50: 1183), where the conflict DT makes far fewer: from 40
 * neighbours on, wrapping declines once its exact tests pass 2n (warm,
 * cosphere degree [48,64): 719 us wrapping against 383 us for
 * grr-neighbor; below 40 wrapping stays ahead: [32,48) 294 vs 403 us). */
#define W_EXACT_FROM 40

struct dd_wrap {
    uint32_t n, cap_n;            /* neighbours, capacity of the arrays  */
    const double **pt;            /* local -> point                       */
    double *lift[4];              /* lift[i][k]: coordinate i of
                                     (x_k - q, |x_k - q|^2), rounded      */
    double *o;                    /* scan scratch, per local number       */
    double ierr, oerr;            /* the filters' error bounds (+inf: off) */
    double m;                     /* max |x_k - q_k| over the neighbours  */
    const double *q;
    int shifted;                  /* the shifted lifts were tried         */
    uint32_t nexact;              /* tests the filters left to the exact
                                     predicates, this deletion            */
    uint32_t *loc, cap_loc;       /* vertex id -> local number, valid for
                                     this deletion's neighbours only      */
    dd_trihash ftab;              /* triangle -> its facet record         */
    /* facet records */
    uint32_t (*tri)[3];           /* oriented triangle, local numbers     */
    uint32_t *own;                /* qdt facet 4c+j on the other side, or
                                     W_NONE for a link triangle           */
    uint32_t *out;                /* a link triangle's mesh facet outside
                                     the cavity                           */
    uint8_t *closed;
    uint32_t *stack, nrec, cap_rec;
};

void dd_wrap_free(struct dd_wrap *w)
{
    if (!w) return;
    free(w->pt);
    for (int i = 0; i < 4; i++) free(w->lift[i]);
    free(w->o); free(w->loc);
    dd_trihash_free(&w->ftab);
    free(w->tri); free(w->own); free(w->out); free(w->closed); free(w->stack);
    free(w);
}

static int grow(void **p, size_t n, size_t size)
{
    void *q = realloc(*p, n * size);
    if (!q) return 0;
    *p = q;
    return 1;
}

/* Room for n neighbours, and local numbers for vertex ids below nv. */
static dd_status w_reserve_n(struct dd_wrap *w, uint32_t n, uint32_t nv)
{
    if (n > w->cap_n) {
        uint32_t cap = w->cap_n ? w->cap_n : 64;
        while (cap < n) cap *= 2;
        if (!grow((void **)&w->pt, cap, sizeof *w->pt) || !grow((void **)&w->o, cap, sizeof *w->o))
            return DD_ERR_NOMEM;
        for (int i = 0; i < 4; i++)
            if (!grow((void **)&w->lift[i], cap, sizeof *w->lift[i])) return DD_ERR_NOMEM;
        w->cap_n = cap;
    }
    if (nv > w->cap_loc) {
        if (!grow((void **)&w->loc, nv, sizeof *w->loc)) return DD_ERR_NOMEM;
        w->cap_loc = nv;
    }
    return DD_OK;
}

/* A triangle's rank in a canonical order (its sorted local numbers, 21
 * bits each): picks the link triangle the wrap starts from.             */
static inline uint64_t w_tri_key(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t t;
    if (a > b) { t = a; a = b; b = t; }
    if (b > c) { t = b; b = c; c = t; }
    if (a > b) { t = a; a = b; b = t; }
    return (uint64_t)a << 42 | (uint64_t)b << 21 | c;
}

/* Room for one more facet record. */
static dd_status w_reserve_rec(struct dd_wrap *w)
{
    if (w->nrec == w->cap_rec) {
        uint32_t cap = w->cap_rec ? 2 * w->cap_rec : 256;
        if (!grow((void **)&w->tri, cap, sizeof *w->tri) || !grow((void **)&w->own, cap, sizeof *w->own) ||
            !grow((void **)&w->out, cap, sizeof *w->out) ||
            !grow((void **)&w->closed, cap, sizeof *w->closed) || !grow((void **)&w->stack, cap, sizeof *w->stack))
            return DD_ERR_NOMEM;
        w->cap_rec = cap;
    }
    return DD_OK;
}

/* Opens triangle (a, b, c), whose other side is qdt facet `own` (W_NONE:
 * a link triangle), as a new record; *val is its entry in w->ftab.      */
static void w_open(struct dd_wrap *w, uint32_t *val, uint32_t a, uint32_t b, uint32_t c, uint32_t own)
{
    uint32_t r = w->nrec++;
    w->tri[r][0] = a; w->tri[r][1] = b; w->tri[r][2] = c;
    w->own[r] = own;
    w->closed[r] = 0;
    *val = r;
}

/* Lifts the neighbours relative to q and sets the filters' bounds.
 *
 * In-sphere.  For points a, b, c, x, p the in-sphere determinant equals
 * det4(L[b]-L[a], L[c]-L[a], L[x]-L[a], L[p]-L[a]) with L[y] = (y - q,
 * |y - q|^2) (translate, then add to the lift a combination of the first
 * three columns); negative when p is inside the sphere of the positively
 * oriented a, b, c, x.  These are the entries of qsmall.c's filter (rows
 * L[v] - L[p] there), with the same bounds: columns 0-2 at most 2m with
 * errors at most 4um, column 3 at most 3m^2 with errors at most 36um^2,
 * m = max |y_k - q_k|.  wrap_scan evaluates the determinant by 2x2
 * minors of the first two rows, 3x3 cofactors with the third, a dot
 * product with the fourth: at most 9 roundings on any product path, so
 * qsmall.c's bound (10 roundings) holds: |error| < 1.8e-12 m^5, and the
 * filter answers only beyond 1e-11 m^5.
 *
 * Orientation.  orient3d(a, b, c, p) = det3 of the first three columns of
 * the same rows: entries at most 2m with errors at most 4um; the 6 terms
 * move by at most 6 * 3 * (2m)^2 * 4um = 288u m^3 from the entry errors,
 * and the evaluation (2x2 minors, then a 3-term dot product: 5 roundings)
 * adds at most gamma_5 * 48 m^3 < 241u m^3: in all below 6e-14 m^3; the
 * filter answers beyond 1e-13 m^3.
 *
 * Both only for 1e-55 <= m <= 1e55 (no overflow; underflow errors far
 * below the bounds); otherwise the bounds are +inf and the exact
 * predicates decide every test.                                          */
static void w_lift(struct dd_wrap *w, const double *q)
{
    double m = 0;
    double *L[4] = {w->lift[0], w->lift[1], w->lift[2], w->lift[3]};
    for (uint32_t k = 0; k < w->n; k++) {
        const double *p = w->pt[k];
        for (int i = 0; i < 3; i++) {
            L[i][k] = p[i] - q[i];
            double a = L[i][k] < 0 ? -L[i][k] : L[i][k];
            if (a > m) m = a;
        }
        L[3][k] = L[0][k] * L[0][k] + L[1][k] * L[1][k] + L[2][k] * L[2][k];
    }
    w->ierr = dd_lift_err(m);
    int ok = w->ierr != 1.0 / 0.0;
    w->oerr = ok ? 1e-13 * m * m * m : 1.0 / 0.0;
    w->m = m;
    w->q = q;
    w->shifted = !ok;
    w->nexact = 0;
}

/* Shifted lifts (qsmall.c's, whose bound they keep: the determinants of
 * wrap_scan have the same entries and at most as many roundings), for
 * nearly cospherical cavities where the plain filter abstains.  Tried
 * once per deletion, when a fast scan first fails its check, with at
 * least DD_SHIFT_FROM neighbours (below that the exact expansions of the
 * shift cost more than the tests they save, as in qsmall.c); the scan is
 * then run again.                                                        */
static void w_shift(struct dd_wrap *w)
{
    w->shifted = 1;
    double *const *L = w->lift, l[3][4];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) l[j][i] = L[i][j];
    double *o = w->o;                              /* scratch until the next scan */
    double err = dd_shift_lifts(w->pt, w->n, w->q, l[0], l[1], l[2], w->m, w->ierr, o);
    if (err == 0) return;
    memcpy(L[3], o, w->n * sizeof *o);
    w->ierr = err;
}

/* The fill cell on the positive side of open facet (a, b, c): the point p
 * with orient3d(a, b, c, p) > 0 whose sphere through a, b, c, p holds no
 * other such point (perturbed as CGAL does).  The spheres through a, b, c
 * are ordered along their pencil, so the point is a minimum; W_NONE if no
 * point is surely on the positive side (and none on abc's plane), W_BAIL
 * if none is beyond but some lie on the plane.
 *
 * With rows B = L[b]-L[a], C = L[c]-L[a] (see w_lift) and P = L[p]-L[a],
 * w(X, P) = det4(B, C, X, P) is the in-sphere determinant of a, b, c, x, p
 * (negative: p inside the sphere of the positively oriented a, b, c, x).
 * Its cofactors along the last row, K(X), give w(X, P) = K(X) . P; they
 * are made from the six 2x2 minors mij of B and C, whose three first
 * ones also give orient3d(a, b, c, p) = o(P) = n . P, n = (m12, -m02,
 * m01).  The form w is antisymmetric with kernel span(B, C), so with
 * N = (n, 0) and t(P) = K(N) . P,
 *     w(X, P) |n|^2 = o(X) t(P) - t(X) o(P),
 * and for x, p on the positive side, p is inside the sphere of a, b, c, x
 * iff t(p)/o(p) < t(x)/o(x): the fill cell's point minimises t/o.      */
static inline void w_cofactors(double K[4], const double X[4], const double m[6])
{
    enum { M01, M02, M03, M12, M13, M23 };
    K[0] = -(X[1] * m[M23] - X[2] * m[M13] + X[3] * m[M12]);
    K[1] = X[0] * m[M23] - X[2] * m[M03] + X[3] * m[M02];
    K[2] = -(X[0] * m[M13] - X[1] * m[M03] + X[3] * m[M01]);
    K[3] = X[0] * m[M12] - X[1] * m[M02] + X[2] * m[M01];
}

/* The exact scan: one pass keeping the best point so far, each test
 * filtered (bounds of w_lift) and else decided by the exact perturbed
 * predicates.  Its branches depend on the data, which costs where the
 * pattern is new: wrap_scan runs it only when the fast scan cannot
 * certify its answer.                                                    */
static uint32_t wrap_scan_exact(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c,
                                const double m[6])
{
    double *const *L = w->lift;
    double K[4] = {0, 0, 0, 0};
    const double oerr = w->oerr, ierr = w->ierr;
    uint32_t best = W_NONE;
    int zero = 0;
    for (uint32_t k = 0; k < w->n; k++) {
        if (k == a || k == b || k == c) continue;
        double P[4];
        for (int i = 0; i < 4; i++) P[i] = L[i][k] - L[i][a];
        double o = P[0] * m[3] - P[1] * m[1] + P[2] * m[0];
        if (!(o > oerr)) {
            if (o < -oerr) continue;
            w->nexact++;
            int or = dd_orient3d(pr, w->pt[a], w->pt[b], w->pt[c], w->pt[k]);
            zero |= or == 0;
            if (or <= 0) continue;
        }
        if (best != W_NONE) {
            double det = K[0] * P[0] + K[1] * P[1] + K[2] * P[2] + K[3] * P[3];
            if (det >= -ierr) {                  /* not surely inside */
                if (det > ierr) continue;        /* surely outside    */
                    w->nexact++;
                const double *cell[4] = {w->pt[a], w->pt[b], w->pt[c], w->pt[best]};
                if (!dd_points_conflict(pr, cell, -1, -1, w->pt[k])) continue;
            }
        }
        best = k;
        w_cofactors(K, P, m);
    }
    /* No point beyond: for a hull vertex, abc becomes a hull facet, the
     * cell (a, b, c, infinite).  With points in abc's plane the coplanar
     * hull rules of the perturbation would decide: left to the conflict
     * DT (W_BAIL).                                                       */
    return best == W_NONE && zero ? W_BAIL : best;
}

/* The fast scan, without data-dependent branches: o and t for every
 * point, the minimum of t/o in doubles, then a check of that candidate x
 * with the filtered determinant w(x, p) for every other point p on the
 * positive side.  The check proves the answer (every such p surely
 * outside the sphere of a, b, c, x; every orientation sure); when it
 * cannot, wrap_scan_exact decides.  Rounding (or overflow) in t/o can
 * only make the check fail, never pass a wrong point.  (Written with
 * SSE2 vectors, two points at a time, it ran 10% slower: register
 * spills.)                                                               */
static uint32_t wrap_scan(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c)
{
    double *const *L = w->lift;
    const double ax = L[0][a], ay = L[1][a], az = L[2][a], aw = L[3][a];
    double B[4] = {L[0][b] - ax, L[1][b] - ay, L[2][b] - az, L[3][b] - aw};
    double C[4] = {L[0][c] - ax, L[1][c] - ay, L[2][c] - az, L[3][c] - aw};
    double m[6] = {B[0] * C[1] - B[1] * C[0], B[0] * C[2] - B[2] * C[0], B[0] * C[3] - B[3] * C[0],
                   B[1] * C[2] - B[2] * C[1], B[1] * C[3] - B[3] * C[1], B[2] * C[3] - B[3] * C[2]};
    double N[4] = {m[3], -m[1], m[0], 0}, T[4], K[4];
    w_cofactors(T, N, m);
    const double oerr = w->oerr, ierr = w->ierr;
    const uint32_t n = w->n;
    /* a, b, c need no test of their own: o(a) is exactly 0 and o(b),
     * o(c) are 0 up to less than oerr (their exact value is 0), so each
     * counts once among the unsure orientations, never as a candidate. */
    double *o = w->o;
    int unsure = 0;
    double lo = 1.0 / 0.0;
    uint32_t best = W_NONE;
    for (uint32_t k = 0; k < n; k++) {
        double P0 = L[0][k] - ax, P1 = L[1][k] - ay, P2 = L[2][k] - az, P3 = L[3][k] - aw;
        double ok = P0 * N[0] + P1 * N[1] + P2 * N[2];
        double tk = P0 * T[0] + P1 * T[1] + P2 * T[2] + P3 * T[3];
        int pos = ok > oerr;
        unsure += !pos & (ok >= -oerr);
        o[k] = pos ? ok : -1.0;                 /* > oerr: a candidate */
        double lam = pos ? tk / ok : 1.0 / 0.0;
        int better = lam < lo;
        lo = better ? lam : lo;
        best = better ? k : best;
    }
    if (unsure != 3 || best == W_NONE) return wrap_scan_exact(w, pr, a, b, c, m);
    double X[4] = {L[0][best] - ax, L[1][best] - ay, L[2][best] - az, L[3][best] - aw};
    w_cofactors(K, X, m);
    o[best] = -1.0;                             /* not tested against itself */
    int bad = 0;
    for (uint32_t k = 0; k < n; k++) {
        double P0 = L[0][k] - ax, P1 = L[1][k] - ay, P2 = L[2][k] - az, P3 = L[3][k] - aw;
        double det = K[0] * P0 + K[1] * P1 + K[2] * P2 + K[3] * P3;
        bad |= (o[k] > oerr) & !(det > ierr);
    }
    if (!bad) return best;
    return w->shifted || n < DD_SHIFT_FROM ? wrap_scan_exact(w, pr, a, b, c, m) : W_SHIFT;
}

/* The fill cell on open facet (a, b, INF) (local numbers, rotated so that
 * the infinite vertex comes last): the cell (a, b, INF, p) whose hull
 * facet (b, a, p) has no point beyond it.  Seen along the hull edge ab,
 * the points lie in a wedge of less than a half-turn, and "x beyond the
 * plane of b, a, p" orders them by angle: one pass keeping the point
 * furthest round (Jarvis) finds p.  Exact predicates throughout (few
 * cells of a fill are infinite); W_BAIL when a point is in the plane of
 * b, a and the best so far, where the wedge may be a half-turn and the
 * perturbed in-circle rules of the hull would decide.                    */
static uint32_t wrap_scan_inf(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b)
{
    uint32_t best = W_NONE;
    for (uint32_t k = 0; k < w->n; k++) {
        if (k == a || k == b) continue;
        if (best == W_NONE) {
            if (dd_orient_coplanar(pr, w->pt[a], w->pt[b], w->pt[k]) != 0) best = k;
            continue;
        }
        int o = dd_orient3d(pr, w->pt[b], w->pt[a], w->pt[best], w->pt[k]);
        if (o == 0) return W_BAIL;
        if (o > 0) best = k;
    }
    /* Checked against the final point: none beyond, none in its plane. */
    for (uint32_t k = 0; k < w->n && best != W_NONE; k++) {
        if (k == a || k == b || k == best) continue;
        if (dd_orient3d(pr, w->pt[b], w->pt[a], w->pt[best], w->pt[k]) >= 0) return W_BAIL;
    }
    return best;
}

static int cmp_u32(const void *x, const void *y)
{
    uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
    return a < b ? -1 : a > b;
}

/* Sorts a[0..n) increasingly (n is small but for a few vertices). */
static void w_sort_ids(uint32_t *a, size_t n)
{
    if (n > 64) {
        qsort(a, n, sizeof *a, cmp_u32);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        uint32_t v = a[i];
        size_t j = i;
        for (; j > 0 && a[j - 1] > v; j--) a[j] = a[j - 1];
        a[j] = v;
    }
}

static dd_status w_get(dd_del *d, struct dd_wrap **out)
{
    if (!d->wrap) {
        d->wrap = calloc(1, sizeof *d->wrap);
        if (!d->wrap) return DD_ERR_NOMEM;
    }
    *out = d->wrap;
    return DD_OK;
}

static dd_status w_broken(dd_del *d, const char *what)
{
    return dd_fail(d->t, DD_ERR_INTERNAL, "gift wrapping the cavity of point %u: %s", d->t->v2in[d->q], what);
}

/* Room for `room` fill cells in all, `made` of them made already. */
static dd_status w_reserve_fill(dd_del *d, size_t made, size_t room)
{
    dd_status s = dd_reserve_cells(d->qdt, (uint32_t)(room - made));
    if (s == DD_OK) s = dd_vec_reserve(&d->fill, room);
    if (s == DD_OK) s = dd_vec_reserve(&d->sew_out, 4 * room);
    return s;
}

dd_status dd_wrap_fill(dd_del *d, int *declined)
{
    dd_tri *t = d->t, *x = d->qdt;
    *declined = 0;
    struct dd_wrap *w;
    dd_status s = w_get(d, &w);
    if (s == DD_OK) s = w_reserve_n(w, (uint32_t)d->order.n, t->nvid);
    if (s != DD_OK) return s;
    DD_PHASE_BEGIN(d);
    w_sort_ids(d->order.a, d->order.n);
    const uint32_t *gid = d->order.a;
    const uint32_t n = w->n = (uint32_t)d->order.n, inf = n;   /* DD_INF's local number */
    for (uint32_t k = 0; k < n; k++) {
        w->pt[k] = dd_pt(t, gid[k]);
        w->loc[gid[k]] = k;
    }
    w_lift(w, d->qp);
    dd_qdt_reset(d, 0);
    w->nrec = 0;
    size_t room = 4 * (size_t)n + 16;                /* fill cells, grown below */
    s = dd_trihash_reset(&w->ftab, 4 * (size_t)n);
    if (s == DD_OK) s = w_reserve_fill(d, 0, room);
    if (s != DD_OK) return s;
    /* The link triangles, open towards q, all in the table; the wrap
     * starts from one of them and reaches the others through the fill
     * (a triangulated ball: its cells are connected through interior
     * facets).  The start is the triangle of least key, rotated to begin
     * with its least local number: with the neighbours sorted by id, the
     * whole wrap, and so the order and rotation of the fill cells, does
     * not depend on how the star was stored.  The same deletion repeated
     * is the same computation, as with the other strategies.             */
    uint64_t kmin = UINT64_MAX;
    uint32_t rmin = 0;
    for (size_t k = 0; k < d->star.n; k++) {
        uint32_t c = d->star.a[k];
        const uint32_t *v = t->tv + 4 * (size_t)c;
        int i = dd_index_of(t, c, d->q);
        uint32_t lv[3];
        for (int j = 0; j < 3; j++) {
            uint32_t g = v[dd_facet[i][j]];
            if (g == DD_INF) {
                lv[j] = inf;
                continue;
            }
            if (g >= t->nvid || w->loc[g] >= n || gid[w->loc[g]] != g)
                return w_broken(d, "a link vertex is not a neighbour");
            lv[j] = w->loc[g];
        }
        int found;
        uint32_t *val = dd_trihash_slot(&w->ftab, lv[0], lv[1], lv[2], &found);
        if (!val || (s = w_reserve_rec(w)) != DD_OK) return DD_ERR_NOMEM;
        if (found) return w_broken(d, "a link triangle appears twice");
        uint64_t key = w_tri_key(lv[0], lv[1], lv[2]);
        if (key < kmin) { kmin = key; rmin = w->nrec; }
        w->out[w->nrec] = t->tn[4 * (size_t)c + (uint32_t)i];
        w_open(w, val, lv[0], lv[1], lv[2], W_NONE);
    }
    if (w->nrec == 0) return w_broken(d, "no link triangle");
    uint32_t *st = w->tri[rmin];
    while (st[0] > st[1] || st[0] > st[2]) {      /* rotate: same orientation */
        uint32_t x0 = st[0];
        st[0] = st[1]; st[1] = st[2]; st[2] = x0;
    }
    /* Wrap: each open facet gives the cell on its open side.  Each facet
     * of a new cell goes in d->sew_out for the sew: a link triangle's
     * outside facet, or DD_NONE inside the fill.                         */
    uint32_t ns = 0, nlink = 0;
    w->stack[ns++] = rmin;
    size_t limit = 8 * (size_t)n * n + 64;          /* |fill| is O(n^2) */
    while (ns > 0) {
        uint32_t r = w->stack[--ns];
        if (w->closed[r]) continue;
        w->closed[r] = 1;
        uint32_t a = w->tri[r][0], b = w->tri[r][1], e = w->tri[r][2], p;
        if (n >= W_EXACT_FROM && w->nexact > 2 * n) {
            *declined = 1;                      /* see W_EXACT_FROM */
            return DD_OK;
        }
        if (a == inf || b == inf || e == inf) {
            while (e != inf) {                  /* rotate: same orientation */
                uint32_t a0 = a;
                a = b; b = e; e = a0;
            }
            p = wrap_scan_inf(w, &x->pred, a, b);
        } else {
            p = wrap_scan(w, &x->pred, a, b, e);
            if (p == W_SHIFT) {
                w_shift(w);
                p = wrap_scan(w, &x->pred, a, b, e);
            }
            if (p == W_NONE && d->on_hull) p = inf;
        }
        if (p == W_BAIL) {
            *declined = 1;
            return DD_OK;
        }
        if (p == W_NONE) return w_broken(d, "an open facet has no point beyond it");
        size_t fp = d->fill.n;
        if (fp >= limit) return w_broken(d, "the fill does not close");
        if (fp == room && (s = w_reserve_fill(d, fp, room *= 2)) != DD_OK) return s;
        uint32_t m = dd_new_cell(x), lv[4] = {a, b, e, p};
        uint32_t *tv = x->tv + 4 * (size_t)m, *tn = x->tn + 4 * (size_t)m, *so = d->sew_out.a + 4 * fp;
        for (int i = 0; i < 4; i++) tv[i] = lv[i] == inf ? DD_INF : gid[lv[i]];
        tn[3] = w->own[r];
        if (w->own[r] != W_NONE) {
            x->tn[w->own[r]] = 4 * m + 3;
            so[3] = DD_NONE;
        } else {
            so[3] = w->out[r];
            nlink++;
        }
        for (uint32_t j = 0; j < 3; j++) {
            uint32_t f0 = lv[dd_facet[j][0]], f1 = lv[dd_facet[j][1]], f2 = lv[dd_facet[j][2]];
            int found;
            uint32_t *val = dd_trihash_slot(&w->ftab, f0, f1, f2, &found);
            if (!val) return DD_ERR_NOMEM;
            if (found) {                         /* its other side is known */
                uint32_t o = *val;
                if (w->closed[o]) return w_broken(d, "a triangle bounds three cells");
                w->closed[o] = 1;
                tn[j] = w->own[o];
                if (w->own[o] != W_NONE) {
                    x->tn[w->own[o]] = 4 * m + j;
                    so[j] = DD_NONE;
                } else {
                    so[j] = w->out[o];
                    nlink++;
                }
                continue;
            }
            s = w_reserve_rec(w);
            if (s != DD_OK) return s;
            tn[j] = DD_NONE;
            so[j] = DD_NONE;
            w->stack[ns++] = w->nrec;
            w_open(w, val, f1, f0, f2, 4 * m + j);       /* reversed: open outwards */
        }
        d->fill.a[d->fill.n++] = m;
    }
    /* Each link triangle closed at most once (above), so all of them
     * exactly once: the sew needs no matching of its own.               */
    if (nlink != d->star.n) return w_broken(d, "the fill does not cover the link");
    d->sew_direct = 1;
    x->tets_created = d->fill.n;
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return DD_OK;
}
