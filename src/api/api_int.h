/*
 * api_int.h -- what the files of the API layer (src/api/) share and the
 * library does not export: the first steps of an insertion, which the
 * single calls and the batch calls (batch.c) take alike.
 */
#ifndef DD_API_INT_H
#define DD_API_INT_H

#include "dtdel.h"
#include "mesh/mesh.h"
#include "mesh/hidden.h"

/* Checks p (DD_ERR_NAN, DD_ERR_INFINITE) and hint (-1 or a live cell,
 * else DD_ERR_UNKNOWN_CELL), each failure with its message and nothing
 * changed, and gives the cell where the insertion's walk starts: hint,
 * or for -1 one near p (the location grid made ready).                  */
dd_status dd_insert_start(dd_tri *t, const double p[3], dd_cell_id hint, uint32_t *start);

/* A vertex id for a new point of an unweighted t: a deleted one to reuse
 * (*reused = 1, keeping that slot's input index; never with
 * DD_STABLE_INDICES, whose free list stays empty), or the next unused one
 * (t->nvid, input index t->np; the caller advances both once it is a
 * vertex), the vertex arrays grown if needed (DD_ERR_NOMEM).            */
dd_status dd_new_vertex_id(dd_tri *t, uint32_t *v, int *reused);

/* Puts vertex id v (its point, and weight, as they were) back into t:
 * the undo of its deletion.  On a weighted t by CGAL's rule, so that a
 * point that was hidden is hidden again (keep mode is the regular
 * triangulation of the points in t, whatever the order).               */
dd_status dd_put_back(dd_tri *t, uint32_t v);

/* Checks a batch's m points and weights (w NULL: none): DD_ERR_NAN /
 * DD_ERR_INFINITE naming the position of the first bad one, DD_ERR_NOMEM
 * for m beyond 32-bit ids; with t's message.  O(m).                     */
dd_status dd_check_batch(dd_tri *t, const double *xyz, const double *w, size_t m);

/* Whether vertex id v is in t: a vertex or a kept hidden point. */
static inline int dd_present(const dd_tri *t, uint32_t v)
{
    return t->vcell[v] != DD_NONE || dd_hidden_has(t, v);
}

#endif
