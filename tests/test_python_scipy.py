"""
test_python_scipy.py -- dtdel.Delaunay, the scipy.spatial.Delaunay drop-in
(issue 57): equal to scipy on generic data, equal to CGAL where scipy's
qhull is not exact (grids, cospherical points, duplicates), every method
against the C library, bad inputs refused with nothing changed, and
threads.

    PYTHONPATH=python:tests /usr/bin/python3 tests/test_python_scipy.py build/dtdel
"""
import threading
import time
from fractions import Fraction

import numpy as np
import scipy.spatial

import dtdel
import test_python as tp
from test_python import cgal_canonical, cgal_weighted, check, raises, sort_rows


def row_set(a):
    return set(map(tuple, np.sort(np.asarray(a), axis=1).tolist()))


def orient(a, b, c, d):
    """The exact sign of (b - a) x (c - a) . (d - a) on the doubles."""
    a, b, c, d = ([Fraction(float(x)) for x in p] for p in (a, b, c, d))
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def holds(x, tet, q):
    """The closed tetrahedron x[tet] holds q, exactly."""
    p = x[tet]
    for k in range(4):
        r = list(p)
        r[k] = q
        if orient(*r) < 0:
            return False
    return True


def outside(x, hull, q):
    """q lies strictly beyond the plane of some hull facet, exactly."""
    return any(orient(x[f[0]], x[f[1]], x[f[2]], q) > 0 for f in hull)


def test_against_scipy():
    rng = np.random.default_rng(21)
    pts = rng.random((3000, 3))
    tri, ref = dtdel.Delaunay(pts), scipy.spatial.Delaunay(pts)
    check("simplices as scipy's (sets of sorted rows)", row_set(tri.simplices) == row_set(ref.simplices),
          "%d vs %d" % (tri.nsimplex, ref.nsimplex))
    check("dtypes and shapes", tri.simplices.dtype == np.intc and tri.neighbors.dtype == np.intc
          and tri.simplices.shape == (tri.nsimplex, 4) == tri.neighbors.shape
          and tri.points.shape == (3000, 3) and tri.npoints == 3000 and tri.ndim == 3
          and tri.vertex_to_simplex.shape == (3000,) and tri.transform.shape == (tri.nsimplex, 4, 3), "")
    check("points as given", np.array_equal(tri.points, pts), "")
    x = tri.points[tri.simplices]
    vol = np.einsum("ij,ij->i", np.cross(x[:, 1] - x[:, 0], x[:, 2] - x[:, 0]), x[:, 3] - x[:, 0])
    check("simplices positively oriented", (vol > 0).all(), "")
    S, N = tri.simplices, tri.neighbors
    ok = True
    for i in range(tri.nsimplex):
        for k in range(4):
            j = N[i, k]
            if j < 0:
                continue
            shared = set(S[i]) & set(S[j])
            ok &= len(shared) == 3 and S[i, k] not in shared and i in N[j]
    check("neighbors: across the facet opposite vertex k", ok, "")
    hull_from_n = {tuple(sorted(np.delete(S[i], k))) for i, k in zip(*np.nonzero(N < 0))}
    check("neighbors -1 exactly on the hull, convex_hull as scipy's",
          hull_from_n == row_set(tri.convex_hull) == row_set(ref.convex_hull), "")
    c = pts.mean(axis=0)
    h = tri.points[tri.convex_hull]
    check("convex_hull oriented outwards",
          (np.einsum("ij,ij->i", np.cross(h[:, 1] - h[:, 0], h[:, 2] - h[:, 0]), h[:, 0] - c) > 0).all(), "")
    v2s = tri.vertex_to_simplex
    check("vertex_to_simplex", all(v in S[v2s[v]] for v in range(3000)), "")
    ip, ix = tri.vertex_neighbor_vertices
    rp, rx = ref.vertex_neighbor_vertices
    check("vertex_neighbor_vertices as scipy's",
          all(set(ix[ip[v]:ip[v + 1]]) == set(rx[rp[v]:rp[v + 1]]) for v in range(3000)), "")
    q = rng.random((4000, 3)) * 1.4 - 0.2
    f, g = tri.find_simplex(q), ref.find_simplex(q)
    check("find_simplex -1 where scipy's is", np.array_equal(f < 0, g < 0), "%d vs %d" % ((f < 0).sum(), (g < 0).sum()))
    inside = np.flatnonzero(f >= 0)[:300]
    out = np.flatnonzero(f < 0)[:100]
    check("find_simplex: the simplex holds the point (exact)",
          all(holds(tri.points, S[f[i]], q[i]) for i in inside), "")
    check("find_simplex: -1 only outside the hull (exact)",
          all(outside(tri.points, tri.convex_hull, q[i]) for i in out), "")
    check("find_simplex keeps the leading shape",
          tri.find_simplex(q[:24].reshape(2, 3, 4, 3)).shape == (2, 3, 4)
          and tri.find_simplex(q[0]).shape == () and tri.find_simplex(q[:24]).dtype == np.intc, "")
    T = tri.transform[f[inside]]
    b = np.einsum("nij,nj->ni", T[:, :3, :], q[inside] - T[:, 3, :])
    rebuilt = np.einsum("ni,nij->nj", np.c_[b, 1 - b.sum(axis=1)], tri.points[S[f[inside]]])
    check("transform: scipy's barycentric coordinates", np.allclose(rebuilt, q[inside])
          and (np.c_[b, 1 - b.sum(axis=1)] > -1e-9).all(), "")
    check("coplanar empty on distinct points", tri.coplanar.shape == (0, 3), str(tri.coplanar.shape))
    check("simplices are the C library's finite cells",
          row_set(tri.simplices) == row_set(tri.triangulation.canonical()[(tri.triangulation.canonical() >= 0).all(axis=1)]), "")
    check("simplices are a read-only snapshot", not tri.simplices.flags.writeable, "")


