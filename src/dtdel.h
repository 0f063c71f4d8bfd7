/*
 * dtdel.h -- the one public header of libdtdel.
 *
 * libdtdel builds the 3D Delaunay triangulation DT(S) of a point set and
 * deletes vertices from it with the algorithms of Buchin, Devillers, Mulzer,
 * Schrijvers and Shewchuk, "Vertex Deletion for 3D Delaunay Triangulations"
 * (ESA 2013).  Predicates are exact and symbolically perturbed exactly as
 * CGAL's Delaunay_triangulation_3 perturbs them, so the triangulation is
 * unique for every point set that is not all coplanar and equals CGAL's
 * simplex for simplex.
 *
 * Threads.  The calls that take a `const dd_tri *` only read it: dd_point,
 * dd_cells, dd_incident_cells, dd_neighbors, dd_degree, dd_on_hull,
 * dd_locate, dd_nearest_vertex, dd_canonical, dd_local_canonical,
 * dd_check, dd_check_msg, the cell handles' calls (dd_cell_end,
 * dd_cell_alive, dd_cell, dd_locate_from, dd_created_cells), dd_write,
 * dd_write_ex, dd_version, the weighted reads (dd_is_weighted, dd_weight,
 * dd_is_hidden, dd_hidden) and every counter or getter (dd_num_*, dd_alias,
 * dd_is_vertex, dd_memory_bytes, dd_errmsg, and dtdel_stats.h's
 * dd_last_delete_stats and dd_get_counters).  Their scratch belongs to the
 * call, not to the triangulation, so any number of threads may call them
 * at once on one triangulation while none edits it.  The edits, the calls
 * that take a `dd_tri *` (dd_free, dd_delete, dd_delete_with,
 * dd_delete_set, dd_delete_set_with, dd_insert, dd_reinsert, dd_move, and
 * dtdel_stats.h's dd_reset_counters and dd_test_control), need exclusive
 * access: no other call on the same triangulation while one runs (a
 * reader-writer lock of the caller's: reads shared, edits exclusive).
 * Distinct triangulations share nothing, and the calls on no
 * triangulation (dd_create, dd_create_ex, dd_status_name, dd_variant_*,
 * dd_canonical_hash) are safe in any thread.  A read-only call that fails
 * says so by its status alone and leaves dd_errmsg as it was;
 * dd_check_msg writes the validator's message to a buffer of the
 * caller's.
 *
 * Conventions:
 *  - Vertices are named by their input index: the 0-based position of the
 *    point in the array given to dd_create (or the index returned by
 *    dd_insert).  A duplicate input point is not a vertex; dd_alias maps it
 *    to the first occurrence, which is.
 *  - Return values, one rule per kind:
 *      a call that can fail returns a dd_status: DD_OK, or the reason; on
 *        failure the triangulation is left exactly as it was, and out-
 *        parameters are unspecified unless the call says otherwise;
 *      a count (dd_num_*, dd_degree, dd_neighbors, dd_incident_cells)
 *        has no status: 0 for an index that names no vertex, and 0
 *        too when one that allocates runs out of memory (see Memory);
 *      a yes/no (dd_is_vertex, dd_on_hull, dd_is_hidden) is 1 or 0, 0 for
 *        a bad index (dd_on_hull: and on running out of memory);
 *      a name (dd_status_name, dd_variant_name, dd_version, dd_errmsg) is
 *        a string the library owns; dd_variant_name is NULL past the end;
 *      dd_alias answers UINT32_MAX for an index out of range.
 *  - A list written into a caller's array of `max` entries (dd_neighbors,
 *    dd_incident_cells) is truncated as snprintf truncates: at most max
 *    entries are written, and the return value is the full count, so a
 *    return value above max says the array was too short (with max 0 the
 *    array may be NULL: a call that only counts).
 *  - dd_errmsg(t) is the message of the last call on t that failed; a
 *    later success leaves it.  Only calls taking a non-const dd_tri *
 *    write it; read-only calls (const dd_tri *) report by status alone.
 *  - Memory: a call that allocates may fail with DD_ERR_NOMEM, and then
 *    leaves the triangulation as it was (dd_create, dd_create_ex: *out
 *    NULL, nothing held).  The exact predicates allocate nothing during
 *    an operation: their GMP numbers are sized when the triangulation is
 *    made (dd_create can fail with DD_ERR_NOMEM for them) for the
 *    largest any finite doubles need, and a read-only call's sit on its
 *    stack (about 100 KB, only while such a test runs); so running out
 *    of memory is reported, never an abort in GMP.  What remains: an
 *    edit that succeeded may have lost dd_created_cells' list (that call
 *    then answers DD_ERR_NOMEM) or not remade its location grid
 *    (queries walk longer); the counts and yes/no answers that allocate
 *    (dd_degree, dd_neighbors, dd_incident_cells, dd_on_hull: the star
 *    of the vertex, on the heap) cannot report it and answer 0, the
 *    answer for no vertex (a caller that must tell the two apart asks
 *    dd_is_vertex, which allocates nothing; a vertex has degree >= 4 and
 *    at least 4 incident cells);
 *    and an edit undone by a compensating edit (dd_delete_set failing in
 *    its one-at-a-time course, dd_move's temporary insertion) needs
 *    memory for the undo: if that fails too (memory still short), the
 *    call answers DD_ERR_INTERNAL and the triangulation is not as it
 *    was.  tests/test_fault.c fails every allocation of every call in
 *    turn.
 *  - Exported names start with dd_; nothing here keeps global state.
 *  - Diagnostics for benchmarks and tests (what a deletion did, predicate
 *    counters, test-build controls) are in dtdel_stats.h, not here.
 */
