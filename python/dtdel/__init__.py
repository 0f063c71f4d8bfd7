"""
dtdel -- Python bindings of libdtdel, the exact 3D Delaunay engine whose
triangulations equal CGAL's simplex for simplex, with fast vertex deletion.

Thin: every method is one or two calls of src/dtdel.h through ctypes
(_lib.py); no geometry is computed here.  Vertices are named by their input
index, -1 stands for the infinite vertex.  A failed call raises DtdelError
with the library's status and message, and leaves the triangulation as it
was.

    import numpy as np, dtdel
    with dtdel.Triangulation(np.random.rand(1000, 3)) as t:
        t.delete(7)
        print(t.canonical_hash(), t.degree(8), t.locate([0.5, 0.5, 0.5]))

Weighted points give the regular triangulation (CGAL's Regular_triangulation_3):

    t = dtdel.Triangulation(xyz, weights=w)          # hidden points kept
    t.hidden(), t.is_hidden(3), t.weight(3), t.insert_weighted([0.5] * 3, 0.01)
    dtdel.Triangulation(xyz, weights=w, discard_hidden=True)   # forgotten
"""
import ctypes
from ctypes import byref, c_double, c_int32, c_int64, c_size_t, c_uint32, c_void_p

import numpy as np

from . import _lib
from ._lib import STATUS_NAMES, lib

__all__ = ["Triangulation", "DtdelError", "variants", "variant_descriptions",
           "status_name", "version", "canonical_hash", "STATUS_NAMES"]

_MSGLEN = 512
_U32 = 1 << 32


class DtdelError(Exception):
    """A libdtdel call failed.  .code is the dd_status number, .status its
    C name ("DD_ERR_UNKNOWN_VERTEX", ...), .message the library's message."""

    def __init__(self, code, message):
        self.code = int(code)
        self.status = (STATUS_NAMES[self.code] if 0 <= self.code < len(STATUS_NAMES)
                       else "DD_STATUS_%d" % self.code)
        self.message = message
        super().__init__("%s: %s" % (self.status, message or status_name(self.code)))


def _need(name):
    f = getattr(lib, name, None)
    if f is None:
        raise NotImplementedError("%s is not in the loaded libdtdel (%s)" % (name, _lib.PATH))
    return f


def status_name(code):
    """The library's short name of a status (dd_status_name)."""
    return lib.dd_status_name(int(code)).decode()


def version():
    """The library's version string (dd_version)."""
    return _need("dd_version")().decode()


def variants():
    """The deletion strategies' names, the default first (dd_variant_name)."""
    out, i = [], 0
    while True:
        name = lib.dd_variant_name(i)
        if name is None:
            return out
        out.append(name.decode())
        i += 1


def variant_descriptions():
    """{name: one-line description} of the strategies (dd_variant_description)."""
    return {n: lib.dd_variant_description(i).decode() for i, n in enumerate(variants())}


def canonical_hash(tets):
    """dd_canonical_hash of an (m, 4) int32 canonical list."""
    a = np.ascontiguousarray(tets, dtype=np.int32).reshape(-1, 4)
    return int(lib.dd_canonical_hash(a.ctypes.data_as(ctypes.POINTER(c_int32)), a.shape[0]))


def _point(p):
    a = np.ascontiguousarray(p, dtype=np.float64)
    if a.shape != (3,):
        raise ValueError("a point is 3 coordinates, got shape %s" % (a.shape,))
    return a


def _dptr(a):
    return a.ctypes.data_as(ctypes.POINTER(c_double))


def _vertex_list(vs):
    a = np.asarray(vs)
    if a.size and (a.min() < 0 or a.max() >= _U32):
        raise DtdelError(STATUS_NAMES.index("DD_ERR_UNKNOWN_VERTEX"),
                         "a vertex index is outside [0, 2^32)")
    return np.ascontiguousarray(a, dtype=np.uint32).reshape(-1)


