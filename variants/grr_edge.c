/*
 * grr_edge.c -- GRR-Edge (paper 5, the variants table): the point and its
 * guide are sampled together as a random link edge uv with deg(u) <= 7 and
 * deg(u) + deg(v) <= 15; u is deleted, v is its guide.
 *
 * The sampling is dd_grr_sample_edge (grr.c), which guide-only shares.
 */
#include "delete/grr.h"

static const dd_grr_policy edge_policy = {dd_grr_sample_edge, 0, 0};

static dd_status grr_edge_fill(dd_del *d) { return dd_grr_construct(d, &edge_policy); }

const dd_variant dd_variant_grr_edge = {
    "grr-edge",
    "GRR, random link edge uv, deg(u) <= 7, deg(u)+deg(v) <= 15, guide v",
    grr_edge_fill,
    grr_edge_fill,     /* weighted points: the conflict RT (grr.h) */
};
