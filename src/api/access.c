/*
 * access.c -- the public calls of dtdel.h whose work the mesh layer does:
 * construction, weighted or not, and the validator (handed over to src/mesh), the
 * canonical form and its hash, status names, and the small accessors.
 * Defined here, in the API layer, so that no layer below includes the
 * public header (docs/architecture.md).
 */
#include "dtdel.h"
#include "mesh/mesh.h"
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The flags dd_create_ex knows. */
#define KNOWN_FLAGS ((unsigned)DD_STABLE_INDICES | (unsigned)DD_DISCARD_HIDDEN | DD_THREADS(DD_THREADS_MASK) | \
                     (unsigned)DD_THREADS_ALL)
_Static_assert(DD_DISCARD_HIDDEN == DD_DISCARD_HIDDEN_FLAG, "mesh.h's copy of DD_DISCARD_HIDDEN");
_Static_assert(DD_THREADS_ALL == DD_THREADS_ALL_FLAG, "mesh.h's copy of DD_THREADS_ALL");
_Static_assert(DD_THREADS(1) == 1u << DD_THREADS_SHIFT && DD_THREADS(DD_THREADS_MASK) >> DD_THREADS_SHIFT ==
                   DD_THREADS_MASK, "mesh.h's copy of DD_THREADS");

dd_status dd_create_ex(dd_tri **out, const double *xyz, const double *weights, uint32_t n, unsigned flags,
                       char *msg, size_t msglen)
{
    dd_status s;
    *out = NULL;
    if (msg && msglen) msg[0] = 0;
    if (flags & ~KNOWN_FLAGS) {
        s = DD_ERR_ARG;
        if (msg && msglen) snprintf(msg, msglen, "unknown flag bits 0x%x", flags & ~KNOWN_FLAGS);
    } else {
        s = dd_mesh_create(out, xyz, weights, n, flags, msg, msglen);
    }
    if (s != DD_OK && msg && msglen && !msg[0]) snprintf(msg, msglen, "%s", dd_status_name(s));
    return s;
}

void dd_set_threads(dd_tri *t, unsigned n)
{
    t->nthreads = n == 0 ? dd_cores() : n > DD_THREADS_MAX ? DD_THREADS_MAX : n;
}

unsigned dd_threads(const dd_tri *t)
{
    return t->nthreads;
}

dd_status dd_create(dd_tri **out, const double *xyz, uint32_t n, char *msg, size_t msglen)
{
    return dd_create_ex(out, xyz, NULL, n, 0, msg, msglen);
}

dd_status dd_check(const dd_tri *t) { return dd_mesh_check(t, NULL, 0); }

dd_status dd_check_msg(const dd_tri *t, char *msg, size_t msglen) { return dd_mesh_check(t, msg, msglen); }

const char *dd_status_name(dd_status s) { return dd_status_text(s); }

const char *dd_errmsg(const dd_tri *t) { return t->errmsg; }
uint32_t dd_num_input(const dd_tri *t) { return t->np; }
uint32_t dd_num_vertices(const dd_tri *t) { return t->nvert; }
uint32_t dd_num_duplicates(const dd_tri *t) { return t->ndup; }
size_t dd_num_tets(const dd_tri *t) { return t->nlive; }
size_t dd_num_finite_tets(const dd_tri *t) { return t->nfinite; }

uint32_t dd_alias(const dd_tri *t, uint32_t i)
{
    return i < t->np ? t->v2in[t->in2v[i]] : UINT32_MAX;
}

int dd_is_vertex(const dd_tri *t, uint32_t i)
{
    if (i >= t->np) return 0;
    uint32_t v = t->in2v[i];
    return t->v2in[v] == i && t->vcell[v] != DD_NONE;
}

size_t dd_memory_bytes(const dd_tri *t)
{
    /* cells: records (plus the alignment slack), stamp; vertices: xyz,
     * vcell, v2in; inputs: in2v; insertion scratch: the three vectors,
     * the edge hash and table; the location grid and the reusable ids;
     * the predicates' GMP numbers                                        */
    return (size_t)t->cap_c * (DD_CELL_WORDS * sizeof(uint32_t) + sizeof(dd_mark)) + (t->cell_block ? 64 : 0)
         + (size_t)t->cap_v * (3 * sizeof(double) + 2 * sizeof(uint32_t))
         + (size_t)t->cap_in * sizeof(uint32_t)
         + (t->stack.cap + t->conflict.cap + t->boundary.cap + t->vfree.cap) * sizeof(uint32_t)
         + (t->flip[0].cap + t->flip[1].cap + t->flip[2].cap + t->flip[3].cap + t->flip[4].cap) * sizeof(uint32_t)
         + t->grid.cap * sizeof(uint32_t)
         + (size_t)t->ehash_cap * sizeof(dd_edge_slot)
         + (t->etab ? DD_STAR_MAXV * DD_STAR_MAXV * sizeof(uint32_t) : 0)
         + t->made.cap * sizeof(int64_t)
         + (t->wt ? (size_t)t->cap_v * sizeof(double) : 0) + dd_hidden_bytes(t)
         + (t->pred.limbs ? (size_t)DD_PRED_SCRATCH * DD_PRED_LIMBS * sizeof(mp_limb_t) : 0);
}

dd_status dd_canonical(const dd_tri *t, int32_t **tets, size_t *ntets)
{
    uint32_t *live = dd_malloc((t->nlive ? t->nlive : 1) * sizeof *live);
    if (!live) return DD_ERR_NOMEM;
    size_t n = 0;
    for (uint32_t c = 0; c < t->ncell; c++)
        if (dd_tv(t, c)[0] != DD_DEAD) live[n++] = c;
    dd_status s = dd_canonical_of_cells(t, live, n, tets, ntets);
    dd_mfree(live);
    return s;
}

uint64_t dd_canonical_hash(const int32_t *tets, size_t ntets)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < 4 * ntets; i++) {
        uint32_t x = (uint32_t)tets[i];
        for (int b = 0; b < 4; b++) {
            h ^= (x >> (8 * b)) & 0xFF;
            h *= 0x100000001b3ull;
        }
    }
    return h;
}
