"""
_scipy.py -- dtdel.Delaunay: scipy.spatial.Delaunay's shape on the exact
engine, for 3D input, with the edits, weights and threads scipy lacks.

Owns: scipy's names, shapes and dtypes, built from the compiled core's
whole-array calls (_core.Triangulation), and their caches, recomputed
lazily after an edit.  No geometry is computed here but scipy's
barycentric `transform`, which is numpy's inverse of each simplex's
matrix, as scipy's is.
"""
import numpy as np

from ._core import DtdelError, Triangulation

_ERR_ARG, _ERR_UNSUPPORTED = 14, 15


def _frozen(a):
    a.flags.writeable = False
    return a


def _queries(xi, call):
    """xi as an (m, 3) float64 array and the leading shape to give back."""
    a = np.asarray(xi)
    if a.dtype.kind not in "biuf":
        raise DtdelError(_ERR_ARG, "%s: coordinates must be real numbers, got dtype %s" % (call, a.dtype))
    if a.ndim == 0 or a.shape[-1] != 3:
        raise DtdelError(_ERR_ARG, "%s: the last axis must have length 3 (3D points), got shape %s"
                         % (call, a.shape))
    return np.ascontiguousarray(a.reshape(-1, 3), dtype=np.float64), a.shape[:-1]


