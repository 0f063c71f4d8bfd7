# cython: language_level=3, boundscheck=False, wraparound=False, initializedcheck=False
"""
_core -- the compiled binding of libdtdel (src/dtdel.h): the Triangulation
class, one C call a method, the array calls on numpy arrays with the GIL
released, and the scipy-shaped arrays' single pass over the cells.

Owns: converting and checking arguments (shapes, dtypes, index ranges),
the per-object read/write lock, and turning a failed dd_status into
DtdelError.  No geometry is computed here.

Threads: every call takes the object's lock, shared by the reads (the
calls dtdel.h marks read-only may run in any number of threads at once)
and held alone by an edit; the lock is taken and held without the GIL
and nothing holding it asks for the GIL, so it cannot deadlock with it.
"""
cimport numpy as cnp
import numpy as np
from libc.stdint cimport int32_t, int64_t, uint32_t, uint64_t
from libc.stdlib cimport free
from libc.string cimport memcpy, strncpy

cnp.import_array()

cdef extern from "<pthread.h>" nogil:
    ctypedef struct pthread_rwlock_t:
        pass
    int pthread_rwlock_init(pthread_rwlock_t *, void *)
    int pthread_rwlock_destroy(pthread_rwlock_t *)
    int pthread_rwlock_rdlock(pthread_rwlock_t *)
    int pthread_rwlock_wrlock(pthread_rwlock_t *)
    int pthread_rwlock_unlock(pthread_rwlock_t *)

cdef extern from "<time.h>" nogil:
    ctypedef long time_t
    cdef struct timespec:
        time_t tv_sec
        long tv_nsec
    int clock_gettime(int, timespec *)
    int CLOCK_MONOTONIC

cdef extern from "dtdel.h" nogil:
    ctypedef struct dd_tri:
        pass
    ctypedef int dd_status
    ctypedef int64_t dd_cell_id
    int DD_STABLE_INDICES, DD_DISCARD_HIDDEN, DD_WRITE_ASCII, DD_THREADS_ALL
    unsigned DD_THREADS(unsigned n)
    const char *dd_version()
    const char *dd_status_name(dd_status s)
    dd_status dd_create(dd_tri **out, const double *xyz, uint32_t n, char *msg, size_t msglen)
    dd_status dd_create_ex(dd_tri **out, const double *xyz, const double *weights, uint32_t n,
                           unsigned flags, char *msg, size_t msglen)
    void dd_free(dd_tri *t)
    void dd_set_threads(dd_tri *t, unsigned n)
    unsigned dd_threads(const dd_tri *t)
    int dd_is_weighted(const dd_tri *t)
    dd_status dd_weight(const dd_tri *t, uint32_t i, double *w)
    int dd_is_hidden(const dd_tri *t, uint32_t i)
    dd_status dd_hidden(const dd_tri *t, uint32_t **idx, size_t *n)
    dd_status dd_insert_weighted(dd_tri *t, const double *p, double w, uint32_t *index)
    const char *dd_errmsg(const dd_tri *t)
    uint32_t dd_num_input(const dd_tri *t)
    uint32_t dd_num_vertices(const dd_tri *t)
    uint32_t dd_num_duplicates(const dd_tri *t)
    size_t dd_num_tets(const dd_tri *t)
    size_t dd_num_finite_tets(const dd_tri *t)
    uint32_t dd_alias(const dd_tri *t, uint32_t i)
    int dd_is_vertex(const dd_tri *t, uint32_t i)
    uint32_t dd_degree(const dd_tri *t, uint32_t v)
    int dd_on_hull(const dd_tri *t, uint32_t v)
    dd_status dd_canonical(const dd_tri *t, int32_t **tets, size_t *ntets)
    uint32_t dd_neighbors(const dd_tri *t, uint32_t v, uint32_t *out, uint32_t max)
    dd_status dd_local_canonical(const dd_tri *t, const uint32_t *vs, size_t n, int32_t **tets, size_t *ntets)
    uint64_t dd_canonical_hash(const int32_t *tets, size_t ntets)
    dd_status dd_check(const dd_tri *t)
    dd_status dd_check_msg(const dd_tri *t, char *msg, size_t msglen)
    dd_status dd_point(const dd_tri *t, uint32_t v, double *p)
    dd_status dd_cells(const dd_tri *t, int32_t **verts, int32_t **nbrs, size_t *ncells)
    uint32_t dd_incident_cells(const dd_tri *t, uint32_t v, int32_t (*out)[4], uint32_t max)
    dd_status dd_locate(const dd_tri *t, const double *p, int32_t *cell)
    dd_status dd_nearest_vertex(const dd_tri *t, const double *p, uint32_t *v)
    dd_status dd_delete(dd_tri *t, uint32_t v)
    dd_status dd_delete_with(dd_tri *t, uint32_t v, const char *variant)
    dd_status dd_delete_set(dd_tri *t, const uint32_t *vs, size_t n)
    dd_status dd_delete_set_with(dd_tri *t, const uint32_t *vs, size_t n, const char *variant)
    dd_status dd_move(dd_tri *t, uint32_t v, const double *p)
    dd_status dd_move_weighted(dd_tri *t, uint32_t v, const double *p, double w)
    dd_status dd_insert(dd_tri *t, const double *p, uint32_t *index)
    dd_status dd_reinsert(dd_tri *t, uint32_t v)
    dd_cell_id dd_cell_end(const dd_tri *t)
    int dd_cell_alive(const dd_tri *t, dd_cell_id c)
    dd_status dd_cell(const dd_tri *t, dd_cell_id c, int32_t *v, dd_cell_id *nbr)
    dd_status dd_locate_from(const dd_tri *t, const double *p, dd_cell_id hint, dd_cell_id *cell)
    dd_status dd_created_cells(const dd_tri *t, const dd_cell_id **cells, size_t *n)
    dd_status dd_insert_from(dd_tri *t, const double *p, dd_cell_id hint, uint32_t *index)
    dd_status dd_insert_weighted_from(dd_tri *t, const double *p, double w, dd_cell_id hint, uint32_t *index)
    dd_status dd_insert_many(dd_tri *t, const double *xyz, const double *w, size_t m, uint32_t *indices,
                             size_t *merged)
    dd_status dd_move_many(dd_tri *t, const uint32_t *vs, const double *xyz, const double *w, size_t m)
    dd_status dd_locate_many(const dd_tri *t, const double *xyz, size_t m, dd_cell_id *cells)
    dd_status dd_nearest_many(const dd_tri *t, const double *xyz, size_t m, uint32_t *nearest)
    dd_status dd_points(const dd_tri *t, double *xyz, double *w)
    dd_status dd_cells_vertices(const dd_tri *t, const dd_cell_id *ids, size_t n, int32_t *verts)
    dd_status dd_write(const dd_tri *t, const char *path)
    dd_status dd_write_ex(const dd_tri *t, const char *path, unsigned flags)
    const char *dd_variant_name(size_t i)
    const char *dd_variant_description(size_t i)
    size_t dd_memory_bytes(const dd_tri *t)

