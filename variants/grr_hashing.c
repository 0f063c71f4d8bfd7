/*
 * grr_hashing.c -- GRR-Hashing (paper 5): a random link vertex of degree
 * <= 7, deleted with the low-degree link deletion; its guide is one of the
 * triangles that deletion creates, found again in the conflict DT as its
 * dummy cell through a hash table keyed by the vertex triple (the paper
 * used a search tree).  Fallback (counted): a random remaining vertex when
 * none of degree <= 7 is left besides the base.
 */
#include "delete/grr.h"

static uint32_t hashing_sample(dd_grr *g, uint32_t *guide)
{
    *guide = DD_NONE;
    return dd_grr_sample_lowdeg(g);
}

static const dd_grr_policy hashing_policy = {hashing_sample, 1, 0};

static dd_status grr_hashing_fill(dd_del *d) { return dd_grr_construct(d, &hashing_policy); }

const dd_variant dd_variant_grr_hashing = {
    "grr-hashing",
    "GRR, random link vertex of degree <= 7, guide = a new link triangle via a hash",
    grr_hashing_fill,
    grr_hashing_fill,     /* weighted points: the conflict RT (grr.h) */
};
