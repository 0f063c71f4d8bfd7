/*
 * grr_brio.c -- GRR-BRIO (paper 4.2 "BRIO sampling", Theorem 4(ii)):
 * gradation rounds with degree-3 spanning-tree guides.
 *
 * Gradation: starting from all deletable link vertices (the four base
 * points excepted), each round keeps every point with probability 1/2;
 * the points not kept form the round.  Per round, on the current link
 * DT^l(S_i + q): a spanning tree of maximum degree 3 (delete/bdst.h,
 * linear time), rooted at a base point, is stored with its BFS order; then the
 * round's points are deleted from the link.  Construction: DT(x) of the
 * base, then the rounds in reverse; inside a round the points are
 * inserted in the BFS order of its tree, each located from its tree
 * parent, which is always present by then (inserted earlier in the BFS or
 * kept by the smaller set).  A parent that is the infinite vertex is no
 * guide: then the point's BFS-earliest finite link neighbour is used, or,
 * if none precedes it, a counted scan.  On a weighted t the same rounds
 * build the conflict regular triangulation (qdt.h), the base among the
 * neighbours, the star's hidden points inserted after them.
 */
#include "delete/grr.h"
#include "delete/qdt.h"
#include "delete/bdst.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

/* Scratch kept in the deletion context across deletions (a strategy
 * scratch, dd_del_scratch): per-vertex arrays sized to the vertex
 * capacity, per-link arrays sized to the largest degree seen.           */
typedef struct brio_buf {
    uint32_t *loc, *mark, *rmark;   /* per vertex id                     */
    size_t vcap;
    uint32_t gen;
    uint32_t *ids, *tri, *parent, *order, *seq, *guide, *cur;   /* per link */
    size_t lcap;
    uint32_t round_end[65];
    dd_bdst_ws *ws;
} brio_buf;

static void brio_buf_free(void *p)
{
    brio_buf *b = p;
    if (!b) return;
    dd_mfree(b->loc); dd_mfree(b->mark); dd_mfree(b->rmark);
    dd_mfree(b->ids); dd_mfree(b->tri); dd_mfree(b->parent); dd_mfree(b->order); dd_mfree(b->seq); dd_mfree(b->guide); dd_mfree(b->cur);
    dd_bdst_ws_free(b->ws);
    dd_mfree(b);
}

static const dd_scratch_kind brio_kind = {"grr-brio", brio_buf_free};

/* The scratch kept in d (made on first use), sized for d's vertices and
 * a link of degree deg.                                                 */
static dd_status get_buf(dd_del *d, size_t deg, brio_buf **out)
{
    brio_buf *b = dd_del_scratch(d, &brio_kind);
    if (!b) {
        b = dd_calloc(1, sizeof *b);
        if (!b || !(b->ws = dd_bdst_ws_new())) { dd_mfree(b); return DD_ERR_NOMEM; }
        dd_status s = dd_del_keep_scratch(d, &brio_kind, b);
        if (s != DD_OK) return s;
    }
    const size_t u = sizeof(uint32_t);
    if (b->vcap < d->t->cap_v) {
        size_t n = d->t->cap_v;
        if (dd_grow(&b->loc, n, u) || dd_grow(&b->mark, n, u) || dd_grow(&b->rmark, n, u)) return DD_ERR_NOMEM;
        memset(b->mark, 0, n * u);           /* marks of generation 0 */
        memset(b->rmark, 0, n * u);
        b->vcap = n;
        b->gen = 0;
    }
    if (b->lcap < 2 * (deg + 2)) {   /* seq holds the records and a round */
        size_t n = 2 * (deg + 2);
        if (dd_grow(&b->ids, n, u) || dd_grow(&b->tri, 6 * n + 24, u) || dd_grow(&b->parent, n, u) ||
            dd_grow(&b->order, n, u) || dd_grow(&b->seq, n, u) || dd_grow(&b->guide, n, u) ||
            dd_grow(&b->cur, n, u))
            return DD_ERR_NOMEM;
        b->lcap = n;
    }
    *out = b;
    return DD_OK;
}

/* GRR-BRIO's fill: the rounds on the link (steps 1-4), then the conflict
 * DT built round by round from the last (step 5).                      */