class Delaunay:
    """Delaunay(points, furthest_site=False, incremental=False,
    qhull_options=None, *, weights=None, discard_hidden=False, threads=None)

    The Delaunay triangulation of 3D points, a drop-in for
    ``scipy.spatial.Delaunay`` on 3D input: the same attribute names,
    shapes and dtypes, from an exact engine whose result is CGAL's
    simplex for simplex, degenerate input included (no joggling, no
    tolerance, no flat simplices).  Beyond scipy it edits in place
    (`remove`, `insert`, `move`), takes weights (the regular
    triangulation, with `hidden` points), and releases the GIL in every
    array call.

    Parameters
    ----------
    points : (npoints, 3) array_like
        Coordinates, any real dtype (converted to float64).  NaN or an
        infinite coordinate raises DtdelError naming its row.
    furthest_site, qhull_options
        scipy's; only the defaults are accepted (DtdelError otherwise).
    incremental : bool
        Accepted for scipy's sake: every Delaunay can be edited.
    weights : (npoints,) array_like, optional
        Gives the regular (weighted Delaunay) triangulation, as CGAL's
        ``Regular_triangulation_3``.
    discard_hidden : bool
        Weighted only: forget hidden points instead of keeping them.
    threads : int, optional
        Build (and answer find_simplex's arrays) on that many threads,
        0 for every core; None: 1, or the DTDEL_THREADS variable.  The
        result is the same on any count.

    Attributes
    ----------
    points : (npoints, 3) float64
        The point of every input index; a row of NaN for an index that
        names no point now (a removed vertex, a forgotten hidden point).
    simplices : (nsimplex, 4) intc
        The finite cells, positively oriented.
    neighbors : (nsimplex, 4) intc
        ``neighbors[i, k]`` is the simplex opposite vertex k of simplex
        i, -1 across the hull.
    vertex_to_simplex : (npoints,) intc
        A simplex of each vertex, -1 for an input index that is no vertex.
    vertex_neighbor_vertices : tuple (indptr, indices) of intc
        The neighbours of vertex k are ``indices[indptr[k]:indptr[k+1]]``.
    convex_hull : (nfacets, 3) intc
        The hull's triangles, ordered so that the right-hand normal
        points outwards.
    coplanar : (ncoplanar, 3) intc
        Input indices that are no vertices: ``[point, simplex, nearest
        vertex]``; duplicates (their vertex as nearest) and kept hidden
        points (nearest in power distance).
    transform : (nsimplex, 4, 3) float64
        scipy's barycentric transform.
    nsimplex, npoints, ndim : int
    weights : (npoints,) float64 or None
    hidden : (nhidden,) int64
        Input indices of the kept hidden points (weighted).

    Every array describes the triangulation as it is now: after an edit
    the next access recomputes it.  An array handed out is a read-only
    snapshot, which an edit does not change.

    Notes
    -----
    Not in this class, unlike scipy's: ``furthest_site=True``,
    ``qhull_options``, ``equations``, ``paraboloid_scale`` and
    ``paraboloid_shift``, ``plane_distance`` and ``lift_points`` (the
    paraboloid lifting is qhull's), ``vertices`` (scipy's deprecated
    alias), ``find_simplex``'s ``tol`` (the test is exact, no tolerance
    is needed) and input of other dimensions than 3.

    Examples
    --------
    >>> import numpy as np, dtdel
    >>> pts = np.random.default_rng(0).random((1000, 3))
    >>> tri = dtdel.Delaunay(pts)               # was scipy.spatial.Delaunay(pts)
    >>> tri.simplices.shape[1], tri.find_simplex([[2.0, 2.0, 2.0]])[0]
    (4, -1)
    >>> tri.remove([3, 4, 5]); new = tri.insert([[0.5, 0.5, 0.5]])
    >>> tri.check()
    """

    ndim = 3
    furthest_site = False

    def __init__(self, points, furthest_site=False, incremental=False, qhull_options=None, *,
                 weights=None, discard_hidden=False, threads=None):
        if furthest_site:
            raise DtdelError(_ERR_UNSUPPORTED, "Delaunay: furthest_site=True is not supported")
        if qhull_options is not None:
            raise DtdelError(_ERR_UNSUPPORTED, "Delaunay: qhull_options are qhull's; this engine is "
                             "exact and takes none (got %r)" % (qhull_options,))
        a = np.asarray(points)
        if a.ndim != 2 or a.shape[1] != 3:
            raise DtdelError(_ERR_ARG, "Delaunay: points must be an (npoints, 3) array (3D only), got "
                             "shape %s" % (a.shape,))
        self._tri = Triangulation(a, weights=weights, discard_hidden=discard_hidden, threads=threads)
        self._cache = {}
        self._at = -1

    # ---- the underlying triangulation, lifetime --------------------------------
    @property
    def triangulation(self):
        """The dtdel.Triangulation underneath, for every other call
        (degree, canonical_hash, cell handles, ...)."""
        return self._tri

    def close(self):
        """Frees the triangulation now; later calls raise ValueError."""
        self._tri.close()
        self._cache = {}

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        if self._tri.closed:
            return "<dtdel.Delaunay (closed)>"
        return "<dtdel.Delaunay: %d points, %d simplices>" % (self.npoints, self.nsimplex)

    def _get(self, name, make):
        """The cached array `name`, remade by make() after an edit."""
        if self._at != self._tri.edits:
            self._cache = {}
            self._at = self._tri.edits
        if name not in self._cache:
            self._cache.update(make())
        return self._cache[name]

    def _simplices(self):
        s, c2s = self._tri._simplices()
        return {"simplices": _frozen(s), "_c2s": c2s}

    # ---- scipy's attributes ---------------------------------------------------------
    @property
    def points(self):
        return self._get("points", lambda: {"points": _frozen(self._tri.input_points())})

    @property
    def simplices(self):
        return self._get("simplices", self._simplices)

    @property
    def neighbors(self):
        c2s = self._get("_c2s", self._simplices)
        return self._get("neighbors", lambda: {"neighbors": _frozen(self._tri._neighbors(c2s))})

    @property
    def vertex_to_simplex(self):
        def make():
            s = self.simplices
            v2s = np.full(self.npoints, -1, dtype=np.intc)
            v2s[s.ravel()] = np.repeat(np.arange(len(s), dtype=np.intc), 4)
            return {"vertex_to_simplex": _frozen(v2s)}
        return self._get("vertex_to_simplex", make)

    @property
    def convex_hull(self):
        return self._get("convex_hull", lambda: {"convex_hull": _frozen(self._tri._hull())})

    @property
    def vertex_neighbor_vertices(self):
        def make():
            ip, ix = self._tri._vertex_neighbor_vertices()
            return {"vertex_neighbor_vertices": (_frozen(ip), _frozen(ix))}
        return self._get("vertex_neighbor_vertices", make)

    @property
    def nsimplex(self):
        return self._tri.num_finite_tets

    @property
    def npoints(self):
        return self._tri.num_input

    @property
    def weights(self):
        """The weight of every input index (NaN where no point), or None
        for an unweighted triangulation."""
        if not self._tri.is_weighted:
            return None
        return self._get("weights", lambda: {"weights": _frozen(self._tri.input_points(True)[1])})

    @property
    def hidden(self):
        return self._get("hidden", lambda: {"hidden": _frozen(self._tri.hidden())})

    @property
    def coplanar(self):
        def make():
            t = self._tri
            alias = t._aliases()
            idx = np.arange(len(alias), dtype=np.int64)
            dup = np.flatnonzero((alias != idx) & (alias >= 0))
            dup = dup[self.vertex_to_simplex[alias[dup]] >= 0]
            hid = t.hidden()
            rows = np.empty((len(dup) + len(hid), 3), dtype=np.intc)
            rows[:len(dup), 0] = dup
            rows[:len(dup), 1] = self.vertex_to_simplex[alias[dup]]
            rows[:len(dup), 2] = alias[dup]
            if len(hid):
                xyz = self.points[hid]
                rows[len(dup):, 0] = hid
                rows[len(dup):, 1] = self._get("_c2s", self._simplices)[t.locate_many(xyz)]
                rows[len(dup):, 2] = t.nearest_many(xyz)
            rows = rows[np.argsort(rows[:, 0], kind="stable")]
            return {"coplanar": _frozen(rows)}
        return self._get("coplanar", make)

    @property
    def transform(self):
        def make():
            x = self.points[self.simplices]               # (nsimplex, 4, 3)
            out = np.empty((len(x), 4, 3))
            out[:, 3, :] = x[:, 3, :]
            if len(x):
                out[:, :3, :] = np.linalg.inv(np.transpose(x[:, :3, :] - x[:, 3:4, :], (0, 2, 1)))
            return {"transform": _frozen(out)}
        return self._get("transform", make)

    def find_simplex(self, xi, bruteforce=False, tol=None):
        """The simplex holding each point, as scipy's find_simplex.

        Parameters
        ----------
        xi : (..., 3) array_like
            Query points, any leading shape.
        bruteforce : bool
            Accepted for scipy's sake; no effect (the walk is exact).
        tol : None
            Must be None: the test is exact, a point on a face, edge or
            vertex gets one of the simplices that hold it.

        Returns
        -------
        (...) ndarray of intc
            Indices into `simplices`, -1 exactly where the point is
            outside the convex hull.  O(m log m) for the order of the
            queries, then a short walk each.

        Raises
        ------
        DtdelError
            DD_ERR_NAN / DD_ERR_INFINITE naming the first bad point;
            DD_ERR_ARG for another last axis than 3; DD_ERR_UNSUPPORTED
            for a tol.

        Examples
        --------
        >>> import numpy as np, dtdel
        >>> tri = dtdel.Delaunay(np.random.default_rng(0).random((100, 3)))
        >>> tri.find_simplex([[5.0, 5.0, 5.0]]).tolist()
        [-1]
        """
        if tol is not None:
            raise DtdelError(_ERR_UNSUPPORTED, "find_simplex: the test is exact; tol is not supported "
                             "(got %r)" % (tol,))
        q, shape = _queries(xi, "find_simplex")
        c2s = self._get("_c2s", self._simplices)
        return c2s[self._tri.locate_many(q)].astype(np.intc, copy=False).reshape(shape)

    # ---- what scipy cannot do -------------------------------------------------------
    def locate(self, xi):
        """Cell ids of cells holding the points of xi.

        Parameters
        ----------
        xi : (..., 3) array_like

        Returns
        -------
        (...) ndarray of int64
            The Triangulation's cell ids (`triangulation.cell(c)`), an
            infinite cell's id for a point outside the hull; they stay
            valid across edits that do not touch the cell.
            `find_simplex` gives indices into `simplices` instead.
        """
        q, shape = _queries(xi, "locate")
        return self._tri.locate_many(q).reshape(shape)

    def nearest_vertex(self, xi):
        """A nearest vertex of each point, exact.

        Parameters
        ----------
        xi : (..., 3) array_like

        Returns
        -------
        (...) ndarray of int64
            Input indices; on a weighted triangulation the least power
            distance |p - x|^2 - w(x) decides.

        Examples
        --------
        >>> import dtdel
        >>> tri = dtdel.Delaunay([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
        >>> tri.nearest_vertex([[0.9, 0.1, 0.0]]).tolist()
        [1]
        """
        q, shape = _queries(xi, "nearest_vertex")
        return self._tri.nearest_many(q).reshape(shape)

    def remove(self, ids):
        """Removes vertices, all or nothing.

        Parameters
        ----------
        ids : array_like of int
            Input indices of vertices now.  The result is the
            triangulation of the other points, CGAL's.

        Raises
        ------
        DtdelError
            DD_ERR_UNKNOWN_VERTEX naming an id that is no vertex;
            DD_ERR_DIMENSION if fewer than 4 or only coplanar points
            would be left; DD_ERR_ARG for ids that are not integers.
            Nothing changes.
        """
        self._tri.delete_set(ids)

    def insert(self, points, weights=None):
        """Inserts points, all or nothing.

        Parameters
        ----------
        points : (m, 3) array_like
        weights : (m,) array_like, optional
            On a weighted triangulation (weight 0 when omitted).

        Returns
        -------
        (m,) ndarray of int64
            Each point's input index; a point equal to a vertex, or to an
            earlier point of the batch, gets that one's.

        Raises
        ------
        DtdelError
            DD_ERR_NAN / DD_ERR_INFINITE naming the row; DD_ERR_UNSUPPORTED
            for weights on an unweighted triangulation.  Nothing changes.

        Examples
        --------
        >>> import numpy as np, dtdel
        >>> tri = dtdel.Delaunay(np.random.default_rng(0).random((100, 3)))
        >>> tri.insert([[0.5, 0.5, 0.5]]).tolist()
        [100]
        """
        q, _ = _queries(points, "insert")
        return self._tri.insert_many(q, weights)[0]

    def add_points(self, points, restart=False):
        """scipy's incremental call: insert(points), indices dropped.
        restart=True rebuilds from all points, as scipy's does."""
        if restart:
            pts = np.concatenate([self.points[~np.isnan(self.points[:, 0])],
                                  np.asarray(points, dtype=np.float64).reshape(-1, 3)])
            self.__init__(pts)
            return
        self.insert(points)

    def move(self, ids, points, weights=None):
        """Moves vertices, each keeping its index, all or nothing.

        Parameters
        ----------
        ids : array_like of int
            Input indices of vertices, each at most once.
        points : (m, 3) array_like
            Their new positions, distinct from each other and from every
            vertex not moved.
        weights : (m,) array_like, optional
            New weights (weighted only; omitted: each keeps its own).

        Raises
        ------
        DtdelError
            DD_ERR_DUPLICATE naming the pair that would coincide,
            DD_ERR_ARG for an id listed twice or mismatched lengths,
            DD_ERR_UNKNOWN_VERTEX, DD_ERR_NAN.  Nothing changes.
        """
        q, _ = _queries(points, "move")
        self._tri.move_many(ids, q, weights)

    def check(self):
        """Validates the triangulation (orientation, adjacency, the
        perturbed empty-sphere test); DtdelError naming a fault."""
        self._tri.check()

    def canonical(self):
        """The canonical form, CGAL's too: (m, 4) int32, rows sorted."""
        return self._tri.canonical()

    def write(self, path, ascii=False):
        """Writes the finite cells to a .vtu (binary; ascii=True for
        ASCII) or .mesh file."""
        self._tri.write(path, ascii=ascii)

    def to_meshio(self):
        """A meshio.Mesh of the vertices and the finite cells ("tetra"),
        with point data "input_index"."""
        import meshio
        verts = self._tri.vertices()
        new = np.full(self.npoints, -1, dtype=np.int64)
        new[verts] = np.arange(len(verts))
        return meshio.Mesh(self.points[verts], [("tetra", new[self.simplices])],
                           point_data={"input_index": verts})
