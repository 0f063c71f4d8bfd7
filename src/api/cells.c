/*
 * cells.c -- the cell handles of dtdel.h: a cell id is the cell's slot in
 * the mesh (mesh.h), so reading a cell is O(1); location from a hint;
 * the cells the last edit made (recorded by mesh/cells.c).  Read-only:
 * nothing here writes to t, so these calls may run side by side on one
 * triangulation (their scratch, the predicates' and the walk's random
 * state, is the call's own).
 */
#include "dtdel.h"
#include "mesh/mesh.h"

#include <math.h>
#include <string.h>

dd_cell_id dd_cell_end(const dd_tri *t)
{
    return (dd_cell_id)t->ncell;
}

int dd_cell_alive(const dd_tri *t, dd_cell_id c)
{
    return c >= 0 && c < (dd_cell_id)t->ncell && dd_tv(t, (uint32_t)c)[0] != DD_DEAD;
}

dd_status dd_cell(const dd_tri *t, dd_cell_id c, int32_t v[4], dd_cell_id nbr[4])
{
    if (!dd_cell_alive(t, c)) return DD_ERR_UNKNOWN_CELL;
    const uint32_t *tv = dd_tv(t, (uint32_t)c), *tn = dd_tn(t, (uint32_t)c);
    for (int i = 0; i < 4; i++) {
        if (v) v[i] = dd_input_index(t, tv[i]);
        if (nbr) nbr[i] = (dd_cell_id)(tn[i] >> 2);
    }
    return DD_OK;
}

dd_status dd_locate_from(const dd_tri *t, const double p[3], dd_cell_id hint, dd_cell_id *cell)
{
    *cell = -1;
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return DD_ERR_NAN;
        if (isinf(p[c])) return DD_ERR_INFINITE;
    }
    if (hint != -1 && !dd_cell_alive(t, hint)) return DD_ERR_UNKNOWN_CELL;
    const uint32_t start = hint == -1 ? dd_start_near(t, p) : (uint32_t)hint;
    /* the walk's random state: seeded by the query, so a query repeated
     * walks the same way                                                */
    uint64_t bits[3], rng;
    memcpy(bits, p, sizeof bits);
    rng = dd_mix64(bits[0] ^ dd_mix64(bits[1] ^ dd_mix64(bits[2] + start))) | 1;
    dd_pred pr;
    dd_pred_init(&pr);
    uint32_t c = DD_NONE;
    const dd_status s = dd_walk_const(t, &pr, &rng, p, start, &c);
    dd_pred_clear(&pr);
    if (s == DD_OK) *cell = c;
    return s;
}

dd_status dd_created_cells(const dd_tri *t, const dd_cell_id **cells, size_t *n)
{
    *cells = t->made.list;
    *n = t->made.lost ? 0 : t->made.n;
    return t->made.lost ? DD_ERR_NOMEM : DD_OK;
}