# Status names in the order of dtdel.h's enum dd_status (tests/test_python.py checks it).
STATUS_NAMES = [
    "DD_OK", "DD_ERR_NOMEM", "DD_ERR_IO", "DD_ERR_PARSE", "DD_ERR_NAN",
    "DD_ERR_INFINITE", "DD_ERR_TOO_FEW", "DD_ERR_COLLINEAR", "DD_ERR_COPLANAR",
    "DD_ERR_UNKNOWN_VERTEX", "DD_ERR_UNKNOWN_VARIANT", "DD_ERR_DUPLICATE",
    "DD_ERR_DIMENSION", "DD_ERR_INTERNAL", "DD_ERR_ARG", "DD_ERR_UNSUPPORTED",
    "DD_ERR_UNKNOWN_CELL", "DD_ERR_UNKNOWN_FORMAT",
]
cdef int ERR_NOMEM = 1, ERR_UNKNOWN_VERTEX = 9, ERR_ARG = 14
cdef int CLOSED = -1            # not a dd_status: the object was closed
DEF MSGLEN = 512
cdef uint64_t U32 = 1 << 32

STABLE_INDICES = DD_STABLE_INDICES
DISCARD_HIDDEN = DD_DISCARD_HIDDEN
WRITE_ASCII = DD_WRITE_ASCII


class DtdelError(ValueError):
    """A libdtdel call failed, or its arguments were refused before it.
    .code is the dd_status number, .status its C name ("DD_ERR_NAN", ...),
    .message what went wrong, naming the position or index.  A ValueError,
    as scipy's errors for the same inputs are."""

    def __init__(self, code, message):
        self.code = int(code)
        self.status = (STATUS_NAMES[self.code] if 0 <= self.code < len(STATUS_NAMES)
                       else "DD_STATUS_%d" % self.code)
        self.message = message or status_name(self.code)
        super().__init__("%s: %s" % (self.status, self.message))


def status_name(code):
    """The library's short name of a status (dd_status_name)."""
    return dd_status_name(<dd_status>int(code)).decode()


def version():
    """The C library's version string (dd_version)."""
    return dd_version().decode()


def variants():
    """The deletion strategies' names, the default first (dd_variant_name)."""
    out = []
    cdef size_t i = 0
    while dd_variant_name(i) != NULL:
        out.append(dd_variant_name(i).decode())
        i += 1
    return out


def variant_descriptions():
    """{name: one-line description} of the strategies (dd_variant_description)."""
    return {n: dd_variant_description(i).decode() for i, n in enumerate(variants())}


def canonical_hash(tets):
    """dd_canonical_hash of an (m, 4) int32 canonical list."""
    cdef cnp.ndarray a = np.ascontiguousarray(tets, dtype=np.int32).reshape(-1, 4)
    cdef size_t n = cnp.PyArray_DIM(a, 0)
    with nogil:
        h = dd_canonical_hash(<int32_t *>cnp.PyArray_DATA(a), n)
    return int(h)


cdef inline double now() nogil:
    cdef timespec ts
    clock_gettime(CLOCK_MONOTONIC, &ts)
    return ts.tv_sec + 1e-9 * ts.tv_nsec


cdef arg_error(str what):
    return DtdelError(ERR_ARG, what)


cdef cnp.ndarray as_points(object p, str what):
    """An (m, 3) C-contiguous float64 array of p (a copy when needed); a
    single point (3,) is one row.  DD_ERR_ARG for another shape or a
    dtype that is not a real number."""
    a = np.asarray(p)
    if a.dtype.kind not in "biuf":
        raise arg_error("%s: coordinates must be real numbers, got dtype %s" % (what, a.dtype))
    if a.ndim == 1 and a.shape[0] == 3:
        a = a.reshape(1, 3)
    if a.ndim != 2 or a.shape[1] != 3:
        raise arg_error("%s: points must be an (m, 3) array, got shape %s" % (what, a.shape))
    return np.ascontiguousarray(a, dtype=np.float64)


cdef cnp.ndarray as_point(object p, str what):
    a = np.asarray(p)
    if a.dtype.kind not in "biuf" or a.shape != (3,):
        raise arg_error("%s: a point is 3 real coordinates, got shape %s dtype %s" % (what, a.shape, a.dtype))
    return np.ascontiguousarray(a, dtype=np.float64)


cdef object as_weights(object w, Py_ssize_t m, str what):
    if w is None:
        return None
    a = np.asarray(w)
    if a.dtype.kind not in "biuf":
        raise arg_error("%s: weights must be real numbers, got dtype %s" % (what, a.dtype))
    if a.ndim == 0 and m == 1:
        a = a.reshape(1)
    if a.shape != (m,):
        raise arg_error("%s: weights must be an (%d,) array, got shape %s" % (what, m, a.shape))
    return np.ascontiguousarray(a, dtype=np.float64)


