/*
 * guide_only.c -- guide-only (paper 5, the variants table): GRR-Edge's
 * sampling and edge guides (dd_grr_sample_edge), but the full DT(P) of
 * q's neighbours is built and then sewn, not the conflict DT: it
 * separates the gain of the guides from that of DT(x).
 */
#include "delete/grr.h"

static const dd_grr_policy guide_only_policy = {dd_grr_sample_edge, 0, 1};

static dd_status guide_only_fill(dd_del *d) { return dd_grr_construct(d, &guide_only_policy); }

const dd_variant dd_variant_guide_only = {
    "guide-only",
    "full DT of the neighbours with edge sampling and edge guides, then sew",
    guide_only_fill,
    guide_only_fill,     /* weighted points: the conflict RT (grr.h) */
};
