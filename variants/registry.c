/*
 * registry.c -- the table of deletion strategies (DESIGN 6).  Adding a
 * variant is one file in variants/ and one line here.  The first entry is
 * the default of dd_delete(...) and of the CLI: the fastest correct
 * one, as measured by the bench.
 */
#include "delete/delete.h"

extern const dd_variant dd_variant_auto, dd_variant_grr_edge, dd_variant_grr_neighbor, dd_variant_grr_hashing,
    dd_variant_guide_only, dd_variant_dtq_only, dd_variant_sew_full, dd_variant_grr_brio,
    dd_variant_gift_wrap;

const dd_variant *const dd_variant_table[] = {
    &dd_variant_auto,
    &dd_variant_grr_edge,
    &dd_variant_grr_neighbor,
    &dd_variant_grr_hashing,
    &dd_variant_grr_brio,
    &dd_variant_guide_only,
    &dd_variant_dtq_only,
    &dd_variant_sew_full,
    &dd_variant_gift_wrap,
    NULL,
};