cdef cnp.ndarray as_ids(object vs, str what):
    """A uint32 array of vertex indices; DD_ERR_ARG for a non-integer
    dtype, DD_ERR_UNKNOWN_VERTEX (naming it) for one outside [0, 2^32)."""
    a = np.asarray(vs)
    if a.size == 0:
        return np.zeros(0, dtype=np.uint32)
    if a.dtype.kind not in "iu":
        raise arg_error("%s: vertex indices must be integers, got dtype %s" % (what, a.dtype))
    a = a.reshape(-1)
    if a.dtype.kind == "i" and a.min() < 0:
        raise DtdelError(ERR_UNKNOWN_VERTEX, "%s: vertex %d (position %d) is not an index"
                         % (what, a.min(), int(np.argmin(a))))
    if a.max() >= U32:
        raise DtdelError(ERR_UNKNOWN_VERTEX, "%s: vertex %d (position %d) is outside [0, 2^32)"
                         % (what, a.max(), int(np.argmax(a))))
    return np.ascontiguousarray(a, dtype=np.uint32)


cdef uint32_t as_id(object v, str what) except? 0xffffffff:
    try:
        i = int(v)
    except (TypeError, ValueError):
        raise arg_error("%s: a vertex index is an integer, got %r" % (what, v))
    if not 0 <= i < U32:
        raise DtdelError(ERR_UNKNOWN_VERTEX, "%s: vertex %d is outside [0, 2^32)" % (what, i))
    return <uint32_t>i


cdef cnp.ndarray take_ints(void *ptr, size_t count, int width, object dtype):
    """A numpy copy of count x width int32 (or uint32) values malloc'd by
    the library, which it frees."""
    try:
        out = np.empty((count, width), dtype=dtype)
        if count:
            memcpy(cnp.PyArray_DATA(out), ptr, count * width * 4)
        return out
    finally:
        free(ptr)


