/*
 * grr_neighbor.c -- GRR-Neighbor (paper 5): a random link vertex of degree
 * <= 7, deleted with the low-degree link deletion; its guide is its
 * lowest-degree (finite) link neighbour.  Fallback (counted): a random
 * remaining vertex when none of degree <= 7 is left besides the base.
 */
#include "delete/grr.h"

static uint32_t neighbor_sample(dd_grr *g, uint32_t *guide)
{
    uint32_t u = dd_grr_sample_lowdeg(g);
    *guide = dd_grr_lowest_neighbour(g, u);
    return u;
}

static const dd_grr_policy neighbor_policy = {neighbor_sample, 0, 0};

static dd_status grr_neighbor_fill(dd_del *d) { return dd_grr_construct(d, &neighbor_policy); }

const dd_variant dd_variant_grr_neighbor = {
    "grr-neighbor",
    "GRR, random link vertex of degree <= 7, guide = its lowest-degree neighbour",
    grr_neighbor_fill,
    grr_neighbor_fill,     /* weighted points: the conflict RT (grr.h) */
};