def test_degenerate():
    """Grids, cospherical points and duplicates: equal to CGAL; where scipy
    differs is printed (#: lines), not asserted."""
    g = np.array([(i, j, k) for i in range(10) for j in range(10) for k in range(10)], dtype=float)
    rng = np.random.default_rng(4)
    g = g[rng.permutation(len(g))]
    u = rng.normal(size=(400, 3))
    sphere = u / np.linalg.norm(u, axis=1)[:, None]
    sphere = np.vstack([np.round(sphere * 4) / 4, [[0, 0, 0]]])        # many cospherical, copies
    cube = np.array([(i, j, k) for i in range(3) for j in range(3) for k in range(3)], dtype=float)
    dup = np.vstack([g[:300], g[:50]])
    for name, pts in (("grid 10^3", g), ("grid 3^3", cube), ("rounded sphere", sphere), ("duplicates", dup)):
        tri = dtdel.Delaunay(pts)
        live = {}
        for i, p in enumerate(pts):
            live.setdefault(tuple(p), i)
        ref = cgal_canonical({i: np.array(p) for p, i in live.items()})
        ours = tri.canonical()
        check(name + ": as CGAL", np.array_equal(ours, ref), "%d vs %d cells" % (len(ours), len(ref)))
        x = tri.points[tri.simplices]
        vol = np.einsum("ij,ij->i", np.cross(x[:, 1] - x[:, 0], x[:, 2] - x[:, 0]), x[:, 3] - x[:, 0])
        check(name + ": no flat simplex", (vol > 0).all(), "")
        ndup = len(pts) - len(live)
        cop = tri.coplanar
        check(name + ": coplanar lists the merged copies", len(cop) == ndup
              and all(tuple(pts[c[0]]) == tuple(pts[c[2]]) and c[2] in tri.simplices[c[1]] for c in cop),
              "%d rows, %d copies" % (len(cop), ndup))
        try:
            s = scipy.spatial.Delaunay(pts)
            xs = pts[s.simplices]
            vs = np.einsum("ij,ij->i", np.cross(xs[:, 1] - xs[:, 0], xs[:, 2] - xs[:, 0]), xs[:, 3] - xs[:, 0])
            print("#: %s: dtdel %d simplices, none flat; scipy %d, %d of zero volume, %d points dropped"
                  % (name, tri.nsimplex, s.nsimplex, int((np.abs(vs) == 0).sum()), len(s.coplanar)))
        except Exception as e:  # noqa: BLE001 - scipy's failure is what we show
            print("#: %s: dtdel %d simplices; scipy raised %s" % (name, tri.nsimplex, type(e).__name__))
        q = pts[:200] + 0.0                       # the input points themselves: on faces, edges, vertices
        f = tri.find_simplex(q)
        check(name + ": find_simplex of the points themselves", (f >= 0).all()
              and all(holds(tri.points, tri.simplices[f[i]], q[i]) for i in range(0, len(q), 7)), "")