cdef unsigned thread_count(n, what) except? 0:
    """A thread count from Python: an int >= 0 (0: every core; past 1024
    clamped by the library)."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
        raise arg_error("%s: threads must be an integer >= 0 (0: every core), got %r" % (what, n))
    return <unsigned>min(int(n), 1024)


cdef unsigned thread_flag(threads, what) except? 1:
    """dd_create_ex's thread bits: none for None (1, or DTDEL_THREADS),
    DD_THREADS_ALL for 0, DD_THREADS(n) else."""
    if threads is None:
        return 0
    cdef unsigned n = thread_count(threads, what)
    return DD_THREADS_ALL if n == 0 else DD_THREADS(n)


cdef class Triangulation:
    """The Delaunay triangulation of an (n, 3) array of points (dd_create),
    or with weights (an (n,) array) the regular one (dd_create_ex), its
    hidden points kept, or forgotten when discard_hidden; built on
    `threads` threads (0: every core; None: 1, or DTDEL_THREADS), with the
    same result on any count.  A point's row
    number is its input index; duplicates are merged into their first
    occurrence (alias).  -1 stands for the infinite vertex.

    Every method is one call of src/dtdel.h, the array ones with the GIL
    released.  Reads may run in many threads at once; an edit takes the
    object for itself (a per-object lock).  A failed call raises
    DtdelError and leaves the triangulation as it was.  Use `with` or
    close() to free it early.

    >>> import numpy as np, dtdel
    >>> t = dtdel.Triangulation(np.random.default_rng(1).random((100, 3)))
    >>> t.delete(7); t.num_vertices
    99
    """
    cdef dd_tri *t
    cdef pthread_rwlock_t lock
    cdef readonly unsigned long long edits
    cdef readonly double last_c_seconds
    cdef object __weakref__

    def __cinit__(self, *args, **kwargs):
        self.t = NULL
        self.edits = 0
        self.last_c_seconds = 0.0
        pthread_rwlock_init(&self.lock, NULL)

    def __dealloc__(self):
        if self.t != NULL:
            dd_free(self.t)
            self.t = NULL
        pthread_rwlock_destroy(&self.lock)

    def __init__(self, points, weights=None, stable_indices=False, discard_hidden=False, threads=None):
        cdef cnp.ndarray xyz = as_points(points, "Triangulation")
        cdef unsigned tflag = thread_flag(threads, "Triangulation")
        if cnp.PyArray_DIM(xyz, 0) >= U32:
            raise arg_error("Triangulation: %d points, more than 2^32 - 1" % cnp.PyArray_DIM(xyz, 0))
        wa = as_weights(weights, cnp.PyArray_DIM(xyz, 0), "Triangulation")
        cdef const double *wp = NULL
        if wa is not None:
            wp = <const double *>cnp.PyArray_DATA(wa)
        cdef unsigned flags = ((DD_STABLE_INDICES if stable_indices else 0)
                               | (DD_DISCARD_HIDDEN if discard_hidden else 0) | tflag)
        cdef uint32_t n = cnp.PyArray_DIM(xyz, 0)
        cdef char msg[MSGLEN]
        cdef dd_tri *out = NULL
        cdef dd_status s
        cdef double t0
        msg[0] = 0
        with nogil:
            t0 = now()
            if wp == NULL and flags == 0:
                s = dd_create(&out, <const double *>cnp.PyArray_DATA(xyz), n, msg, MSGLEN)
            else:
                s = dd_create_ex(&out, <const double *>cnp.PyArray_DATA(xyz), wp, n, flags, msg, MSGLEN)
            self.last_c_seconds = now() - t0
        if s != 0:
            raise DtdelError(s, msg.decode(errors="replace"))
        with nogil:
            pthread_rwlock_wrlock(&self.lock)
        old = self.t
        self.t = out
        self.edits += 1
        with nogil:
            pthread_rwlock_unlock(&self.lock)
        if old != NULL:
            dd_free(old)

    # ---- lifetime and locking ----------------------------------------------
    def close(self):
        """Frees the C triangulation (dd_free); later calls raise ValueError."""
        cdef dd_tri *old
        with nogil:
            pthread_rwlock_wrlock(&self.lock)
            old = self.t
            self.t = NULL
            pthread_rwlock_unlock(&self.lock)
            if old != NULL:
                dd_free(old)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def closed(self):
        return self.t == NULL

    cdef inline int rd(self) except -1:
        """Takes the lock for a read (released by un); ValueError if closed."""
        with nogil:
            pthread_rwlock_rdlock(&self.lock)
        if self.t == NULL:
            pthread_rwlock_unlock(&self.lock)
            raise ValueError("the triangulation is closed")
        return 0

    cdef inline int wr(self) except -1:
        with nogil:
            pthread_rwlock_wrlock(&self.lock)
        if self.t == NULL:
            pthread_rwlock_unlock(&self.lock)
            raise ValueError("the triangulation is closed")
        self.edits += 1
        return 0

    cdef inline void un(self):
        pthread_rwlock_unlock(&self.lock)

    cdef int edit_done(self, dd_status s) except -1:
        """After an edit, with the write lock held: releases it, raising
        DtdelError with dd_errmsg's message (copied under the lock) if s
        failed."""
        cdef char msg[MSGLEN]
        if s != 0:
            strncpy(msg, dd_errmsg(self.t), MSGLEN - 1)
            msg[MSGLEN - 1] = 0
        self.un()
        if s != 0:
            raise DtdelError(s, msg.decode(errors="replace"))
        return 0

    cdef int read_done(self, dd_status s, object what) except -1:
        """After a read, with the read lock held: releases it; a failed read
        reports by status alone (dtdel.h), so its message is made here."""
        self.un()
        if s != 0:
            raise DtdelError(s, "%s: %s" % (what() if callable(what) else what, status_name(s)))
        return 0

    def errmsg(self):
        """The message of the last failed edit (dd_errmsg)."""
        self.rd()
        m = dd_errmsg(self.t).decode(errors="replace")
        self.un()
        return m

    # ---- threads -------------------------------------------------------------
    @property
    def threads(self):
        """The threads the calls on it use (dd_threads): the construction,
        locate_many, nearest_many.  Set it (dd_set_threads) to n >= 1, or
        0 for every core; the results never depend on it."""
        self.rd(); n = dd_threads(self.t); self.un()
        return n

    @threads.setter
    def threads(self, n):
        cdef unsigned k = thread_count(n, "threads")
        self.wr(); dd_set_threads(self.t, k); self.un()

    # ---- sizes ---------------------------------------------------------------
    @property
    def num_input(self):
        """Input indices so far: the points given, inserted or moved in."""
        self.rd(); n = dd_num_input(self.t); self.un()
        return n

    @property
    def num_vertices(self):
        """Finite vertices now."""
        self.rd(); n = dd_num_vertices(self.t); self.un()
        return n

    @property
    def num_duplicates(self):
        """Input points merged into an equal earlier one."""
        self.rd(); n = dd_num_duplicates(self.t); self.un()
        return n

    @property
    def num_tets(self):
        """Cells, finite and infinite."""
        self.rd(); n = dd_num_tets(self.t); self.un()
        return n

    @property
    def num_finite_tets(self):
        self.rd(); n = dd_num_finite_tets(self.t); self.un()
        return n

    @property
    def memory_bytes(self):
        """Bytes held by the triangulation's arrays (dd_memory_bytes)."""
        self.rd(); n = dd_memory_bytes(self.t); self.un()
        return n

    def __len__(self):
        return self.num_vertices

    def __repr__(self):
        if self.t == NULL:
            return "<dtdel.Triangulation (closed)>"
        return "<dtdel.Triangulation: %d vertices, %d finite cells%s>" % (
            self.num_vertices, self.num_finite_tets, ", weighted" if self.is_weighted else "")

    # ---- vertices ------------------------------------------------------------
    def alias(self, i):
        """The vertex input point i became (i unless a duplicate)."""
        cdef uint32_t v = as_id(i, "alias")
        self.rd(); a = dd_alias(self.t, v); self.un()
        if a == U32 - 1:
            raise DtdelError(ERR_UNKNOWN_VERTEX, "alias: no input point %d" % v)
        return a

    def is_vertex(self, v):
        try:
            i = int(v)
        except (TypeError, ValueError):
            return False
        if not 0 <= i < U32:
            return False
        self.rd(); r = dd_is_vertex(self.t, <uint32_t>i); self.un()
        return bool(r)

    def vertices(self):
        """The input indices of the vertices now, ascending (int64 array)."""
        self.rd()
        cdef uint32_t n = dd_num_input(self.t), i, k = 0
        out = np.empty(dd_num_vertices(self.t), dtype=np.int64)
        cdef int64_t[::1] o = out
        with nogil:
            for i in range(n):
                if dd_is_vertex(self.t, i):
                    o[k] = i
                    k += 1
        self.un()
        return out

    def point(self, v):
        """Coordinates of vertex v (dd_point)."""
        cdef uint32_t i = as_id(v, "point")
        p = np.empty(3)
        cdef double[::1] pv = p
        self.rd()
        s = dd_point(self.t, i, &pv[0])
        self.read_done(s, "point(%d)" % i)
        return p

    @property
    def points(self):
        """The vertices' points, an (num_vertices, 3) array in the order of
        vertices()."""
        xyz = self.input_points()
        return xyz[self.vertices()]

    cdef uint32_t vertex(self, object v, str what) except? 0xffffffff:
        """v checked to be a vertex now, for the calls that answer 0 otherwise."""
        cdef uint32_t i = as_id(v, what)
        self.rd(); r = dd_is_vertex(self.t, i); self.un()
        if not r:
            raise DtdelError(ERR_UNKNOWN_VERTEX, "%s: %d is not a vertex" % (what, i))
        return i

    def degree(self, v):
        """Vertices adjacent to v, the infinite one counted (dd_degree)."""
        cdef uint32_t i = self.vertex(v, "degree")
        self.rd(); d = dd_degree(self.t, i); self.un()
        if d == 0:
            raise MemoryError("degree(%d): out of memory" % i)
        return d

    def on_hull(self, v):
        cdef uint32_t i = self.vertex(v, "on_hull")
        self.rd(); r = dd_on_hull(self.t, i); self.un()
        return bool(r)

    def neighbors(self, v):
        """v's finite neighbours, as an int64 array (dd_neighbors)."""
        cdef uint32_t i = self.vertex(v, "neighbors"), cap = self.degree(v), n
        buf = np.empty(max(cap, 1), dtype=np.uint32)
        cdef uint32_t[::1] b = buf
        self.rd()
        with nogil:
            n = dd_neighbors(self.t, i, &b[0], cap)
        self.un()
        if n == 0:
            raise MemoryError("neighbors(%d): out of memory" % i)
        return buf[:min(n, cap)].astype(np.int64)

    def incident_cells(self, v):
        """The cells around v as an (m, 4) int32 array, -1 infinite."""
        cdef uint32_t i = self.vertex(v, "incident_cells"), cap = 2 * self.degree(v), n
        buf = np.zeros((max(cap, 1), 4), dtype=np.int32)
        cdef int32_t[:, ::1] b = buf
        self.rd()
        with nogil:
            n = dd_incident_cells(self.t, i, <int32_t (*)[4]>&b[0, 0], cap)
        self.un()
        if n == 0:
            raise MemoryError("incident_cells(%d): out of memory" % i)
        return buf[:min(n, cap)].copy()

    # ---- edits ---------------------------------------------------------------
    def delete(self, v, variant=None):
        """Deletes vertex v (dd_delete; dd_delete_with when variant is named)."""
        cdef uint32_t i = as_id(v, "delete")
        cdef bytes name = None if variant is None else str(variant).encode()
        cdef const char *nm = NULL if name is None else <const char *>name
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_delete(self.t, i) if nm == NULL else dd_delete_with(self.t, i, nm)
        self.edit_done(s)

    def delete_set(self, vs, variant=None):
        """Deletes the vertices vs as one set, all or nothing (dd_delete_set)."""
        cdef cnp.ndarray a = as_ids(vs, "delete_set")
        cdef bytes name = None if variant is None else str(variant).encode()
        cdef const char *nm = NULL if name is None else <const char *>name
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        cdef dd_status s
        cdef double t0
        self.wr()
        with nogil:
            t0 = now()
            if nm == NULL:
                s = dd_delete_set(self.t, <const uint32_t *>cnp.PyArray_DATA(a), m)
            else:
                s = dd_delete_set_with(self.t, <const uint32_t *>cnp.PyArray_DATA(a), m, nm)
            self.last_c_seconds = now() - t0
        self.edit_done(s)

    def insert(self, p):
        """Inserts point p; returns its input index (dd_insert)."""
        return self.insert_from(p, -1, _call="insert")

    def insert_weighted(self, p, w):
        """Inserts the weighted point (p, w); returns its input index, also
        when it ends hidden (dd_insert_weighted)."""
        return self.insert_weighted_from(p, w, -1)

    def insert_from(self, p, hint=-1, _call="insert_from"):
        """Inserts point p, the walk starting at cell id hint (-1: the
        library's choice); returns its input index (dd_insert_from)."""
        cdef cnp.ndarray a = as_point(p, _call)
        cdef dd_cell_id h = int(hint)
        cdef uint32_t idx = 0
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_insert(self.t, <const double *>cnp.PyArray_DATA(a), &idx) if h == -1 else \
                dd_insert_from(self.t, <const double *>cnp.PyArray_DATA(a), h, &idx)
        self.edit_done(s)
        return idx

    def insert_weighted_from(self, p, w, hint=-1):
        """insert_weighted from cell id hint (dd_insert_weighted_from)."""
        cdef cnp.ndarray a = as_point(p, "insert_weighted")
        cdef double wt = float(w)
        cdef dd_cell_id h = int(hint)
        cdef uint32_t idx = 0
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_insert_weighted(self.t, <const double *>cnp.PyArray_DATA(a), wt, &idx) if h == -1 else \
                dd_insert_weighted_from(self.t, <const double *>cnp.PyArray_DATA(a), wt, h, &idx)
        self.edit_done(s)
        return idx

    def insert_many(self, points, weights=None):
        """Inserts an (m, 3) array of points (and (m,) weights) at once;
        returns (indices, merged): each point's input index (int64), and
        how many equalled a vertex or an earlier point (dd_insert_many).
        All or nothing."""
        cdef cnp.ndarray a = as_points(points, "insert_many")
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        wa = as_weights(weights, m, "insert_many")
        cdef const double *wp = NULL if wa is None else <const double *>cnp.PyArray_DATA(wa)
        out = np.empty(m, dtype=np.uint32)
        cdef uint32_t *o = <uint32_t *>cnp.PyArray_DATA(out)
        cdef size_t merged = 0
        cdef dd_status s
        cdef double t0
        self.wr()
        with nogil:
            t0 = now()
            s = dd_insert_many(self.t, <const double *>cnp.PyArray_DATA(a), wp, m, o, &merged)
            self.last_c_seconds = now() - t0
        self.edit_done(s)
        return out.astype(np.int64), merged

    def move_many(self, vs, points, weights=None):
        """Moves vertices vs to the rows of points (with weights on a
        weighted triangulation), each keeping its index (dd_move_many).
        All or nothing."""
        cdef cnp.ndarray v = as_ids(vs, "move_many")
        cdef cnp.ndarray a = as_points(points, "move_many")
        if cnp.PyArray_DIM(a, 0) != cnp.PyArray_DIM(v, 0):
            raise arg_error("move_many: %d vertices, %d points" % (cnp.PyArray_DIM(v, 0), cnp.PyArray_DIM(a, 0)))
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        wa = as_weights(weights, m, "move_many")
        cdef const double *wp = NULL if wa is None else <const double *>cnp.PyArray_DATA(wa)
        cdef dd_status s
        cdef double t0
        self.wr()
        with nogil:
            t0 = now()
            s = dd_move_many(self.t, <const uint32_t *>cnp.PyArray_DATA(v), <const double *>cnp.PyArray_DATA(a), wp, m)
            self.last_c_seconds = now() - t0
        self.edit_done(s)

    def reinsert(self, v):
        """Puts back deleted vertex v at its point (dd_reinsert)."""
        cdef uint32_t i = as_id(v, "reinsert")
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_reinsert(self.t, i)
        self.edit_done(s)

    def move(self, v, p):
        """Moves vertex v to p, keeping its index (dd_move; on a weighted
        triangulation v keeps its weight, and may be a hidden point)."""
        cdef uint32_t i = as_id(v, "move")
        cdef cnp.ndarray a = as_point(p, "move")
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_move(self.t, i, <const double *>cnp.PyArray_DATA(a))
        self.edit_done(s)

    def move_weighted(self, v, p, w):
        """Moves point v of a weighted triangulation to p with weight w,
        keeping its index; p may be v's own point (a re-weighting).  v may
        end hidden, and may hide others (dd_move_weighted)."""
        cdef uint32_t i = as_id(v, "move_weighted")
        cdef cnp.ndarray a = as_point(p, "move_weighted")
        cdef double wt = float(w)
        cdef dd_status s
        self.wr()
        with nogil:
            s = dd_move_weighted(self.t, i, <const double *>cnp.PyArray_DATA(a), wt)
        self.edit_done(s)

    # ---- queries -------------------------------------------------------------
    def locate(self, p):
        """The four vertices of a cell whose closure holds p (dd_locate)."""
        cdef cnp.ndarray a = as_point(p, "locate")
        cdef int32_t c[4]
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_locate(self.t, <const double *>cnp.PyArray_DATA(a), c)
        self.read_done(s, lambda: "locate(%s)" % a.tolist())
        return (c[0], c[1], c[2], c[3])

    def nearest_vertex(self, p):
        """A vertex nearest to p, exact (dd_nearest_vertex)."""
        cdef cnp.ndarray a = as_point(p, "nearest_vertex")
        cdef uint32_t v = 0
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_nearest_vertex(self.t, <const double *>cnp.PyArray_DATA(a), &v)
        self.read_done(s, lambda: "nearest_vertex(%s)" % a.tolist())
        return v

    def cells(self):
        """(verts, nbrs): (m, 4) int32 arrays of all cells (dd_cells):
        verts[c, i] a vertex (-1 infinite), nbrs[c, i] the cell opposite it."""
        cdef int32_t *pv = NULL
        cdef int32_t *pn = NULL
        cdef size_t n = 0
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_cells(self.t, &pv, &pn, &n)
        self.read_done(s, "cells()")
        verts = take_ints(pv, n, 4, np.int32)
        return verts, take_ints(pn, n, 4, np.int32)

    def canonical(self):
        """The canonical form (dd_canonical): (m, 4) int32, rows sorted."""
        cdef int32_t *p = NULL
        cdef size_t n = 0
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_canonical(self.t, &p, &n)
        self.read_done(s, "canonical()")
        return take_ints(p, n, 4, np.int32)

    def local_canonical(self, vs):
        """Canonical form of the cells incident to any of vs (dd_local_canonical)."""
        cdef cnp.ndarray a = as_ids(vs, "local_canonical")
        cdef int32_t *p = NULL
        cdef size_t n = 0, m = cnp.PyArray_DIM(a, 0)
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_local_canonical(self.t, <const uint32_t *>cnp.PyArray_DATA(a), m, &p, &n)
        self.read_done(s, lambda: "local_canonical(%s)" % a.tolist()[:8])
        return take_ints(p, n, 4, np.int32)

    def canonical_hash(self):
        """dd_canonical_hash of canonical(): the key to compare with CGAL's."""
        return canonical_hash(self.canonical())

    def check(self):
        """The full validator (dd_check_msg): raises DtdelError, naming
        what is wrong, on a broken triangulation.  O(cells)."""
        cdef char msg[MSGLEN]
        cdef dd_status s
        msg[0] = 0
        self.rd()
        with nogil:
            s = dd_check_msg(self.t, msg, MSGLEN)
        self.un()
        if s != 0:
            raise DtdelError(s, "check(): " + (msg.decode(errors="replace") or status_name(s)))

    def is_valid(self):
        """True if the full validator passes (dd_check); check() says why not."""
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_check(self.t)
        self.un()
        return s == 0

    # ---- weighted points -------------------------------------------------------
    @property
    def is_weighted(self):
        """True if made with weights (dd_is_weighted)."""
        self.rd(); r = dd_is_weighted(self.t); self.un()
        return bool(r)

    def weight(self, i):
        """The weight of input point i, 0 when unweighted (dd_weight)."""
        cdef uint32_t v = as_id(i, "weight")
        cdef double w = 0
        self.rd()
        s = dd_weight(self.t, v, &w)
        self.read_done(s, "weight(%d)" % v)
        return w

    def is_hidden(self, i):
        """True if input point i is kept but hidden (dd_is_hidden)."""
        try:
            v = int(i)
        except (TypeError, ValueError):
            return False
        if not 0 <= v < U32:
            return False
        self.rd(); r = dd_is_hidden(self.t, <uint32_t>v); self.un()
        return bool(r)

    def hidden(self):
        """The input indices of the kept hidden points, ascending (dd_hidden)."""
        cdef uint32_t *p = NULL
        cdef size_t n = 0
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_hidden(self.t, &p, &n)
        self.read_done(s, "hidden()")
        return take_ints(p, n, 1, np.uint32).reshape(-1).astype(np.int64)

    # ---- whole-array reads ---------------------------------------------------
    def locate_many(self, points):
        """Cell ids (int64) of cells whose closures hold the rows of points,
        an infinite cell's id for a point outside the hull (dd_locate_many);
        DtdelError on a NaN or infinite row, naming it."""
        cdef cnp.ndarray a = as_points(points, "locate_many")
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        out = np.empty(m, dtype=np.int64)
        cdef dd_cell_id *o = <dd_cell_id *>cnp.PyArray_DATA(out)
        cdef dd_status s
        cdef double t0
        self.rd()
        with nogil:
            t0 = now()
            s = dd_locate_many(self.t, <const double *>cnp.PyArray_DATA(a), m, o)
            self.last_c_seconds = now() - t0
        self.un()
        if s != 0:
            raise bad_query("locate_many", s, a)
        return out

    def nearest_many(self, points):
        """Input indices (int64) of vertices nearest to the rows of points
        (dd_nearest_many; least power distance when weighted)."""
        cdef cnp.ndarray a = as_points(points, "nearest_many")
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        out = np.empty(m, dtype=np.uint32)
        cdef uint32_t *o = <uint32_t *>cnp.PyArray_DATA(out)
        cdef dd_status s
        cdef double t0
        self.rd()
        with nogil:
            t0 = now()
            s = dd_nearest_many(self.t, <const double *>cnp.PyArray_DATA(a), m, o)
            self.last_c_seconds = now() - t0
        self.un()
        if s != 0:
            raise bad_query("nearest_many", s, a)
        return out.astype(np.int64)

    def input_points(self, with_weights=False):
        """Every input index's point, an (num_input, 3) array, NaN rows for
        indices that name no point now; with_weights: also the (num_input,)
        weights (dd_points)."""
        self.rd()
        cdef uint32_t n = dd_num_input(self.t)
        xyz, w = np.empty((n, 3)), np.empty(n)
        cdef double *px = <double *>cnp.PyArray_DATA(xyz)
        cdef double *pw = <double *>cnp.PyArray_DATA(w)
        cdef dd_status s
        cdef double t0
        with nogil:
            t0 = now()
            s = dd_points(self.t, px, pw)
            self.last_c_seconds = now() - t0
        self.read_done(s, "input_points()")
        return (xyz, w) if with_weights else xyz

    def cells_vertices(self, ids):
        """The vertices of cell ids, an (n, 4) int32 array (-1 infinite;
        dd_cells_vertices)."""
        c = np.asarray(ids)
        if c.size and c.dtype.kind not in "iu":
            raise arg_error("cells_vertices: cell ids must be integers, got dtype %s" % c.dtype)
        cdef cnp.ndarray a = np.ascontiguousarray(c, dtype=np.int64).reshape(-1)
        cdef size_t m = cnp.PyArray_DIM(a, 0)
        out = np.empty((m, 4), dtype=np.int32)
        cdef int32_t *o = <int32_t *>cnp.PyArray_DATA(out)
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_cells_vertices(self.t, <const dd_cell_id *>cnp.PyArray_DATA(a), m, o)
        self.read_done(s, "cells_vertices")
        return out

    # ---- cell handles and files ----------------------------------------------
    def cell_end(self):
        """Live cell ids lie in [0, cell_end()) (dd_cell_end)."""
        self.rd(); e = dd_cell_end(self.t); self.un()
        return e

    def cell_alive(self, c):
        self.rd(); r = dd_cell_alive(self.t, int(c)); self.un()
        return bool(r)

    def cell(self, c):
        """(verts, nbrs) of cell id c: 4 vertices (-1 infinite) and the 4
        cell ids across the facets opposite them (dd_cell)."""
        cdef int32_t v[4]
        cdef dd_cell_id nb[4]
        cdef dd_cell_id cid = int(c)
        self.rd()
        s = dd_cell(self.t, cid, v, nb)
        self.read_done(s, "cell(%d)" % cid)
        return (v[0], v[1], v[2], v[3]), (nb[0], nb[1], nb[2], nb[3])

    def locate_from(self, p, hint=-1):
        """The id of a cell whose closure holds p, walked from hint (dd_locate_from)."""
        cdef cnp.ndarray a = as_point(p, "locate_from")
        cdef dd_cell_id h = int(hint), c = -1
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_locate_from(self.t, <const double *>cnp.PyArray_DATA(a), h, &c)
        self.read_done(s, lambda: "locate_from(%s, hint=%d)" % (a.tolist(), h))
        return c

    def created_cells(self):
        """The ids of the live cells the last edit made (dd_created_cells)."""
        cdef const dd_cell_id *p = NULL
        cdef size_t n = 0, i
        self.rd()
        s = dd_created_cells(self.t, &p, &n)
        if s != 0:
            self.read_done(s, "created_cells()")
        out = np.empty(n, dtype=np.int64)
        cdef int64_t[::1] o = out
        with nogil:
            for i in range(n):
                o[i] = p[i]
        self.un()
        return out

    def write(self, path, ascii=False):
        """Writes the finite cells to a .vtu or .mesh file (dd_write); a .vtu
        is binary, or ASCII with ascii=True or a name ending .ascii.vtu
        (dd_write_ex, DD_WRITE_ASCII)."""
        cdef bytes b = str(path).encode()
        cdef const char *pp = b
        cdef unsigned flags = DD_WRITE_ASCII if ascii else 0
        cdef dd_status s
        self.rd()
        with nogil:
            s = dd_write(self.t, pp) if flags == 0 else dd_write_ex(self.t, pp, flags)
        self.read_done(s, "write(%r%s)" % (str(path), ", ascii=True" if ascii else ""))

    def _write_ex(self, path, unsigned flags):
        """dd_write_ex with raw flags, for the tests; returns the status."""
        cdef bytes b = str(path).encode()
        self.rd(); s = dd_write_ex(self.t, b, flags); self.un()
        return s

    # ---- the finite arrays scipy's Delaunay has ------------------------------
    def _simplices(self):
        """(simplices, cell_to_simplex): the live finite cells in id order,
        a (k, 4) intc array (positively oriented), and each cell id's
        simplex index (-1 for an infinite or dead id).  One sequential
        pass over the ids, O(cells)."""
        self.rd()
        cdef dd_cell_id end = dd_cell_end(self.t), c
        cdef size_t nfin = dd_num_finite_tets(self.t), k = 0
        c2s = np.empty(end, dtype=np.int32)
        simp = np.empty((nfin, 4), dtype=np.intc)
        cdef int32_t[::1] cs = c2s
        cdef int[:, ::1] sv = simp
        cdef int32_t v[4]
        cdef double t0
        with nogil:
            t0 = now()
            for c in range(end):
                cs[c] = -1
                if dd_cell(self.t, c, v, NULL) != 0 or v[0] < 0 or v[1] < 0 or v[2] < 0 or v[3] < 0:
                    continue
                cs[c] = <int32_t>k
                sv[k, 0] = v[0]; sv[k, 1] = v[1]; sv[k, 2] = v[2]; sv[k, 3] = v[3]
                k += 1
            self.last_c_seconds = now() - t0
        self.un()
        return simp, c2s

    def _neighbors(self, cnp.ndarray c2s_arr):
        """scipy's neighbors of _simplices' simplices: (k, 4) intc, the
        simplex across the facet opposite vertex i, -1 across the hull.
        c2s_arr: _simplices' cell_to_simplex, of this same state."""
        self.rd()
        cdef dd_cell_id end = dd_cell_end(self.t), c
        cdef size_t nfin = dd_num_finite_tets(self.t)
        if <dd_cell_id>cnp.PyArray_DIM(c2s_arr, 0) != end:
            self.un()
            raise arg_error("_neighbors: a cell_to_simplex of another state")
        nbr = np.empty((nfin, 4), dtype=np.intc)
        cdef int32_t[::1] cs = c2s_arr
        cdef int[:, ::1] sn = nbr
        cdef dd_cell_id nb[4]
        cdef int32_t k
        with nogil:
            for c in range(end):
                k = cs[c]
                if k < 0 or dd_cell(self.t, c, NULL, nb) != 0:
                    continue
                sn[k, 0] = cs[nb[0]]; sn[k, 1] = cs[nb[1]]; sn[k, 2] = cs[nb[2]]; sn[k, 3] = cs[nb[3]]
        self.un()
        return nbr

    def _hull(self):
        """The hull's triangles, (h, 3) intc, each ordered so that its
        right-hand normal points away from the hull.  O(cells)."""
        self.rd()
        cdef dd_cell_id end = dd_cell_end(self.t), c
        cdef size_t ninf = dd_num_tets(self.t) - dd_num_finite_tets(self.t), h = 0
        hull = np.empty((ninf, 3), dtype=np.intc)
        cdef int[:, ::1] hv = hull
        cdef int32_t v[4]
        cdef int inf
        with nogil:
            for c in range(end):
                if dd_cell(self.t, c, v, NULL) != 0:
                    continue
                inf = 0 if v[0] < 0 else 1 if v[1] < 0 else 2 if v[2] < 0 else 3 if v[3] < 0 else -1
                if inf >= 0 and h < ninf:
                    hull_facet(v, inf, &hv[h, 0])
                    h += 1
        self.un()
        return hull

    def _aliases(self):
        """dd_alias of every input index (int64; -1 where it names no point)."""
        self.rd()
        cdef uint32_t nin = dd_num_input(self.t), i, a
        out = np.empty(nin, dtype=np.int64)
        cdef int64_t[::1] o = out
        with nogil:
            for i in range(nin):
                a = dd_alias(self.t, i)
                o[i] = -1 if a == <uint32_t>(U32 - 1) else <int64_t>a
        self.un()
        return out

    def _vertex_neighbor_vertices(self):
        """(indptr, indices) of the finite neighbours of every input index,
        as scipy's vertex_neighbor_vertices (empty for a non-vertex): each
        vertex's degree once, then its neighbours into their slice."""
        self.rd()
        cdef uint32_t nin = dd_num_input(self.t), i, got
        indptr = np.zeros(nin + 1, dtype=np.intc)
        deg = np.zeros(nin, dtype=np.uint32)
        cdef int[::1] ip = indptr
        cdef uint32_t[::1] dg = deg
        cdef size_t total = 0
        cdef int bad = 0
        with nogil:
            for i in range(nin):
                if dd_is_vertex(self.t, i):
                    dg[i] = dd_degree(self.t, i)
                    bad |= dg[i] == 0               # a vertex's degree is >= 4: out of memory
                    total += dg[i]
        buf = np.empty(max(total, 1), dtype=np.uint32)
        cdef uint32_t[::1] b = buf
        cdef size_t at = 0
        with nogil:
            for i in range(nin):
                ip[i] = <int>at
                if bad or dg[i] == 0:
                    continue
                got = dd_neighbors(self.t, i, &b[at], dg[i])
                if got == 0 or got > dg[i]:
                    bad = 1
                    break
                at += got
            ip[nin] = <int>at
        self.un()
        if bad:
            raise MemoryError("vertex_neighbor_vertices: out of memory")
        return indptr, buf[:at].astype(np.intc)