#ifndef DTDEL_H
#define DTDEL_H

#include <stddef.h>
#include <stdint.h>
#include "dtdel/types.h"      /* dd_status, dd_tri: installed beside this */

/* ---- version and exports ------------------------------------------------ */

/* The version: the one source of truth, which the Makefile reads for the
 * shared library's soname (libdtdel.so.MAJOR) and for dtdel.pc.  MAJOR
 * changes when the ABI breaks.                                           */
#define DD_VERSION_MAJOR 0
#define DD_VERSION_MINOR 1
#define DD_VERSION_PATCH 0
#define DD_STRINGIFY_(x) #x
#define DD_STRINGIFY(x) DD_STRINGIFY_(x)
#define DD_VERSION \
    DD_STRINGIFY(DD_VERSION_MAJOR) "." DD_STRINGIFY(DD_VERSION_MINOR) "." DD_STRINGIFY(DD_VERSION_PATCH)

/* What the library exports.  It is built with -fvisibility=hidden; the
 * declarations between DD_API_BEGIN and DD_API_END (all of this header's
 * and dtdel_stats.h's) are exported, DD_API marks a single one.  Nothing
 * else is: internal names cannot clash with a user's.                    */
#if defined(__GNUC__) || defined(__clang__)
#define DD_API __attribute__((visibility("default")))
#define DD_API_BEGIN _Pragma("GCC visibility push(default)")
#define DD_API_END _Pragma("GCC visibility pop")
#else
#define DD_API
#define DD_API_BEGIN
#define DD_API_END
#endif

