"""
pybench.py -- the Python package against scipy.spatial.Delaunay, in one
run (make bench: results/python.txt; the README's Python table).

    PYTHONPATH=python /usr/bin/python3 scripts/pybench.py [full|quick|tiny]

Lines, each one figure pair of the same run:
  python: WHAT: dtdel S s, scipy S s (Rx)
  python overhead: CALL on N points: whole call S ms, C call S ms (Rx)
  python threads: two constructions of N points: one after the other S s,
      in two threads S s (Rx)
Uniform points in the unit cube.  Our construction rows follow one
untimed build (the first in a process pays for fresh memory); the
threads line alternates its two ways twice.  Where scipy takes minutes (find_simplex
of 10^6 queries) it is timed on a sample and the line says so.
"""
import sys
import threading
import time

import numpy as np
import scipy
import scipy.spatial

import dtdel

SIZES = {  # n (build, find_simplex, remove), n2 (insert base, smoothing), inserts, scipy's find_simplex sample
    "full": (1000000, 100000, 10000, 10000),
    "quick": (100000, 20000, 2000, 5000),
    "tiny": (5000, 2000, 200, 1000),
}


def num(n):
    """n with a space between groups of three digits, as the README's tables."""
    return "{:,}".format(n).replace(",", " ")


def timed(fn):
    t0 = time.perf_counter()
    r = fn()
    return time.perf_counter() - t0, r


def line(what, ours, theirs, note=""):
    print("python: %s: dtdel %.4f s, scipy %.4f s (%.1fx)%s" % (what, ours, theirs, theirs / ours, note))
    sys.stdout.flush()


def against_scipy(rng, n, n2, k, sample):
    p = rng.random((n, 3))
    _build(rng.random((n, 3))).close()      # untimed: the first build of a process pays for its memory
    ours, tri = timed(lambda: _build(p))
    theirs, ref = timed(lambda: _build_scipy(p))
    line("build %s uniform points and read simplices" % num(n), ours, theirs)
    q = rng.random((n, 3))
    ours, _ = timed(lambda: tri.find_simplex(q))
    qs = q[:sample]
    theirs, _ = timed(lambda: ref.find_simplex(qs))
    line("find_simplex of %s queries in %s points" % (num(n), num(n)), ours, theirs * n / len(qs),
         "; scipy timed on %d of them, scaled" % len(qs))
    del ref
    ids = rng.permutation(n)[:n // 10]
    keep = np.setdiff1d(np.arange(n), ids)
    ours, _ = timed(lambda: tri.remove(ids))
    theirs, _ = timed(lambda: _build_scipy(p[keep]))
    line("remove 10%% of %s (scipy rebuilds from the rest)" % num(n), ours, theirs)
    tri.close()
    base, new = rng.random((n2, 3)), rng.random((k, 3))
    tri = dtdel.Delaunay(base)
    ref = scipy.spatial.Delaunay(base, incremental=True)
    ours, _ = timed(lambda: tri.insert(new))
    theirs, _ = timed(lambda: ref.add_points(new))
    line("insert %s into %s (scipy's add_points)" % (num(k), num(n2)), ours, theirs)
    ref.close()
    tri.close()
    tri = dtdel.Delaunay(base)
    step = 0.05 * n2 ** (-1.0 / 3)
    moved = base + rng.uniform(-step, step, size=base.shape)
    ours, _ = timed(lambda: (tri.move(np.arange(n2), moved), tri.simplices))
    theirs, _ = timed(lambda: _build_scipy(moved))
    line("smoothing, every vertex of %s moved by 5%% of the spacing, simplices read "
         "(scipy rebuilds)" % num(n2), ours, theirs)


def _build(p):
    tri = dtdel.Delaunay(p)
    tri.simplices
    return tri


def _build_scipy(p):
    ref = scipy.spatial.Delaunay(p)
    ref.simplices
    return ref


def overhead(rng, n):
    """Each array call's whole time from Python against its C call's own
    (Triangulation.last_c_seconds, timed inside the extension), the
    median of 5 runs each."""
    p = rng.random((n, 3))
    q = rng.random((n, 3))
    t = dtdel.Triangulation(p)
    ids = np.arange(0, n, 10)
    calls = [
        ("Triangulation(points)", lambda: dtdel.Triangulation(p), None),
        ("locate_many", lambda: t.locate_many(q), t),
        ("nearest_many", lambda: t.nearest_many(q), t),
        ("input_points", lambda: t.input_points(), t),
        ("delete_set + insert_many of 10%", None, t),
    ]
    for name, fn, obj in calls:
        whole, c = [], []
        for _ in range(5):
            if name.startswith("delete_set"):
                pts = t.input_points()[ids]
                w0, _ = timed(lambda: t.delete_set(ids))
                c0 = t.last_c_seconds
                w1, _ = timed(lambda: t.insert_many(pts))
                whole.append(w0 + w1)
                c.append(c0 + t.last_c_seconds)
                continue
            w, r = timed(fn)
            whole.append(w)
            c.append((obj or r).last_c_seconds)
        w, cc = float(np.median(whole)), float(np.median(c))
        print("python overhead: %s on %d points: whole call %.3f ms, C call %.3f ms (%.3fx)"
              % (name, n, 1e3 * w, 1e3 * cc, w / cc))
    sys.stdout.flush()


def threads(rng, n):
    """One after the other against two threads, alternated twice (A B A B)
    after an untimed build, the medians of each; the first build of a
    process pays for memory the others reuse."""
    a, b = rng.random((n, 3)), rng.random((n, 3))
    dtdel.Triangulation(a).close()
    out = [None, None]

    def build(k, p):
        out[k] = dtdel.Triangulation(p)

    def both():
        ths = [threading.Thread(target=build, args=(k, p)) for k, p in ((0, a), (1, b))]
        for th in ths:
            th.start()
        for th in ths:
            th.join()

    seqs, pars = [], []
    for _ in range(2):
        seqs.append(timed(lambda: (dtdel.Triangulation(a).close(), dtdel.Triangulation(b).close()))[0])
        pars.append(timed(both)[0])
        out[0].close(), out[1].close()
    seq, par = float(np.median(seqs)), float(np.median(pars))
    print("python threads: two constructions of %d points: one after the other %.3f s, in two threads "
          "%.3f s (%.2fx)" % (n, seq, par, seq / par))


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else "full"
    n, n2, k, sample = SIZES[mode]
    rng = np.random.default_rng(2026)
    print("python: dtdel %s, scipy %s, numpy %s" % (dtdel.__version__, scipy.__version__, np.__version__))
    against_scipy(rng, n, n2, k, sample)
    overhead(rng, n2 if mode != "full" else 100000)
    threads(rng, n)


if __name__ == "__main__":
    main()