cdef inline void hull_facet(const int32_t *v, int inf, int *out) nogil:
    """The three finite vertices of an infinite cell, in an order whose
    (b - a) x (c - a) points away from the hull: the cell with -1 read as a
    point beyond the facet is positive, and replacing the -1 by the
    facet's own order keeps that sign for an even permutation."""
    if inf == 0:
        out[0] = v[1]; out[1] = v[3]; out[2] = v[2]
    elif inf == 1:
        out[0] = v[0]; out[1] = v[2]; out[2] = v[3]
    elif inf == 2:
        out[0] = v[0]; out[1] = v[3]; out[2] = v[1]
    else:
        out[0] = v[0]; out[1] = v[1]; out[2] = v[2]


cdef object bad_query(str call, dd_status s, cnp.ndarray a):
    """The DtdelError of a whole-array read refused for a bad row, naming
    the first NaN or infinite row."""
    if s == ERR_NOMEM:
        return DtdelError(s, "%s: out of memory" % call)
    bad = np.flatnonzero(~np.isfinite(a).all(axis=1))
    at = int(bad[0]) if len(bad) else -1
    return DtdelError(s, "%s: point %d is %s" % (call, at, "NaN" if at >= 0 and np.isnan(a[at]).any()
                                                    else "infinite"))
