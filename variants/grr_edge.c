/*
 * grr_edge.c -- GRR-Edge (paper 5, the variants table): the point and its
 * guide are sampled together as a random link edge uv with deg(u) <= 7 and
 * deg(u) + deg(v) <= 15; u is deleted, v is its guide.
 *
 * Sampling: u is drawn uniformly among the link vertices of degree <= 7;
 * among u's finite neighbours v with deg(u) + deg(v) <= 15 one is drawn
 * uniformly.  Up to 8 draws of u are tried.  Fallback (counted): the last
 * drawn u with its lowest-degree finite neighbour as guide, or, when no
 * vertex of degree <= 7 is left besides the base points, a random vertex.
 */
#include "delete/grr.h"

static uint32_t edge_sample(dd_grr *g, uint32_t *guide)
{
    uint32_t nb[DD_LOWDEG + 1], u = DD_NONE;
    for (int tries = 0; tries < 8; tries++) {
        u = dd_grr_random_lowdeg(g);
        if (u == DD_NONE) break;
        uint32_t du = dd_grr_degree(g, u), k = dd_grr_neighbours(g, u, nb, DD_LOWDEG + 1), ok = 0;
        for (uint32_t j = 0; j < k; j++)
            if (nb[j] != DD_INF && du + dd_grr_degree(g, nb[j]) <= 15) nb[ok++] = nb[j];
        if (ok) {
            *guide = nb[dd_grr_rand(g) % ok];
            return u;
        }
    }
    dd_grr_fallback(g);
    if (u == DD_NONE) u = dd_grr_random_any(g);
    *guide = dd_grr_lowest_neighbour(g, u);
    return u;
}

static const dd_grr_policy edge_policy = {edge_sample, 0, 0};

static dd_status grr_edge_fill(dd_del *d) { return dd_grr_construct(d, &edge_policy); }

const dd_variant dd_variant_grr_edge = {
    "grr-edge",
    "GRR, random link edge uv, deg(u) <= 7, deg(u)+deg(v) <= 15, guide v",
    grr_edge_fill,
};

/* guide-only: the same sampling and guides, but the full DT(P) is built
 * and then sewn (paper 5: separates the gain of guides from that of DT(x)). */
static const dd_grr_policy guide_only_policy = {edge_sample, 0, 1};

static dd_status guide_only_fill(dd_del *d) { return dd_grr_construct(d, &guide_only_policy); }

const dd_variant dd_variant_guide_only = {
    "guide-only",
    "full DT of the neighbours with edge sampling and edge guides, then sew",
    guide_only_fill,
};