def _points(p):
    """An (m, 3) C-contiguous float64 copy or view of p."""
    a = np.ascontiguousarray(p, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 3:
        a = a.reshape(-1, 3) if a.ndim == 1 and a.size % 3 == 0 else a
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError("points are an (m, 3) array, got shape %s" % (a.shape,))
    return a


def _weights(w, m):
    if w is None:
        return None
    a = np.ascontiguousarray(w, dtype=np.float64).reshape(-1)
    if a.shape != (m,):
        raise ValueError("weights are an (%d,) array, got shape %s" % (m, a.shape))
    return a


def _variant(variant):
    return None if variant is None else str(variant).encode()


def _take(ptr, count, width=4, dtype=np.int32):
    """Copies count x width ints of a malloc'd array, then frees it."""
    try:
        if count == 0:
            return np.zeros((0, width), dtype=dtype)
        return np.ctypeslib.as_array(ptr, shape=(count, width)).astype(dtype, copy=True)
    finally:
        if ptr:
            _lib.libc_free(ptr)


class Triangulation:
    """DT of an (n, 3) float64 array of points (dd_create); a point's row
    number is its input index.  Duplicates are merged into their first
    occurrence (alias).  With weights (an (n,) array), the regular
    triangulation (dd_create_ex), its hidden points kept, or forgotten
    when discard_hidden.  Use `with` or close() to free it early.  ctypes
    lets other threads run during a call: an edit needs the triangulation
    to itself (no other call on it meanwhile), as in C."""

    def __init__(self, points, weights=None, stable_indices=False, discard_hidden=False):
        xyz = np.ascontiguousarray(points, dtype=np.float64)
        if xyz.ndim != 2 or xyz.shape[1] != 3:
            raise ValueError("points must be an (n, 3) array, got shape %s" % (xyz.shape,))
        if xyz.shape[0] >= _U32:
            raise ValueError("too many points")
        self._t = None
        out = c_void_p()
        msg = ctypes.create_string_buffer(_MSGLEN)
        if weights is None and not stable_indices and not discard_hidden:
            s = lib.dd_create(byref(out), _dptr(xyz), xyz.shape[0], msg, _MSGLEN)
        else:
            w = None
            if weights is not None:
                w = np.ascontiguousarray(weights, dtype=np.float64)
                if w.shape != (xyz.shape[0],):
                    raise ValueError("weights must be an (n,) array")
            flags = (STABLE_INDICES if stable_indices else 0) | (DISCARD_HIDDEN if discard_hidden else 0)
            s = _need("dd_create_ex")(byref(out), _dptr(xyz), None if w is None else _dptr(w),
                                      xyz.shape[0], flags, msg, _MSGLEN)
        if s != 0:
            raise DtdelError(s, msg.value.decode(errors="replace"))
        self._t = out

    # ---- lifetime ------------------------------------------------------------
    def close(self):
        """Frees the C triangulation (dd_free); later calls raise ValueError."""
        if self._t is not None:
            lib.dd_free(self._t)
            self._t = None

    def __del__(self):
        if getattr(self, "_t", None) is not None and lib is not None:
            self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def _h(self):
        if self._t is None:
            raise ValueError("the triangulation is closed")
        return self._t

    def _check(self, s, what=None):
        """Raises DtdelError for a failed status.  An edit's message is
        dd_errmsg's; a read-only call (what: the call and its argument)
        reports by status alone (dtdel.h), so its message is made here."""
        if s != 0:
            msg = "%s: %s" % (what, status_name(s)) if what else self.errmsg()
            raise DtdelError(s, msg or status_name(s))

    def _vid(self, v):
        v = int(v)
        if not 0 <= v < _U32:
            raise DtdelError(STATUS_NAMES.index("DD_ERR_UNKNOWN_VERTEX"),
                             "vertex %d is outside [0, 2^32)" % v)
        return v

    def _vertex(self, v):
        """v checked to be a vertex now, for the calls that answer 0 otherwise."""
        v = self._vid(v)
        if not lib.dd_is_vertex(self._h, v):
            raise DtdelError(STATUS_NAMES.index("DD_ERR_UNKNOWN_VERTEX"),
                             "%d is not a vertex" % v)
        return v

    def errmsg(self):
        """The message of the last failed call (dd_errmsg)."""
        return lib.dd_errmsg(self._h).decode(errors="replace")

    # ---- sizes ---------------------------------------------------------------
    @property
    def num_input(self):
        return int(lib.dd_num_input(self._h))

    @property
    def num_vertices(self):
        return int(lib.dd_num_vertices(self._h))

    @property
    def num_duplicates(self):
        return int(lib.dd_num_duplicates(self._h))

    @property
    def num_tets(self):
        """Cells, finite and infinite."""
        return int(lib.dd_num_tets(self._h))

    @property
    def num_finite_tets(self):
        return int(lib.dd_num_finite_tets(self._h))

    @property
    def memory_bytes(self):
        return int(lib.dd_memory_bytes(self._h))

    def __len__(self):
        return self.num_vertices

    def __repr__(self):
        if self._t is None:
            return "<dtdel.Triangulation (closed)>"
        return "<dtdel.Triangulation: %d vertices, %d finite cells>" % (
            self.num_vertices, self.num_finite_tets)

    # ---- vertices ------------------------------------------------------------
    def alias(self, i):
        """The vertex input point i became (i unless a duplicate)."""
        a = lib.dd_alias(self._h, self._vid(i))
        if a == _U32 - 1:
            raise DtdelError(STATUS_NAMES.index("DD_ERR_UNKNOWN_VERTEX"), "no input point %d" % i)
        return int(a)

    def is_vertex(self, v):
        v = int(v)
        return 0 <= v < _U32 and bool(lib.dd_is_vertex(self._h, v))

    def vertices(self):
        """The input indices of the vertices now, ascending (int64 array)."""
        h = self._h
        return np.array([i for i in range(lib.dd_num_input(h)) if lib.dd_is_vertex(h, i)],
                        dtype=np.int64)

    def point(self, v):
        """Coordinates of vertex v (dd_point)."""
        p = np.empty(3)
        self._check(lib.dd_point(self._h, self._vid(v), _dptr(p)), "point(%d)" % v)
        return p

    @property
    def points(self):
        """The vertices' points, an (num_vertices, 3) array in the order of
        vertices()."""
        vs = self.vertices()
        out = np.empty((len(vs), 3))
        for k, v in enumerate(vs):
            self._check(lib.dd_point(self._h, int(v), _dptr(out[k])), "point(%d)" % v)
        return out

    def _star_count(self, n, call, v):
        """n, the count a star query answered for vertex v; 0 there means
        the library ran out of memory (dtdel.h: it has no status to say
        so, and a vertex has at least 4 neighbours and cells)."""
        if n == 0:
            raise MemoryError("%s(%d): out of memory" % (call, v))
        return n

    def degree(self, v):
        """Vertices adjacent to v, the infinite one counted (dd_degree)."""
        v = self._vertex(v)
        return self._star_count(int(lib.dd_degree(self._h, v)), "dd_degree", v)

    def on_hull(self, v):
        return bool(lib.dd_on_hull(self._h, self._vertex(v)))

    def neighbors(self, v):
        """v's finite neighbours, as an int64 array (dd_neighbors)."""
        v = self._vertex(v)
        cap = self.degree(v)
        buf = (c_uint32 * max(cap, 1))()
        n = self._star_count(lib.dd_neighbors(self._h, v, buf, cap), "dd_neighbors", v)
        return np.array(buf[:min(n, cap)], dtype=np.int64)

    def incident_cells(self, v):
        """The cells around v as an (m, 4) int32 array, -1 infinite."""
        v = self._vertex(v)
        cap = 2 * self.degree(v)        # a link of d vertices has 2d-4 triangles
        buf = np.zeros((max(cap, 1), 4), dtype=np.int32)
        n = lib.dd_incident_cells(self._h, v, buf.ctypes.data_as(ctypes.POINTER(c_int32)), cap)
        n = self._star_count(n, "dd_incident_cells", v)
        return buf[:min(n, cap)].copy()

    # ---- edits ---------------------------------------------------------------
    def delete(self, v, variant=None):
        """Deletes vertex v (dd_delete; dd_delete_with when variant is named)."""
        v = self._vid(v)
        if variant is None:
            self._check(lib.dd_delete(self._h, v))
        else:
            self._check(lib.dd_delete_with(self._h, v, _variant(variant)))

    def delete_set(self, vs, variant=None):
        """Deletes the vertices vs as one set, all or nothing (dd_delete_set)."""
        a = _vertex_list(vs)
        ptr = a.ctypes.data_as(ctypes.POINTER(c_uint32))
        if variant is None:
            self._check(lib.dd_delete_set(self._h, ptr, a.size))
        else:
            self._check(lib.dd_delete_set_with(self._h, ptr, a.size, _variant(variant)))

    def insert(self, p):
        """Inserts point p; returns its input index (dd_insert)."""
        a = _point(p)
        idx = c_uint32()
        self._check(lib.dd_insert(self._h, _dptr(a), byref(idx)))
        return int(idx.value)

    def insert_weighted(self, p, w):
        """Inserts the weighted point (p, w); returns its input index, also
        when it ends hidden (dd_insert_weighted)."""
        a = _point(p)
        idx = c_uint32()
        self._check(_need("dd_insert_weighted")(self._h, _dptr(a), float(w), byref(idx)))
        return int(idx.value)

    def insert_from(self, p, hint=-1):
        """Inserts point p, the walk starting at cell id hint (-1: the
        library's choice); returns its input index (dd_insert_from)."""
        a = _point(p)
        idx = c_uint32()
        self._check(lib.dd_insert_from(self._h, _dptr(a), int(hint), byref(idx)))
        return int(idx.value)

    def insert_weighted_from(self, p, w, hint=-1):
        """insert_weighted from cell id hint (dd_insert_weighted_from)."""
        a = _point(p)
        idx = c_uint32()
        self._check(lib.dd_insert_weighted_from(self._h, _dptr(a), float(w), int(hint), byref(idx)))
        return int(idx.value)

    def insert_many(self, points, weights=None):
        """Inserts an (m, 3) array of points (and (m,) weights) at once;
        returns (indices, merged): each point's input index, and how many
        equalled a vertex or an earlier point (dd_insert_many).  All or
        nothing."""
        a = _points(points)
        w = _weights(weights, len(a))
        out = np.empty(len(a), dtype=np.uint32)
        merged = c_size_t()
        self._check(lib.dd_insert_many(self._h, _dptr(a), None if w is None else _dptr(w), len(a),
                                       out.ctypes.data_as(ctypes.POINTER(c_uint32)), byref(merged)))
        return out.astype(np.int64), int(merged.value)

    def move_many(self, vs, points, weights=None):
        """Moves vertices vs to the rows of points (with weights on a
        weighted triangulation), each keeping its index (dd_move_many).
        All or nothing."""
        v = _vertex_list(vs)
        a = _points(points)
        if len(a) != len(v):
            raise ValueError("%d vertices, %d points" % (len(v), len(a)))
        w = _weights(weights, len(a))
        self._check(lib.dd_move_many(self._h, v.ctypes.data_as(ctypes.POINTER(c_uint32)), _dptr(a),
                                     None if w is None else _dptr(w), len(a)))

    def reinsert(self, v):
        """Puts back deleted vertex v at its point (dd_reinsert)."""
        self._check(lib.dd_reinsert(self._h, self._vid(v)))

    def move(self, v, p):
        """Moves vertex v to p, keeping its index (dd_move; on a weighted
        triangulation v keeps its weight, and may be a hidden point)."""
        a = _point(p)
        self._check(lib.dd_move(self._h, self._vid(v), _dptr(a)))

    def move_weighted(self, v, p, w):
        """Moves point v of a weighted triangulation to p with weight w,
        keeping its index; p may be v's own point (a re-weighting).  v may
        end hidden, and may hide others (dd_move_weighted)."""
        a = _point(p)
        self._check(_need("dd_move_weighted")(self._h, self._vid(v), _dptr(a), float(w)))

    # ---- queries -------------------------------------------------------------
    def locate(self, p):
        """The four vertices of a cell whose closure holds p (dd_locate)."""
        a = _point(p)
        cell = (c_int32 * 4)()
        self._check(lib.dd_locate(self._h, _dptr(a), cell), "locate(%s)" % a.tolist())
        return tuple(cell)

    def nearest_vertex(self, p):
        """A vertex nearest to p, exact (dd_nearest_vertex)."""
        a = _point(p)
        v = c_uint32()
        self._check(lib.dd_nearest_vertex(self._h, _dptr(a), byref(v)),
                    "nearest_vertex(%s)" % a.tolist())
        return int(v.value)

    def cells(self):
        """(verts, nbrs): (m, 4) int32 arrays of all cells (dd_cells):
        verts[c, i] a vertex (-1 infinite), nbrs[c, i] the cell opposite it."""
        pv, pn, n = ctypes.POINTER(c_int32)(), ctypes.POINTER(c_int32)(), c_size_t()
        self._check(lib.dd_cells(self._h, byref(pv), byref(pn), byref(n)), "cells()")
        verts = _take(pv, n.value)
        return verts, _take(pn, n.value)

    def canonical(self):
        """The canonical form (dd_canonical): (m, 4) int32, rows sorted."""
        p, n = ctypes.POINTER(c_int32)(), c_size_t()
        self._check(lib.dd_canonical(self._h, byref(p), byref(n)), "canonical()")
        return _take(p, n.value)

    def local_canonical(self, vs):
        """Canonical form of the cells incident to any of vs (dd_local_canonical)."""
        a = _vertex_list(vs)
        p, n = ctypes.POINTER(c_int32)(), c_size_t()
        self._check(lib.dd_local_canonical(self._h, a.ctypes.data_as(ctypes.POINTER(c_uint32)),
                                           a.size, byref(p), byref(n)),
                    "local_canonical(%s)" % a.tolist()[:8])
        return _take(p, n.value)

    def canonical_hash(self):
        """dd_canonical_hash of canonical(): the key to compare with CGAL's."""
        return canonical_hash(self.canonical())

    def check(self):
        """The full validator (dd_check); raises DtdelError on a broken mesh."""
        f = getattr(lib, "dd_check_msg", None)
        if f is None:
            self._check(lib.dd_check(self._h), "check()")
            return
        msg = ctypes.create_string_buffer(_MSGLEN)
        s = f(self._h, msg, _MSGLEN)
        if s != 0:
            raise DtdelError(s, "check(): " + (msg.value.decode(errors="replace")
                                               or status_name(s)))

    # ---- weighted points (issue 43) ---------------------------------------------
    @property
    def is_weighted(self):
        """True if made with weights (dd_is_weighted)."""
        return bool(_need("dd_is_weighted")(self._h))

    def weight(self, i):
        """The weight of input point i, 0 when unweighted (dd_weight)."""
        w = c_double()
        self._check(_need("dd_weight")(self._h, self._vid(i), byref(w)), "weight(%d)" % i)
        return float(w.value)

    def is_hidden(self, i):
        """True if input point i is kept but hidden (dd_is_hidden)."""
        i = int(i)
        return 0 <= i < _U32 and bool(_need("dd_is_hidden")(self._h, i))

    def hidden(self):
        """The input indices of the kept hidden points, ascending (dd_hidden)."""
        p, n = ctypes.POINTER(c_uint32)(), c_size_t()
        self._check(_need("dd_hidden")(self._h, byref(p), byref(n)), "hidden()")
        return _take(p, n.value, width=1, dtype=np.int64).reshape(-1)

    # ---- cell handles and files (issue 42) -------------------------------------
    def locate_many(self, points):
        """Cell ids (int64) of cells whose closures hold the rows of points
        (dd_locate_many); raises on a NaN or infinite row."""
        a = _points(points)
        out = np.empty(len(a), dtype=np.int64)
        self._check(lib.dd_locate_many(self._h, _dptr(a), len(a),
                                       out.ctypes.data_as(ctypes.POINTER(c_int64))), "locate_many")
        return out

    def nearest_many(self, points):
        """Input indices (int64) of vertices nearest to the rows of points
        (dd_nearest_many)."""
        a = _points(points)
        out = np.empty(len(a), dtype=np.uint32)
        self._check(lib.dd_nearest_many(self._h, _dptr(a), len(a),
                                        out.ctypes.data_as(ctypes.POINTER(c_uint32))), "nearest_many")
        return out.astype(np.int64)

    def input_points(self, with_weights=False):
        """Every input index's point, an (num_input, 3) array, NaN rows for
        indices that name no point now; with_weights: also the (num_input,)
        weights (dd_points)."""
        n = lib.dd_num_input(self._h)
        xyz, w = np.empty((n, 3)), np.empty(n)
        self._check(lib.dd_points(self._h, _dptr(xyz), _dptr(w)), "input_points()")
        return (xyz, w) if with_weights else xyz

    def cells_vertices(self, ids):
        """The vertices of cell ids, an (n, 4) int32 array (-1 infinite;
        dd_cells_vertices)."""
        c = np.ascontiguousarray(ids, dtype=np.int64).reshape(-1)
        out = np.empty((len(c), 4), dtype=np.int32)
        self._check(lib.dd_cells_vertices(self._h, c.ctypes.data_as(ctypes.POINTER(c_int64)), len(c),
                                          out.ctypes.data_as(ctypes.POINTER(c_int32))), "cells_vertices")
        return out

    def cell_end(self):
        """Live cell ids lie in [0, cell_end()) (dd_cell_end)."""
        return int(_need("dd_cell_end")(self._h))

    def cell_alive(self, c):
        return bool(_need("dd_cell_alive")(self._h, int(c)))

    def cell(self, c):
        """(verts, nbrs) of cell id c: 4 vertices (-1 infinite) and the 4
        cell ids across the facets opposite them (dd_cell)."""
        v, nb = (c_int32 * 4)(), (c_int64 * 4)()
        self._check(_need("dd_cell")(self._h, int(c), v, nb), "cell(%d)" % c)
        return tuple(v), tuple(nb)

    def locate_from(self, p, hint=-1):
        """The id of a cell whose closure holds p, walked from hint (dd_locate_from)."""
        a = _point(p)
        c = c_int64()
        self._check(_need("dd_locate_from")(self._h, _dptr(a), int(hint), byref(c)),
                    "locate_from(%s, hint=%d)" % (a.tolist(), hint))
        return int(c.value)

    def created_cells(self):
        """The ids of the live cells the last edit made (dd_created_cells)."""
        p, n = ctypes.POINTER(c_int64)(), c_size_t()
        self._check(_need("dd_created_cells")(self._h, byref(p), byref(n)), "created_cells()")
        if n.value == 0:
            return np.zeros(0, dtype=np.int64)
        return np.ctypeslib.as_array(p, shape=(n.value,)).copy()

    def write(self, path, ascii=False):
        """Writes the finite cells to a .vtu or .mesh file (dd_write); a .vtu
        is binary, or ASCII with ascii=True or a name ending .ascii.vtu
        (dd_write_ex, DD_WRITE_ASCII)."""
        if not ascii:
            self._check(_need("dd_write")(self._h, str(path).encode()), "write(%r)" % str(path))
        else:
            self._check(_need("dd_write_ex")(self._h, str(path).encode(), WRITE_ASCII),
                        "write(%r, ascii=True)" % str(path))


STABLE_INDICES = 1   # DD_STABLE_INDICES
DISCARD_HIDDEN = 2   # DD_DISCARD_HIDDEN
WRITE_ASCII = 1      # DD_WRITE_ASCII