def test_edits():
    rng = np.random.default_rng(8)
    pts = rng.random((800, 3))
    tri = dtdel.Delaunay(pts)
    t = dtdel.Triangulation(pts)
    old = tri.simplices
    tri.remove(np.arange(0, 80))
    t.delete_set(list(range(80)))
    live = {i: pts[i] for i in range(80, 800)}
    check("remove: as CGAL", np.array_equal(tri.canonical(), cgal_canonical(live)), "")
    check("remove: the attributes follow", row_set(tri.simplices) == row_set(dtdel.Delaunay(pts[80:]).simplices + 80)
          and np.isnan(tri.points[:80]).all() and (tri.vertex_to_simplex[:80] == -1).all(), "")
    check("an array handed out earlier is a snapshot", row_set(old) == row_set(dtdel.Delaunay(pts).simplices), "")
    new = rng.random((100, 3))
    idx = tri.insert(np.vstack([new, pts[100:102]]))
    for i, p in zip(idx, new):
        live[int(i)] = p
    check("insert: indices, copies get theirs", len(idx) == 102 and list(idx[-2:]) == [100, 101]
          and len(set(idx[:100].tolist())) == 100, str(idx[-2:]))
    check("insert: as CGAL", np.array_equal(tri.canonical(), cgal_canonical(live)), "")
    vs = np.array(sorted(live))[::5]
    moved = np.array([live[v] for v in vs]) + rng.normal(scale=1e-3, size=(len(vs), 3))
    tri.move(vs, moved)
    for v, p in zip(vs, moved):
        live[int(v)] = p
    check("move: as CGAL", np.array_equal(tri.canonical(), cgal_canonical(live)), "")
    check("move: points follow", np.array_equal(tri.points[vs], moved), "")
    tri.check()
    check("check after edits", True)
    q = rng.random((500, 3))
    nv = tri.nearest_vertex(q)
    P = tri.points
    d = np.nansum((P[None, :, :] - q[:, None, :]) ** 2, axis=2)
    d[:, np.isnan(P[:, 0])] = np.inf
    check("nearest_vertex: none strictly nearer", np.allclose(d[np.arange(500), nv], d.min(axis=1), rtol=0, atol=0), "")
    cells = tri.locate(q)
    f = tri.find_simplex(q)
    check("locate gives cell ids, find_simplex their simplices",
          all(sorted(tri.triangulation.cell(c)[0]) == sorted(tri.simplices[s]) if s >= 0
              else -1 in tri.triangulation.cell(c)[0] for c, s in zip(cells[:200], f[:200])), "")
    n0 = tri.triangulation.num_vertices
    tri.add_points(rng.random((10, 3)))
    check("add_points (scipy's incremental call)", tri.triangulation.num_vertices == n0 + 10, "")
    m = tri.to_meshio()
    check("to_meshio", m.cells[0].data.shape == (tri.nsimplex, 4)
          and np.array_equal(m.points[m.cells[0].data], tri.points[tri.simplices]), "")
    tri.close()
    raises("closed", "ValueError", lambda: tri.simplices)


def test_weighted():
    rng = np.random.default_rng(13)
    xyz = rng.random((300, 3))
    w = rng.random(300) * 0.01
    for discard in (False, True):
        tri = dtdel.Delaunay(xyz, weights=w, discard_hidden=discard)
        cells, hidden = cgal_weighted(xyz, w, discard)
        tag = "weighted%s: " % (" discard" if discard else "")
        check(tag + "as CGAL", np.array_equal(tri.canonical(), cells), "")
        if not discard:
            check(tag + "hidden as CGAL", np.array_equal(tri.hidden, hidden), "")
            cop = tri.coplanar
            check(tag + "coplanar lists the hidden points", np.array_equal(cop[:, 0], hidden)
                  and all(holds(tri.points, tri.simplices[c[1]], xyz[c[0]]) for c in cop), "")
        check(tag + "weights", np.array_equal(tri.weights[~np.isnan(tri.weights)],
                                              w[~np.isnan(tri.weights)]), "")
        idx = tri.insert(rng.random((20, 3)), weights=rng.random(20) * 0.01)
        check(tag + "insert with weights", len(idx) == 20, "")
        tri.check()
    check("unweighted: weights None", dtdel.Delaunay(xyz).weights is None, "")


