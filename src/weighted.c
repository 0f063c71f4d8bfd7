/*
 * weighted.c -- the public calls of dtdel.h on weighted points (DESIGN 12).
 *
 * PLACEHOLDER while issue 43 is under way: every call answers as on an
 * unweighted triangulation or refuses with DD_ERR_UNSUPPORTED.  The engine
 * work replaces these bodies; nothing may ship with them.
 */
#include "dtdel.h"
#include "mesh/mesh.h"

#include <stdlib.h>

int dd_is_weighted(const dd_tri *t) { (void)t; return 0; }

dd_status dd_weight(const dd_tri *t, uint32_t i, double *w)
{
    if (i >= t->np) return DD_ERR_ARG;
    *w = 0;
    return DD_OK;
}

int dd_is_hidden(const dd_tri *t, uint32_t i) { (void)t; (void)i; return 0; }

dd_status dd_hidden(const dd_tri *t, uint32_t **idx, size_t *n)
{
    (void)t;
    *idx = NULL;
    *n = 0;
    return DD_OK;
}

dd_status dd_insert_weighted(dd_tri *t, const double p[3], double w, uint32_t *index)
{
    (void)t; (void)p; (void)w; (void)index;
    return DD_ERR_UNSUPPORTED;
}