#ifdef __cplusplus
extern "C" {
#endif
DD_API_BEGIN

/* The library's version, DD_VERSION of the build ("0.1.0"): the header a
 * program was compiled with may be older than the library it runs with. */
const char *dd_version(void);

/* A short fixed name for a status ("ok", "out of memory", "coplanar
 * points", ...).                                                        */
const char *dd_status_name(dd_status s);

/* ---- creation ------------------------------------------------------------ */

/* Builds DT of the n points xyz[3i..3i+2].  On success *out owns a copy of
 * the points.  On failure *out is NULL, and if msg is not NULL a message
 * naming the problem (and the offending index) is written to msg (at most
 * msglen bytes, terminated).  dd_create is dd_create_ex(out, xyz, NULL,
 * n, 0, msg, msglen).                                                    */
dd_status dd_create(dd_tri **out, const double *xyz, uint32_t n,
                    char *msg, size_t msglen);

/* Flags of dd_create_ex. */
enum {
    /* dd_insert never reuses an index: each new point gets the index
     * dd_num_input() had before the call, a deleted index stays deleted
     * (dd_reinsert still puts it back), and a user's per-index arrays
     * stay true.  Memory then grows with the insertions, not with the
     * live size.  Without it, dd_insert reuses a deleted vertex's index
     * (see dd_insert).                                                   */
    DD_STABLE_INDICES = 1u << 0,
    /* Weighted only: a point that becomes hidden is forgotten, as CGAL's
     * Discard_hidden_points (Mesh_3's compact cell base); by default
     * hidden points are kept, as in CGAL's default cell base.          */
    DD_DISCARD_HIDDEN = 1u << 1,
    /* Every core (the cores online): see DD_THREADS below.              */
    DD_THREADS_ALL = 1u << 19
};
/* Threads: dd_create_ex(..., flags | DD_THREADS(n), ...) builds on n
 * threads (1 <= n <= 2047; more than 1024 use 1024), and the calls on the
 * triangulation afterwards use n too (dd_set_threads changes it).
 * Without DD_THREADS or DD_THREADS_ALL the count is 1, or the value of
 * the environment variable DTDEL_THREADS when it is set (a count; 0 or
 * "all": every core), read when the triangulation is made.  The result
 * never depends on the count: the same triangulation, simplex for
 * simplex, the same canonical form; only the numbering of the cells
 * (dd_cells' order, cell handles) may differ from one build to another
 * on more than one thread.                                              */
#define DD_THREADS(n) (((unsigned)(n) & 0x7FFu) << 8)

/* dd_create with options.  weights NULL: the Delaunay triangulation, as
 * dd_create.  Otherwise weights[i] is the weight of point i, and the result
 * is the regular triangulation, identical simplex for simplex to CGAL's
 * Regular_triangulation_3 (Epick), with the same hidden points.  flags is 0
 * or an OR of the DD_* flags above (any other bit: DD_ERR_ARG).          */
dd_status dd_create_ex(dd_tri **out, const double *xyz, const double *weights, uint32_t n,
                       unsigned flags, char *msg, size_t msglen);

void dd_free(dd_tri *t);

/* The threads the calls on t use from now on (see DD_THREADS): n, at
 * most 1024; 0: every core.  Which calls use them: dtdel.h names them
 * ("threads: ...").  O(1).                                             */
void dd_set_threads(dd_tri *t, unsigned n);
/* The threads the calls on t use (>= 1).  O(1).                         */
unsigned dd_threads(const dd_tri *t);

/* ---- weighted points (regular triangulations, DESIGN 12) ----------------- */

/* 1 if t was made with weights (dd_create_ex), else 0.  O(1). */
int dd_is_weighted(const dd_tri *t);
/* The weight of input point i (0 on an unweighted t).  O(1).
 * DD_ERR_ARG: i is not an input index.                                  */
dd_status dd_weight(const dd_tri *t, uint32_t i, double *w);
/* 1: input point i is kept but hidden (its lifted point lies above the
 * lower hull); 0 otherwise (a vertex, deleted, forgotten, out of range). O(1). */
int dd_is_hidden(const dd_tri *t, uint32_t i);
/* The input indices of the kept hidden points, sorted ascending, in *idx
 * (malloc'd, the caller frees; NULL when *n is 0).  O(h log h) for h
 * hidden points.  DD_ERR_NOMEM.                                           */
dd_status dd_hidden(const dd_tri *t, uint32_t **idx, size_t *n);
/* Inserts the weighted point (p, w) and returns its input index (numbered
 * as dd_insert numbers).  It may end hidden (still DD_OK, and *index
 * names it), and it may hide vertices, which become hidden points (or are
 * forgotten under DD_DISCARD_HIDDEN).  A point at a vertex's position
 * follows CGAL's rule.  O(log n) expected plus the conflict region.
 * DD_ERR_UNSUPPORTED on an unweighted t; DD_ERR_NAN / DD_ERR_INFINITE for a bad
 * coordinate or weight; DD_ERR_NOMEM.  A failure changes nothing.        */
dd_status dd_insert_weighted(dd_tri *t, const double p[3], double w, uint32_t *index);

/* The message of the last failed edit on t: "" if none has failed; a
 * later success does not clear it; read-only calls write none (see
 * Conventions and Threads above).                                        */
const char *dd_errmsg(const dd_tri *t);

/* The end of the index range: every input index lies in [0, dd_num_input),
 * deleted ones and duplicates included (dd_insert may reuse a deleted
 * index: then the range does not grow).                                  */
uint32_t dd_num_input(const dd_tri *t);
uint32_t dd_num_vertices(const dd_tri *t);   /* finite vertices now in DT   */
uint32_t dd_num_duplicates(const dd_tri *t); /* input points merged away    */
size_t dd_num_tets(const dd_tri *t);         /* finite + infinite cells     */
size_t dd_num_finite_tets(const dd_tri *t);
/* Index of the vertex that input point i became (i itself unless i was a
 * duplicate); UINT32_MAX if i is out of range.                           */
uint32_t dd_alias(const dd_tri *t, uint32_t i);
/* 1 if input index i is a vertex of the triangulation now.               */
int dd_is_vertex(const dd_tri *t, uint32_t i);
/* Number of vertices adjacent to v (the infinite vertex counts as one);
 * 0 if v is not a vertex.  O(cells of v's star), which it collects in
 * memory of its own: out of memory it answers 0 (no status to say so).  */
uint32_t dd_degree(const dd_tri *t, uint32_t v);
/* 1 if vertex v is on the convex hull (adjacent to the infinite vertex);
 * 0 if not, or v is not a vertex.  O(cells of v's star), collected in
 * memory of its own: out of memory it answers 0 (no status to say so).  */
int dd_on_hull(const dd_tri *t, uint32_t v);

/* Canonical form: each cell as its four vertex indices sorted ascending,
 * -1 for the infinite vertex; the cells sorted lexicographically.  *tets
 * is malloc'd (4 * *ntets ints); the caller frees it.                    */
dd_status dd_canonical(const dd_tri *t, int32_t **tets, size_t *ntets);
/* The input indices of v's finite neighbours: at most max written to
 * out; returns their full number (more than max: out was too short), 0
 * if v is not a vertex.  O(cells of v's star), collected in memory of
 * its own: out of memory it answers 0 (no status to say so).            */
uint32_t dd_neighbors(const dd_tri *t, uint32_t v, uint32_t *out, uint32_t max);
/* Canonical form (as dd_canonical) of the cells incident to any of the
 * input vertices vs[0..n): what deleting their common neighbour changes. */
dd_status dd_local_canonical(const dd_tri *t, const uint32_t *vs, size_t n, int32_t **tets, size_t *ntets);

/* 64-bit hash of a canonical list (FNV-1a over the ints). */
uint64_t dd_canonical_hash(const int32_t *tets, size_t ntets);

/* Full self-check: neighbour symmetry, shared facets, positive orientation
 * of finite cells, and the perturbed empty-sphere test on every facet:
 * DD_OK, or DD_ERR_INTERNAL for a broken triangulation.  dd_check_msg
 * also writes what is broken to msg (msglen bytes; "" when valid; msg
 * may be NULL).                                                        */
dd_status dd_check(const dd_tri *t);
dd_status dd_check_msg(const dd_tri *t, char *msg, size_t msglen);

/* ---- reading the mesh and locating points ------------------------------ */

/* Coordinates of input vertex v.  DD_ERR_UNKNOWN_VERTEX if v is not a
 * vertex now.  O(1).                                                     */
dd_status dd_point(const dd_tri *t, uint32_t v, double p[3]);
/* Snapshot of all cells, finite and infinite, in two malloc'd arrays of
 * 4 * *ncells ints (the caller frees both):
 *   verts[4c+i] = input index of vertex i of cell c (-1 = infinite);
 *   nbrs[4c+i]  = the cell across the facet opposite verts[4c+i].
 * Finite cells are positively oriented (CGAL's orientation sign); an
 * infinite cell is oriented as if -1 were a point beyond its hull facet.
 * O(cells).                                                              */
dd_status dd_cells(const dd_tri *t, int32_t **verts, int32_t **nbrs, size_t *ncells);
/* The cells incident to input vertex v, as their four vertices (input
 * indices, -1 = infinite): at most max written to out; returns their full
 * number (more than max: out was too short), 0 if v is not a vertex.
 * O(number of those cells), collected in memory of its own: out of
 * memory it answers 0 (no status to say so).                             */
uint32_t dd_incident_cells(const dd_tri *t, uint32_t v, int32_t (*out)[4], uint32_t max);
/* The four vertices (input indices, -1 = infinite) of a cell whose
 * closure holds p, or, when p is outside the convex hull, of an infinite
 * cell whose hull facet p sees (p on its outer side or in its plane).
 * Exact, degenerate positions included; the same p gets the same cell
 * until the next edit.  DD_ERR_NAN / DD_ERR_INFINITE for a bad p.
 * Expected O(1) cells walked on evenly spread points: the walk starts at
 * a vertex near p (a grid over the vertices, made by dd_create in O(n)
 * and remade by the edits as the size doubles or halves).               */
dd_status dd_locate(const dd_tri *t, const double p[3], int32_t cell[4]);
/* In *v, the input index of a vertex nearest to p in Euclidean distance
 * (any one of ties), exact; on a weighted t, of least power distance
 * |p - x|^2 - w(x) (hidden points are no vertices, so never answered).
 * DD_ERR_NAN / DD_ERR_INFINITE for a bad p, DD_ERR_NOMEM.  dd_locate's
 * cost, then a greedy descent over the edges: O(degree) a step, a few
 * steps.                                                                 */
dd_status dd_nearest_vertex(const dd_tri *t, const double p[3], uint32_t *v);
/* 1 if the vertex index v is the infinite vertex (-1 in the arrays). */
static inline int dd_is_infinite(int32_t v) { return v < 0; }

/* ---- deletion (paper: DELETEVERTEX) ------------------------------------ */

/* Deletes input vertex v with the default strategy, the fastest correct
 * one (dd_delete_with names another: research and benchmarks; NULL there
 * is the default too; dd_variant_name lists them).  The result is DT(S minus v), identical to CGAL's.
 * Refused with DD_ERR_DIMENSION when fewer than 4 or only coplanar points
 * would remain; DD_ERR_UNKNOWN_VERTEX / DD_ERR_UNKNOWN_VARIANT for bad
 * names.  On any failure the triangulation is unchanged.
 * Weighted t: the result is CGAL's Regular_triangulation_3 after
 * remove(), cells and hidden set: kept hidden points of v's star that are
 * no longer hidden become vertices again (under DD_DISCARD_HIDDEN, the
 * regular triangulation of the vertices left).  A kept hidden point v
 * may be deleted too: it is forgotten, O(1) and no cell changes (CGAL
 * has no call for it; the result is the regular triangulation of the
 * points left, which it does not change).  Exact copies (one weighted
 * point under several indices): a copy that comes back as a vertex
 * takes the lowest index and the others are forgotten, as CGAL does;
 * copies that stay hidden all stay hidden, where CGAL's remove(), which
 * re-inserts the star's hidden points one at a time in its own order,
 * may drop some of them (one that is a vertex for a while makes it drop
 * its twins).  The hidden weighted points are CGAL's all the same.     */
dd_status dd_delete(dd_tri *t, uint32_t v);
dd_status dd_delete_with(dd_tri *t, uint32_t v, const char *variant);

/* Deletes the input vertices vs[0..n), a set: the result is DT of the
 * points left whatever the order, and the order taken is the engine's
 * own (along its insertion order, so that consecutive deletions touch
 * nearby memory: faster than deleting the set one dd_delete at a time in
 * a random order).  All or nothing: DD_ERR_UNKNOWN_VERTEX for an index
 * that is no vertex, DD_ERR_ARG for one listed twice, DD_ERR_DIMENSION
 * when fewer than 4 or only coplanar points would be left, checked before
 * any deletion; on any failure the triangulation is unchanged.
 * Weighted t: as n dd_delete calls (kept hidden points may be listed and
 * count among the points left), the regular triangulation of the points
 * left, every hidden point kept either a vertex or hidden, once; under
 * DD_DISCARD_HIDDEN, of the vertices left.  Cost: the cheaper of the
 * deletions one at a time and a rebuild of the points left.             */
dd_status dd_delete_set(dd_tri *t, const uint32_t *vs, size_t n);
dd_status dd_delete_set_with(dd_tri *t, const uint32_t *vs, size_t n, const char *variant);

/* Moves input vertex v to p; v keeps its index.  The result is DT of the
 * moved point set, identical to CGAL's.  DD_ERR_DUPLICATE if p is the
 * point of another vertex, DD_ERR_NAN / DD_ERR_INFINITE for a bad p,
 * DD_ERR_DIMENSION if only coplanar points would remain; on any failure
 * nothing changes.  Moving v onto its own point changes nothing.
 * Cost: O(degree) when no cell changes (an exact relocation filter: the
 * star's cells stay positive and its facets locally Delaunay); else an
 * insertion walked from v's old star plus a deletion.
 * Weighted t: dd_move_weighted with v's own weight.                     */
dd_status dd_move(dd_tri *t, uint32_t v, const double p[3]);
/* Moves input point v of a weighted t to p with weight w (p may be v's
 * own point: a re-weighting); v keeps its index.  The result is CGAL's
 * Regular_triangulation_3 after removing v and inserting (p, w) (DESIGN
 * 12: CGAL's move() refuses a point that ends hidden), cells and hidden
 * set: v may end hidden (still DD_OK; under DD_DISCARD_HIDDEN it is then
 * forgotten, neither vertex nor hidden), and it may hide others.  A kept
 * hidden point v moves too (taken out, then (p, w) inserted).  (p, w)
 * equal to v's changes nothing.  Failures, each changing nothing:
 * DD_ERR_UNSUPPORTED on an unweighted t; DD_ERR_NAN / DD_ERR_INFINITE
 * for a bad coordinate or weight; DD_ERR_UNKNOWN_VERTEX when v is
 * neither a vertex nor a kept hidden point; DD_ERR_DUPLICATE when (p, w)
 * is exactly another point's weighted point that is (or, v removed,
 * becomes) a vertex; DD_ERR_DIMENSION when the moved point set (with
 * the kept hidden points) would be fewer than 4 or coplanar; DD_ERR_NOMEM.
 * Cost: O(degree) power tests when v's star stays regular or a few 2-3
 * and 3-2 flips repair it, its hidden points staying hidden; else a
 * deletion of v plus an insertion walked from its old star; where the
 * points left without v would be fewer than 4 or coplanar (every
 * finite cell holds v), a rebuild of the moved set, O(n log n).         */
dd_status dd_move_weighted(dd_tri *t, uint32_t v, const double p[3], double w);

/* Inserts a new point; *index receives its input index.  As CGAL reuses
 * a removed vertex's storage, the index (and storage) of a deleted vertex
 * is reused when there is one, else the index is dd_num_input() before
 * the call; so memory stays bounded by the live size under churn, and an
 * index deleted before a dd_insert may name the new point after it
 * (dd_reinsert of it then fails).  With DD_STABLE_INDICES (dd_create_ex)
 * the index is always dd_num_input() before the call.  DD_ERR_DUPLICATE
 * if p equals a vertex, DD_ERR_NAN / DD_ERR_INFINITE for a bad p; on
 * failure nothing changes.  The walk starts near p (as dd_locate):
 * expected O(1) cells on evenly spread points, plus the O(degree) update. */
dd_status dd_insert(dd_tri *t, const double p[3], uint32_t *index);
/* Puts back input vertex v after dd_delete (same index, same point).
 * Weighted t: with its weight, by CGAL's insertion rule: it may end
 * hidden (or, under DD_DISCARD_HIDDEN, forgotten; a point forgotten may
 * be put back so too), and may hide others.  DD_ERR_DUPLICATE when v is
 * a vertex or a kept hidden point already, or its weighted point is
 * exactly a vertex's; DD_ERR_UNKNOWN_VERTEX for no input index.        */
dd_status dd_reinsert(dd_tri *t, uint32_t v);

/* ---- cell handles -------------------------------------------------------- */

/* A cell id: the cell's slot in the mesh's own storage, so every call
 * below is O(1) but the walk.  -1: none.  An edit (dd_insert,
 * dd_reinsert, dd_delete(_with), dd_delete_set(_with), dd_move) kills
 * some cells and makes others: a live cell it does not touch keeps its
 * id, its vertices and its neighbours' ids across the facets it did not
 * touch; a killed cell's id may name a cell the edit made (check
 * dd_cell_alive and the vertices, or keep a stamp per id, refreshed from
 * dd_created_cells).  Read-only calls never change an id.             */
typedef int64_t dd_cell_id;

/* Live ids lie in [0, dd_cell_end(t)); dead ones are interspersed.    */
dd_cell_id dd_cell_end(const dd_tri *t);
/* 1 if c is the id of a live cell, 0 otherwise (any c, -1 included).  */
int dd_cell_alive(const dd_tri *t, dd_cell_id c);
/* Cell c's vertices and neighbours, as dd_cells writes them: v[i] the
 * input index of vertex i (-1: the infinite vertex; a finite cell is
 * positively oriented, an infinite one as if -1 were a point beyond its
 * hull facet), nbr[i] the id of the cell across the facet opposite
 * v[i].  Either array may be NULL.  DD_ERR_UNKNOWN_CELL if c is not
 * alive.  O(1).                                                       */
dd_status dd_cell(const dd_tri *t, dd_cell_id c, int32_t v[4], dd_cell_id nbr[4]);
/* A cell whose closure holds p, found by an exact visibility walk from
 * cell `hint`; when p is outside the convex hull, an infinite cell whose
 * hull facet p sees (p on its outer side).  The same answer class as
 * dd_locate.  Cost: the cells crossed from the hint to p, so a hint near
 * p (a cell of the last edit, a neighbour's cell) makes it a short walk.
 * hint -1: the library's choice, a cell of a vertex near p when the
 * location grid exists (dd_locate, dd_insert make it), else the last
 * edit's last cell.
 * DD_ERR_UNKNOWN_CELL if hint is neither -1 nor alive, DD_ERR_NAN /
 * DD_ERR_INFINITE for a bad p.  Writes nothing to t.                  */
dd_status dd_locate_from(const dd_tri *t, const double p[3], dd_cell_id hint, dd_cell_id *cell);
/* The live cells made by the last edit, each once, in *cells[0..*n):
 * after dd_create every cell; after dd_insert / dd_reinsert the new
 * vertex's star; after a deletion the cells that fill the cavities;
 * after dd_move the cells its flips, or its re-insertion, made (a move
 * that keeps every cell, the relocation filter, makes none, though the
 * cells around the vertex change shape under their ids).  With the
 * rule above, a queue of cells kept from this list alone stays exact:
 * every live cell not listed existed before the edit, unchanged.  A
 * set deletion that rebuilds lists every cell.  An edit that fails
 * before changing anything (every refusal: bad index, duplicate,
 * dimension, most out-of-memory cases) leaves the list as it was; a
 * failure undone by a compensating edit (dd_move refused with
 * DD_ERR_DIMENSION after its temporary insertion, an out-of-memory
 * in the middle of a set deletion) leaves the triangulation as it was
 * but lists the cells it re-made, whose ids are new.  The array
 * belongs to t, valid until the next edit or dd_free.  DD_ERR_NOMEM
 * (and an empty list) if the list could not be kept: the edit itself
 * succeeded.  O(1).                                                   */
dd_status dd_created_cells(const dd_tri *t, const dd_cell_id **cells, size_t *n);

/* ---- hinted and whole-array calls ---------------------------------------- */

/* dd_insert / dd_insert_weighted with the walk starting at cell `hint`
 * (a live id, or -1: the library's choice, as dd_insert).  Same result,
 * index and statuses as those, plus DD_ERR_UNKNOWN_CELL if hint is
 * neither -1 nor alive (checked after p, before any change).  Cost: the
 * cells crossed from hint to p plus the update, so O(1) beyond the update
 * when p is in conflict with hint (a refinement loop inserting the
 * circumcentre of the cell it holds).                                  */
dd_status dd_insert_from(dd_tri *t, const double p[3], dd_cell_id hint, uint32_t *index);
dd_status dd_insert_weighted_from(dd_tri *t, const double p[3], double w, dd_cell_id hint, uint32_t *index);

/* Inserts the m points xyz[3i..3i+3) (weights w[i]; w NULL: weight 0 on
 * a weighted t; w non-NULL on an unweighted t: DD_ERR_UNSUPPORTED).
 * The triangulation, and indices[i], the input index of point i, are
 * those of inserting the points one at a time in the given order with
 * dd_insert / dd_insert_weighted, except that a point equal to a vertex
 * (its weighted point, on a weighted t) or to an earlier point of the
 * batch is no error: it gets that vertex's or point's index and is
 * counted in *merged (NULL allowed), as dd_create merges duplicates.
 * The work is done in an order of the call's own (along a Hilbert curve,
 * in BRIO rounds when m is large against the vertices there are),
 * except under DD_DISCARD_HIDDEN, where the given order is the one
 * honoured (what is forgotten depends on it).  All or nothing: a NaN or
 * infinite coordinate or weight anywhere refuses the whole batch
 * (DD_ERR_NAN / DD_ERR_INFINITE, the message naming its position),
 * checked before any change; DD_ERR_NOMEM leaves t as it was (see
 * DD_ERR_INTERNAL above).  m = 0 succeeds and changes nothing.
 * dd_created_cells lists the live cells the batch made.  Cost: that of
 * the m insertions, each walking from the last one's cells, so O(1)
 * cells a walk on spread points, plus O(m) for the order.             */
dd_status dd_insert_many(dd_tri *t, const double *xyz, const double *w, size_t m, uint32_t *indices,
                         size_t *merged);

/* Moves input vertex vs[i] to xyz[3i..3i+3) (with weight w[i] on a
 * weighted t; w NULL keeps each weight; w non-NULL on an unweighted t:
 * DD_ERR_UNSUPPORTED), each keeping its index.  The result is the
 * triangulation of the moved point set (the regular triangulation and
 * hidden set of the moved weighted points), CGAL's, whatever the order;
 * the call chooses its own (along a Hilbert curve of the targets), but
 * under DD_DISCARD_HIDDEN the given order is honoured, as m dd_move_weighted
 * calls would.  A vertex may move onto the old point of another one of
 * the batch.  Refused before any change: DD_ERR_NAN / DD_ERR_INFINITE
 * (naming the position), DD_ERR_UNKNOWN_VERTEX (vs[i] neither a vertex
 * nor a kept hidden point), DD_ERR_ARG (a vertex listed twice, naming
 * both positions), DD_ERR_DUPLICATE (two final positions equal, naming
 * the pair).  DD_ERR_DUPLICATE also when a final position is a vertex's
 * that does not move (found on the way: the moves made are undone), and
 * DD_ERR_DIMENSION as dd_move; DD_ERR_NOMEM.  All or nothing.  m = 0
 * succeeds.  Cost: that of the m moves, O(degree) each for a small move,
 * plus O(m log m) for the checks and the order.                       */
dd_status dd_move_many(dd_tri *t, const uint32_t *vs, const double *xyz, const double *w, size_t m);

/* Read-only, const and thread-safe like every read.  cells[i] receives a
 * cell whose closure holds point xyz[3i..3i+3) (dd_locate_from's answer
 * class, -1 where the point is NaN or infinite), nearest[i] a vertex
 * nearest to it (least power distance on a weighted t, as
 * dd_nearest_vertex; UINT32_MAX where the point is bad).  The queries
 * are answered along a Hilbert curve, in chunks of 4096, each walk
 * starting from the last answer of its chunk.  Threads: the chunks go
 * to dd_threads(t) threads; the answers do not depend on how many.
 * DD_ERR_NAN / DD_ERR_INFINITE if some point was bad (the others
 * answered), DD_ERR_NOMEM (nothing answered; the outputs partly
 * written).  Cost: O(m) for the order plus the walks, O(1) cells each
 * for queries spread like the points, divided among the threads; O(m)
 * scratch.                                                           */
dd_status dd_locate_many(const dd_tri *t, const double *xyz, size_t m, dd_cell_id *cells);
dd_status dd_nearest_many(const dd_tri *t, const double *xyz, size_t m, uint32_t *nearest);

/* Every input point's coordinates: xyz[3i..3i+3) for i < dd_num_input(t)
 * (a duplicate's are its vertex's), NaN for an index that names no point
 * now (a deleted vertex, a forgotten hidden point), and on a weighted t
 * the weights into w (NULL allowed; 0 on an unweighted t, NaN where xyz
 * is).  Read-only.  O(n).                                              */
dd_status dd_points(const dd_tri *t, double *xyz, double *w);

/* The vertices of cells ids[0..n), as dd_cell gives them, into
 * verts[4k..4k+4): with dd_created_cells, the new cells of an edit in one
 * call.  DD_ERR_UNKNOWN_CELL (naming nothing: verts of the cells before
 * it written) at the first id not alive.  Read-only.  O(n).            */
dd_status dd_cells_vertices(const dd_tri *t, const dd_cell_id *ids, size_t n, int32_t *verts);

/* ---- mesh files ------------------------------------------------------------ */

/* Writes the finite cells and the vertices to path, the format chosen by
 * the extension: ".vtu", VTK's XML UnstructuredGrid (VTK_TETRA cells;
 * point data "input_index", the input index of each point), for ParaView,
 * VTK and meshio; ".mesh", Medit's (MeshVersionFormatted 2, Dimension 3,
 * Vertices with reference 0, Tetrahedra 1-based with reference 0), for
 * Gmsh, Medit and meshio.  A .vtu is binary: appended raw data
 * (header_type UInt64, the machine's byte order), points Float64, the
 * integers Int32 (Int64 when a value passes 2^31 - 1); a name ending in
 * ".ascii.vtu" writes ASCII data arrays instead (integers Int32 and
 * Int64, coordinates printed %.17g), as dd_write_ex's DD_WRITE_ASCII
 * does.  Points are the live vertices, in input index order, coordinates
 * exact in both.  Each tetrahedron (a, b, c, d) has
 * (b - a) x (c - a) . (d - a) > 0, the positive volume both formats
 * expect.  DD_ERR_UNKNOWN_FORMAT for another extension, DD_ERR_IO if the
 * file cannot be written (a partial file may be left), DD_ERR_NOMEM (no
 * file written).  O(cells).                                            */
dd_status dd_write(const dd_tri *t, const char *path);

/* Flags of dd_write_ex. */
enum {
    /* A .vtu with ASCII data arrays, whatever its name (no effect on a
     * .mesh, which is text).                                           */
    DD_WRITE_ASCII = 1u << 0
};

/* dd_write with options: flags is 0 or DD_WRITE_ASCII (any other bit:
 * DD_ERR_ARG).  dd_write is dd_write_ex(t, path, 0).                   */
dd_status dd_write_ex(const dd_tri *t, const char *path, unsigned flags);

/* The strategies, in registry order (i = 0, 1, ... until NULL). */
const char *dd_variant_name(size_t i);
const char *dd_variant_description(size_t i);

/* Bytes held by the triangulation's arrays (capacity, not just use). */
size_t dd_memory_bytes(const dd_tri *t);

DD_API_END
#ifdef __cplusplus
}
#endif
#endif