def test_errors():
    rng = np.random.default_rng(2)
    pts = rng.random((200, 3))
    tri = dtdel.Delaunay(pts)
    before = tri.canonical()
    bad = pts.copy()
    bad[17, 2] = np.nan
    raises("NaN point", "DD_ERR_NAN", dtdel.Delaunay, bad)
    try:
        dtdel.Delaunay(bad)
    except dtdel.DtdelError as e:
        check("NaN: the message names the row", "17" in e.message and isinstance(e, ValueError), e.message)
    raises("2D input", "DD_ERR_ARG", dtdel.Delaunay, pts[:, :2])
    raises("string dtype", "DD_ERR_ARG", dtdel.Delaunay, pts.astype(str))
    raises("furthest_site", "DD_ERR_UNSUPPORTED", dtdel.Delaunay, pts, True)
    raises("qhull_options", "DD_ERR_UNSUPPORTED", dtdel.Delaunay, pts, False, False, "QJ")
    raises("find_simplex tol", "DD_ERR_UNSUPPORTED", tri.find_simplex, pts[:3], False, 1e-9)
    raises("find_simplex NaN", "DD_ERR_NAN", tri.find_simplex, bad[15:20])
    raises("find_simplex shape", "DD_ERR_ARG", tri.find_simplex, pts[:, :2])
    raises("remove an unknown id", "DD_ERR_UNKNOWN_VERTEX", tri.remove, [3, 500])
    raises("remove a negative id", "DD_ERR_UNKNOWN_VERTEX", tri.remove, [3, -1])
    raises("remove float ids", "DD_ERR_ARG", tri.remove, [3.0, 4.0])
    raises("insert a NaN", "DD_ERR_NAN", tri.insert, bad[10:20])
    raises("insert weights on an unweighted", "DD_ERR_UNSUPPORTED", tri.insert, pts[:2] + 0.001, [0.0, 0.0])
    raises("move onto another vertex", "DD_ERR_DUPLICATE", tri.move, [1, 2], pts[[5, 2]])
    raises("move twice the same", "DD_ERR_ARG", tri.move, [1, 1], pts[[5, 6]] + 0.001)
    raises("move shapes", "DD_ERR_ARG", tri.move, [1, 2], pts[:3])
    check("nothing changed by the refusals", np.array_equal(tri.canonical(), before), "")


def counter_during(fn):
    """How far a pure-Python counter got while fn ran in another thread:
    large only if fn's C call let go of the GIL."""
    done = threading.Event()
    box = {}

    def run():
        box["r"] = fn()
        done.set()

    th = threading.Thread(target=run)
    n = 0
    th.start()
    while not done.is_set():
        n += 1
    th.join()
    return n, box.get("r")


def test_threads():
    rng = np.random.default_rng(9)
    pts = rng.random((200000, 3))
    n, tri = counter_during(lambda: dtdel.Delaunay(pts))
    check("construction lets go of the GIL", n > 10000, "the counter reached %d" % n)
    q = rng.random((200000, 3))
    n, _ = counter_during(lambda: tri.find_simplex(q))
    check("find_simplex lets go of the GIL", n > 10000, "the counter reached %d" % n)
    want = tri.find_simplex(q[:20000])
    outs = [None] * 4

    def read(k):
        outs[k] = tri.find_simplex(q[:20000])

    ths = [threading.Thread(target=read, args=(k,)) for k in range(4)]
    for th in ths:
        th.start()
    for th in ths:
        th.join()
    check("reads of one triangulation in 4 threads", all(np.array_equal(o, want) for o in outs), "")
    other = dtdel.Delaunay(rng.random((2000, 3)))
    o = other.triangulation
    ids = np.arange(0, 200000, 2)

    def edit():
        tri.remove(ids)
        return True

    counts = []
    n, ok = counter_during(lambda: (edit(), counts.append(o.num_vertices))[0])
    check("an edit holds its own lock, not a global one", ok and n > 10000, "the counter reached %d" % n)
    # an edit and reads of another object interleave
    stop = threading.Event()
    seen = []

    def reader():
        while not stop.is_set():
            seen.append(other.find_simplex(q[:100])[0])

    th = threading.Thread(target=reader)
    th.start()
    t0 = time.perf_counter()
    tri.insert(rng.random((50000, 3)))
    stop.set()
    th.join()
    check("another object's reads go on during an edit", len(seen) > 1,
          "%d reads in %.3f s" % (len(seen), time.perf_counter() - t0))
    tri.check()
    check("after the threaded edits", True)


def test_readme_example():
    """The README's Python example runs as printed."""
    import os
    import re
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    text = open(os.path.join(top, "README.md")).read()
    m = re.search(r"<!-- python-example:begin -->\n```python\n(.*?)```\n<!-- python-example:end -->", text, re.S)
    check("README has the Python example", m is not None, "")
    if m:
        import contextlib
        import io
        env = {}
        with contextlib.redirect_stdout(io.StringIO()):
            exec(compile(m.group(1), "README.md", "exec"), env)
        check("README example: smoothed, edited, checked", env["tri"].nsimplex > 0 and len(env["new"]) == 1000, "")


def test_doctests():
    """The examples in the docstrings run as written."""
    import doctest
    import dtdel._core
    import dtdel._scipy
    for mod in (dtdel._scipy, dtdel._core):
        r = doctest.testmod(mod, optionflags=doctest.ELLIPSIS)
        check("docstring examples of %s" % mod.__name__, r.failed == 0 and r.attempted > 0, str(r))


def main():
    tp.run_groups((test_doctests, test_readme_example, test_against_scipy, test_degenerate, test_edits, test_weighted,
                   test_errors, test_threads))


if __name__ == "__main__":
    main()