static dd_status brio_fill(dd_del *d)
{
    dd_grr *g;
    brio_buf *b;
    const int weighted = d->t->wt != NULL;
    if (weighted && dd_qdt_weighted_base(d) != DD_OK) return dd_full_fill_power(d);
    dd_status s = dd_grr_begin(d, &g);
    if (s == DD_OK) s = get_buf(d, d->nbr.n, &b);
    if (s != DD_OK) return s;
    dd_link *l = dd_grr_link(g);
    size_t nrem;
    const uint32_t *remv = dd_grr_remaining(g, &nrem);
    size_t ncur = nrem, nseq = 0, nrounds = 0;
    if (nrem > 0) memcpy(b->cur, remv, nrem * sizeof *b->cur);   /* an empty list may have no array */

    DD_PHASE_BEGIN(d);
    while (ncur > 0 && s == DD_OK && nrounds < 64) {
        /* 1. The round: the points a fair coin does not keep. */
        if (++b->gen == 0) {
            memset(b->mark, 0, b->vcap * sizeof *b->mark);
            memset(b->rmark, 0, b->vcap * sizeof *b->rmark);
            b->gen = 1;
        }
        uint32_t gen = b->gen;
        size_t nround = 0;
        for (size_t k = 0; k < ncur; k++)
            if (!(dd_del_rand(d) & 1)) { b->rmark[b->cur[k]] = gen; nround++; }
        if (nround == 0) continue;            /* empty round: flip again */
        /* 2. The tree of the current link, rooted at a base point. */
        uint32_t nv = 0, nt = 0, inf_local = DD_NONE;
        for (uint32_t t = 0; t < l->ntri; t++) {
            if (l->lv[3 * t] == DD_DEAD) continue;
            for (uint32_t m = 0; m < 3; m++) {
                uint32_t w = l->lv[3 * t + m];
                if (w == DD_INF) {
                    if (inf_local == DD_NONE) { inf_local = nv; b->ids[nv++] = DD_INF; }
                    b->tri[3 * nt + m] = inf_local;
                    continue;
                }
                if (b->mark[w] != gen) { b->mark[w] = gen; b->loc[w] = nv; b->ids[nv++] = w; }
                b->tri[3 * nt + m] = b->loc[w];
            }
            nt++;
        }
        int bs = dd_bdst(b->ws, b->tri, nt, nv, b->loc[d->base[0]], b->parent, b->order);
        if (bs != DD_BDST_OK) {
            s = bs == DD_BDST_ENOMEM ? DD_ERR_NOMEM : DD_ERR_INTERNAL;
            break;
        }
        /* 3. The round's points in BFS order, each with its tree parent. */
        for (uint32_t k = 0; k < nv; k++) {
            uint32_t w = b->ids[b->order[k]];
            if (w == DD_INF || b->rmark[w] != gen) continue;
            uint32_t par = b->parent[b->order[k]];
            uint32_t gd = par == UINT32_MAX ? DD_NONE : b->ids[par];
            b->seq[nseq] = w;
            b->guide[nseq] = gd == DD_INF ? DD_NONE : gd;   /* INF: counted scan */
            nseq++;
        }
        b->round_end[nrounds++] = (uint32_t)nseq;
        /* 4. Delete the round's points from the link, the ones of low link
         *    degree first (passes with a growing degree bound): the order
         *    inside a round is free, and small holes are cheap to fill.    */
        size_t w2 = 0, nleft = 0;
        for (size_t k = 0; k < ncur; k++) {
            if (b->rmark[b->cur[k]] == gen) b->seq[nseq + nleft++] = b->cur[k];   /* scratch */
            else b->cur[w2++] = b->cur[k];
        }
        for (uint32_t bound = DD_LOWDEG; nleft > 0 && s == DD_OK; bound *= 2) {
            size_t keep = 0;
            for (size_t k = 0; k < nleft && s == DD_OK; k++) {
                uint32_t w = b->seq[nseq + k];
                if (dd_grr_degree(g, w) <= bound) s = dd_grr_delete_point(g, w);
                else b->seq[nseq + keep++] = w;
            }
            nleft = keep;
        }
        ncur = w2;
    }
    DD_PHASE_END(d, DD_PH_LINK);
    if (s == DD_OK && ncur > 0) s = DD_ERR_INTERNAL;   /* 64 rounds: never in practice */
    if (s != DD_OK) return s;

    /* 5. The conflict DT: the base, then the rounds from the last one. */
    dd_qdt_reset(d, 1);
    s = weighted ? dd_qdt_create_power(d) : dd_qdt_create(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (size_t r = nrounds; r-- > 0 && s == DD_OK;) {
        size_t lo = r ? b->round_end[r - 1] : 0, hi = b->round_end[r];
        for (size_t k = lo; k < hi && s == DD_OK; k++) {
            uint32_t c = DD_NONE;
            s = dd_grr_locate(g, b->guide[k], b->seq[k], &c);
            DD_PHASE_END(d, DD_PH_LOCATE);
            if (s == DD_OK) s = weighted ? dd_qdt_insert_power(d, b->seq[k], c) : dd_qdt_insert(d, b->seq[k], c);
            DD_PHASE_END(d, DD_PH_CONFLICT);
        }
    }
    if (s == DD_OK && weighted) s = dd_qdt_insert_hidden(d);   /* after every neighbour */
    return s == DD_OK ? dd_qdt_collect_fill(d) : s;
}

const dd_variant dd_variant_grr_brio = {
    "grr-brio",
    "GRR with BRIO rounds (p = 1/2), guides along a degree-3 spanning tree per round",
    brio_fill,
    brio_fill,             /* weighted points: the conflict RT (qdt.h) */
};
