"""
test_python_batch.py -- the Python bindings of the hinted and whole-array
calls (issue 56): insert_from, insert_weighted_from, insert_many, move_many,
locate_many, nearest_many, input_points, cells_vertices; each against CGAL
(through the CLI, as test_python.py) or against the one-point calls.

    PYTHONPATH=python /usr/bin/python3 tests/test_python_batch.py build/dtdel
"""

import numpy as np

import test_python as tp
from test_python import check, raises, same_as_cgal, sort_rows
from dtdel import Triangulation


def test_insert():
    rng = np.random.default_rng(5)
    xyz = rng.random((600, 3))
    with Triangulation(xyz[:300]) as a, Triangulation(xyz[:300]) as b:
        new = np.vstack([xyz[300:], xyz[10:12], xyz[305:306]])   # 2 vertices, 1 batch copy
        idx, merged = a.insert_many(new)
        single = []
        for p in new:
            try:
                single.append(b.insert(p))
            except tp.DtdelError:
                single.append(b.nearest_vertex(p))
        check("insert_many indices as one at a time", np.array_equal(idx, single), "")
        check("insert_many merged", merged == 3 and idx[-3] == 10 and idx[-1] == idx[5], str(merged))
        check("insert_many cells as one at a time", np.array_equal(a.canonical(), b.canonical()), "")
        same_as_cgal("insert_many equals CGAL", a, {i: xyz[i] for i in range(600)})
        c = a.cell_end() - 1
        while not a.cell_alive(c):
            c -= 1
        i = a.insert_from([0.123, 0.456, 0.789], hint=c)
        live = {k: xyz[k] for k in range(600)}
        live[i] = np.array([0.123, 0.456, 0.789])
        same_as_cgal("insert_from equals CGAL", a, live)
        before = a.canonical()
        bad = new.copy()
        bad[7, 1] = np.nan
        raises("insert_many with a NaN", "DD_ERR_NAN", a.insert_many, bad)
        raises("insert_from a dead hint", "DD_ERR_UNKNOWN_CELL", a.insert_from, [0.2] * 3, a.cell_end() + 3)
        check("refused batches change nothing", np.array_equal(a.canonical(), before), "")
        check("an empty batch", a.insert_many(np.zeros((0, 3)))[1] == 0
              and np.array_equal(a.canonical(), before), "")


def test_move_and_reads():
    rng = np.random.default_rng(7)
    xyz = rng.random((500, 3))
    with Triangulation(xyz) as t:
        vs = np.arange(500)
        to = xyz + 0.01 * (rng.random((500, 3)) - 0.5)
        to[[3, 4]] = xyz[[4, 3]]                          # a swap
        t.move_many(vs, to)
        same_as_cgal("move_many equals CGAL", t, {i: to[i] for i in range(500)})
        pts = t.input_points()
        check("input_points", np.array_equal(pts, to), "")
        before = t.canonical()
        raises("move_many of a vertex twice", "DD_ERR_ARG", t.move_many, [1, 1], to[:2])
        raises("move_many onto one point", "DD_ERR_DUPLICATE", t.move_many, [1, 2], [to[5], to[5]])
        check("refused moves change nothing", np.array_equal(t.canonical(), before), "")
        q = 0.2 + 0.6 * rng.random((2000, 3))          # inside the hull: one cell each
        cells = t.locate_many(q)
        ok = all(sorted(t.cell(c)[0]) == sorted(t.locate(p)) for c, p in zip(cells[:200], q[:200]))
        check("locate_many as locate", ok, "")
        near = t.nearest_many(q)
        d = ((to[None, :, :] - q[:200, None, :]) ** 2).sum(axis=2)
        check("nearest_many is nearest", np.allclose(d[np.arange(200), near[:200]], d.min(axis=1)), "")
        made = t.created_cells()
        cv = t.cells_vertices(made)
        check("cells_vertices as cell", np.array_equal(sort_rows(cv), sort_rows([t.cell(c)[0] for c in made])),
              "")
    w = rng.random(400) * 0.001
    with Triangulation(xyz[:400], weights=w) as t:
        idx, _ = t.insert_many(xyz[400:], w[:100] * 0.5)
        check("weighted insert_many", list(idx) == list(range(400, 500)), str(idx[:5]))
        c = t.created_cells()[0]
        i = t.insert_weighted_from([0.5, 0.5, 0.5], 0.0001, hint=c)
        check("insert_weighted_from", i == 500, str(i))
        pts, ws = t.input_points(with_weights=True)
        check("input_points weights", ws[403] == w[3] * 0.5 and ws[500] == 0.0001, "")


def test_threads():
    """threads= (issue 59): the same triangulation on 1, 2, 3 and 8
    threads, CGAL's; the same locate_many / nearest_many answers; the
    threads property and its refusals; Delaunay(threads=)."""
    import dtdel
    import os
    rng = np.random.default_rng(9)
    grid = np.stack(np.meshgrid(*[np.arange(8.0) / 7] * 3), -1).reshape(-1, 3)   # ties: cospherical cells
    xyz = np.vstack([rng.random((30000, 3)) * 0.9 + 0.05, grid])
    q = np.vstack([rng.random((9000, 3)), xyz[::7]])
    with Triangulation(xyz, threads=1) as one:
        check("threads=1", one.threads == 1, str(one.threads))
        same_as_cgal("threads=1 equals CGAL", one, dict(enumerate(xyz)))
        want = sort_rows(one.canonical())
        c1, n1 = one.locate_many(q), one.nearest_many(q)
        for k in (2, 3, 8):
            with Triangulation(xyz, threads=k) as t:
                check("threads=%d build" % k, t.threads == k and np.array_equal(sort_rows(t.canonical()), want)
                      and t.check() is None, "")
                one.threads = k
                check("threads=%d reads" % k, np.array_equal(one.locate_many(q), c1)
                      and np.array_equal(one.nearest_many(q), n1), "")
        one.threads = 0
        check("threads=0 is every core", one.threads == min(os.cpu_count(), 1024), str(one.threads))
        one.threads = 64
        check("threads=64", one.threads == 64, str(one.threads))
        for bad in (-1, 2.5, "2", True):
            raises("threads=%r refused" % (bad,), "DD_ERR_ARG", setattr, one, "threads", bad)
    raises("Triangulation(threads=-1)", "DD_ERR_ARG", Triangulation, xyz[:50], None, False, False, -1)
    d = dtdel.Delaunay(xyz, threads=2)
    check("Delaunay(threads=2)", d.triangulation.threads == 2
          and np.array_equal(sort_rows(d.triangulation.canonical()), want), "")


def main():
    tp.run_groups((test_insert, test_move_and_reads, test_threads))


if __name__ == "__main__":
    main()
