"""
test_python.py -- the Python bindings (python/dtdel) against CGAL and the header.

Run as tests/run.sh does, from the top of the tree after `make python`:
    PYTHONPATH=python /usr/bin/python3 tests/test_python.py build/dtdel
Prints "ok NAME" / "FAIL NAME: why" per assertion (as tests/testlib.h) and
exits 1 on any failure.  CGAL's triangulations come from the CLI's
`cgal-tets FILE` (canonical form of the points of FILE, renumbered 0..k-1:
mapped back to our input indices here).
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import dtdel
from dtdel import DtdelError, Triangulation

CLI = sys.argv[1] if len(sys.argv) > 1 else "build/dtdel"
HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src", "dtdel.h")
failed = 0


def check(name, cond, why=""):
    global failed
    if cond:
        print("ok " + name)
    else:
        failed += 1
        print("FAIL %s: %s" % (name, why))
    sys.stdout.flush()


def raises(name, status, fn, *args):
    """fn(*args) must raise DtdelError with that status and a message (or
    the exception class named by status, such as ValueError)."""
    try:
        fn(*args)
    except DtdelError as e:
        check(name, e.status == status and e.message and isinstance(e, Exception),
              "raised %s (%r), expected %s" % (e.status, e.message, status))
        return
    except Exception as e:  # noqa: BLE001 - any other exception is the failure
        check(name, type(e).__name__ == status, "raised %r, expected %s" % (e, status))
        return
    check(name, False, "no exception, expected %s" % status)


def sort_rows(a):
    a = np.sort(np.asarray(a, dtype=np.int32).reshape(-1, 4), axis=1)
    return a[np.lexsort(a.T[::-1])] if len(a) else a


def cgal_canonical(live):
    """CGAL's canonical form of the points {index: xyz}, in our indices."""
    idx = sorted(live)
    with tempfile.NamedTemporaryFile("w", suffix=".xyz", delete=False) as f:
        for i in idx:
            f.write("%r %r %r\n" % tuple(float(c) for c in live[i]))
        path = f.name
    try:
        out = subprocess.run([CLI, "cgal-tets", path], check=True, capture_output=True,
                             text=True).stdout
    finally:
        os.unlink(path)
    rows = np.array([[int(x) for x in line.split()] for line in out.splitlines() if line.strip()],
                    dtype=np.int64)
    back = np.array(idx + [-1], dtype=np.int64)   # -1 indexes the appended -1
    return sort_rows(back[rows])


def same_as_cgal(name, t, live):
    ours, ref = t.canonical(), cgal_canonical(live)
    check(name, ours.shape == ref.shape and np.array_equal(ours, ref),
          "%d cells, CGAL %d" % (len(ours), len(ref)))


def header_functions():
    # dtdel.h and the types it includes (dtdel/types.h: the status enum)
    text = open(HEADER).read()
    text += open(os.path.join(os.path.dirname(HEADER), "dtdel", "types.h")).read()
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    return sorted(set(re.findall(r"\b(dd_[a-z0-9_]+)\s*\(", text))), text


CORE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python", "dtdel", "_core.pyx")
# dd_ names of dtdel.h that get no Python function of their own, and why.
UNBOUND = {"dd_is_infinite": "a static inline in the header, not in the library; Python tests v < 0"}


def test_bindings():
    """Every call of dtdel.h is declared in _core.pyx's extern block and
    called in it outside that block (or in UNBOUND, with a reason)."""
    names, text = header_functions()
    check("header has calls", len(names) > 30, "%d names" % len(names))
    src = open(CORE).read()
    m = re.search(r'cdef extern from "dtdel.h" nogil:(.*?)\n(?=\S)', src, flags=re.S)
    check("extern block", m is not None, CORE)
    decl, rest = (m.group(1), src[:m.start()] + src[m.end():]) if m else ("", src)
    for n in names:
        if n in UNBOUND:
            continue
        check("bound " + n, re.search(r"\b%s\(" % n, decl) is not None
              and re.search(r"\b%s\(" % n, rest) is not None,
              "not declared in _core.pyx's extern block, or never called there")
    for n in UNBOUND:
        check("unbound %s is in the header" % n, n in names, "stale exclusion")
    meson = open(os.path.join(os.path.dirname(CORE), "..", "meson.build")).read()
    mv = re.search(r"version: '([0-9.]+)'", meson)
    ver = [re.search(r"#define\s+DD_VERSION_%s\s+(\d+)" % k, text) for k in ("MAJOR", "MINOR", "PATCH")]
    if all(ver):
        check("meson.build's version is dtdel.h's", mv is not None
              and mv.group(1) == ".".join(v.group(1) for v in ver), mv.group(0) if mv else "none")
    enum = re.search(r"enum dd_status\s*\{(.*?)\}", text, flags=re.S).group(1)
    in_header = [e for e in re.findall(r"\b(DD_[A-Z_]+)\b", enum) if e != "DD_NUM_STATUS"]
    check("status names as the enum", in_header == dtdel.STATUS_NAMES, str(in_header))
    m = re.search(r"\bDD_STABLE_INDICES\b\s*=?\s*\(?\s*([0-9xXa-fA-F]+)[uU]?\s*(<<\s*(\d+))?", text)
    if m:
        val = int(m.group(1), 0) << int(m.group(3) or 0)
        check("DD_STABLE_INDICES value", val == dtdel.STABLE_INDICES, m.group(0))
    m = re.search(r"\bDD_DISCARD_HIDDEN\b\s*=?\s*\(?\s*([0-9xXa-fA-F]+)[uU]?\s*(<<\s*(\d+))?", text)
    check("DD_DISCARD_HIDDEN in the header", m is not None)
    if m:
        val = int(m.group(1), 0) << int(m.group(3) or 0)
        check("DD_DISCARD_HIDDEN value", val == dtdel.DISCARD_HIDDEN, m.group(0))
    m = re.search(r"\bDD_WRITE_ASCII\b\s*=?\s*\(?\s*([0-9xXa-fA-F]+)[uU]?\s*(<<\s*(\d+))?", text)
    check("DD_WRITE_ASCII in the header", m is not None)
    if m:
        val = int(m.group(1), 0) << int(m.group(3) or 0)
        check("DD_WRITE_ASCII value", val == dtdel.WRITE_ASCII, m.group(0))
    ver = [re.search(r"#define\s+DD_VERSION_%s\s+(\d+)" % k, text) for k in ("MAJOR", "MINOR", "PATCH")]
    if all(ver):
        want = ".".join(m.group(1) for m in ver)
        check("version", dtdel.version() == want, "%r vs %r" % (dtdel.version(), want))


def test_module():
    vs = dtdel.variants()
    check("variants", len(vs) >= 5 and "auto" in vs and len(set(vs)) == len(vs), str(vs))
    d = dtdel.variant_descriptions()
    check("variant descriptions", list(d) == vs and all(d.values()), str(d))
    check("status_name", dtdel.status_name(0) == "ok"
          and dtdel.status_name(9) != dtdel.status_name(10), dtdel.status_name(0))


def test_uniform():
    rng = np.random.default_rng(42)
    xyz = rng.random((300, 3))
    live = {i: xyz[i] for i in range(len(xyz))}
    t = Triangulation(xyz)
    same_as_cgal("uniform build", t, live)
    t.check()
    check("sizes", t.num_input == 300 and t.num_vertices == 300 == len(t)
          and t.num_duplicates == 0 and t.num_tets == len(t.canonical())
          and t.num_finite_tets == int((t.canonical() >= 0).all(axis=1).sum())
          and t.memory_bytes > 0, "")
    check("points", np.array_equal(t.points, xyz) and np.array_equal(t.point(7), xyz[7])
          and np.array_equal(t.vertices(), np.arange(300)), "")
    h = t.canonical_hash()
    check("canonical_hash", h == dtdel.canonical_hash(t.canonical())
          and h == dtdel.canonical_hash(cgal_canonical(live)), hex(h))

    # one deletion per variant, each compared with CGAL's triangulation
    order = rng.permutation(300)
    for k, var in enumerate(dtdel.variants()):
        v = int(order[k])
        t.delete(v, variant=var)
        del live[v]
        same_as_cgal("delete with %s" % var, t, live)
    t.delete(int(order[20]))
    del live[int(order[20])]
    same_as_cgal("delete default", t, live)
    check("hash changes", t.canonical_hash() != h, "")

    # put back, then a set
    v = int(order[20])
    t.reinsert(v)
    live[v] = xyz[v]
    same_as_cgal("reinsert", t, live)
    s = [int(x) for x in order[30:80]]
    t.delete_set(s)
    for x in s:
        del live[x]
    same_as_cgal("delete_set", t, live)
    s = [int(x) for x in order[80:90]]
    t.delete_set(s, variant="grr-hashing")
    for x in s:
        del live[x]
    same_as_cgal("delete_set with a variant", t, live)

    p = np.array([0.25, 0.5, 0.75])
    i = t.insert(p)
    check("insert index", not any(i == j for j in live) and np.array_equal(t.point(i), p), str(i))
    live[i] = p
    same_as_cgal("insert", t, live)
    v = int(order[100])
    q = np.array([0.1, 0.9, 0.3])
    t.move(v, q)
    live[v] = q
    same_as_cgal("move", t, live)
    t.check()
    check("check after edits", True)
    test_queries(t, live, "edited: ")
    t.close()
    try:
        t.num_vertices
        check("closed raises", False, "no exception")
    except ValueError:
        check("closed raises", True)


def test_queries(t, live, tag):
    can = t.canonical()
    verts, nbrs = t.cells()
    check(tag + "cells are the canonical cells", np.array_equal(sort_rows(verts), can), "")
    sym = all(c in nbrs[nbrs[c, i]] for c in range(len(nbrs)) for i in range(4))
    shared = all(len(set(verts[c]) & set(verts[nbrs[c, i]])) == 3
                 for c in range(len(nbrs)) for i in range(4))
    check(tag + "cells' neighbours", sym and shared and verts.dtype == np.int32
          and nbrs.dtype == np.int32, "")

    finite = np.flatnonzero((verts >= 0).all(axis=1))
    ok_loc = ok_near = True
    idx = np.array(sorted(live))
    pts = np.array([live[i] for i in idx])
    for c in finite[:40]:
        centre = pts[np.searchsorted(idx, verts[c])].mean(axis=0)
        ok_loc &= sorted(t.locate(centre)) == sorted(verts[c].tolist())
        near = int(idx[np.argmin(((pts - centre) ** 2).sum(axis=1))])
        ok_near &= t.nearest_vertex(centre) == near
    check(tag + "locate a cell's centroid", ok_loc, "")
    check(tag + "nearest_vertex", ok_near, "")
    out = t.locate([5.0, 5.0, 5.0])
    check(tag + "locate outside the hull", -1 in out, str(out))

    ok_nb = ok_inc = ok_loc_can = True
    for v in idx[:30]:
        v = int(v)
        rows = can[(can == v).any(axis=1)]
        nb = set(rows[rows >= 0].tolist()) - {v}
        hull = bool((rows < 0).any())
        ok_nb &= (set(t.neighbors(v).tolist()) == nb and t.degree(v) == len(nb) + hull
                  and t.on_hull(v) == hull and len(t.neighbors(v)) == len(nb))
        ok_inc &= np.array_equal(sort_rows(t.incident_cells(v)), rows)
        ok_loc_can &= np.array_equal(t.local_canonical([v]), rows)
    check(tag + "neighbors, degree, on_hull", ok_nb, "")
    check(tag + "incident_cells", ok_inc, "")
    check(tag + "local_canonical", ok_loc_can, "")
    check(tag + "is_vertex", t.is_vertex(int(idx[0])) and not t.is_vertex(10 ** 6)
          and not t.is_vertex(-1), "")


def test_degenerate():
    g = np.array([[x, y, z] for x in range(4) for y in range(4) for z in range(4)], dtype=float)
    xyz = np.vstack([g, g[5:6]])                    # a duplicate of point 5 at the end
    t = Triangulation(xyz)
    live = {i: g[i] for i in range(len(g))}
    check("duplicates", t.num_duplicates == 1 and t.alias(64) == 5 and t.alias(5) == 5
          and not t.is_vertex(64) and t.num_input == 65, "")
    same_as_cgal("grid build", t, live)
    for v in (0, 21, 42, 63):                       # a corner, interior, interior, corner
        t.delete(v)
        del live[v]
    same_as_cgal("grid deletions", t, live)
    t.check()
    check("grid check", True)


def test_errors():
    rng = np.random.default_rng(7)
    xyz = rng.random((50, 3))
    bad = xyz.copy()
    bad[3, 1] = np.nan
    raises("create NaN", "DD_ERR_NAN", Triangulation, bad)
    bad[3, 1] = np.inf
    raises("create inf", "DD_ERR_INFINITE", Triangulation, bad)
    flat = xyz.copy()
    flat[:, 2] = 0.5
    raises("create coplanar", "DD_ERR_COPLANAR", Triangulation, flat)
    raises("create too few", "DD_ERR_TOO_FEW", Triangulation, xyz[:3])
    try:
        Triangulation(xyz[:, :2])
        check("create bad shape", False, "no exception")
    except ValueError:
        check("create bad shape", True)
    try:
        Triangulation(bad)
    except DtdelError as e:
        check("error message names the point", "3" in e.message and e.code == 5
              and str(e).startswith("DD_ERR_INFINITE"), e.message)

    with Triangulation(xyz) as t:
        before = t.canonical()
        raises("delete unknown vertex", "DD_ERR_UNKNOWN_VERTEX", t.delete, 1000)
        raises("delete negative vertex", "DD_ERR_UNKNOWN_VERTEX", t.delete, -1)
        raises("delete 2^32", "DD_ERR_UNKNOWN_VERTEX", t.delete, 1 << 32)
        raises("bad variant", "DD_ERR_UNKNOWN_VARIANT", t.delete, 3, "no-such-fill")
        raises("delete_set twice listed", "DD_ERR_ARG", t.delete_set, [4, 9, 4])
        raises("delete_set bad variant", "DD_ERR_UNKNOWN_VARIANT", t.delete_set, [4], "x")
        raises("insert duplicate", "DD_ERR_DUPLICATE", t.insert, xyz[8])
        raises("insert NaN", "DD_ERR_NAN", t.insert, [0.5, np.nan, 0.5])
        raises("move NaN", "DD_ERR_NAN", t.move, 2, [0.5, np.nan, 0.5])
        raises("move onto a vertex", "DD_ERR_DUPLICATE", t.move, 2, xyz[8])
        raises("reinsert a vertex", "DD_ERR_DUPLICATE", t.reinsert, 2)
        raises("locate NaN", "DD_ERR_NAN", t.locate, [np.nan, 0, 0])
        raises("nearest inf", "DD_ERR_INFINITE", t.nearest_vertex, [np.inf, 0, 0])
        raises("point of no vertex", "DD_ERR_UNKNOWN_VERTEX", t.point, 1000)
        raises("degree of no vertex", "DD_ERR_UNKNOWN_VERTEX", t.degree, 1000)
        raises("neighbors of no vertex", "DD_ERR_UNKNOWN_VERTEX", t.neighbors, 1000)
        raises("alias out of range", "DD_ERR_UNKNOWN_VERTEX", t.alias, 1000)
        check("failures change nothing", np.array_equal(t.canonical(), before), "")
        t.delete_set(list(range(4, 50)))
        raises("delete to 3 points", "DD_ERR_DIMENSION", t.delete, 0)
        check("4 points left", t.num_vertices == 4 and t.num_finite_tets == 1, "")


def test_cell_handles():
    """The cell handles of issue 42, once the library has them."""
    rng = np.random.default_rng(3)
    xyz = rng.random((200, 3))
    with Triangulation(xyz) as t:
        end = t.cell_end()
        live = [c for c in range(end) if t.cell_alive(c)]
        rows = [t.cell(c)[0] for c in live]
        check("cell ids are the cells", np.array_equal(sort_rows(rows), t.canonical()), "")
        ok = all(c in t.cell(t.cell(c)[1][i])[1] for c in live[:100] for i in range(4))
        check("cell neighbours", ok, "")
        c = t.locate_from([0.5, 0.5, 0.5])
        check("locate_from", sorted(t.cell(c)[0]) == sorted(t.locate([0.5, 0.5, 0.5]))
              and t.locate_from([0.5, 0.5, 0.5], hint=live[0]) >= 0, str(c))
        i = t.insert([0.31, 0.41, 0.59])
        made = t.created_cells()
        star = sort_rows([t.cell(c)[0] for c in made])
        check("created_cells: the new star", np.array_equal(star, sort_rows(t.incident_cells(i))),
              "%d cells" % len(made))
        t.delete(i)
        made = t.created_cells()
        check("created_cells after a deletion", all(t.cell_alive(c) for c in made)
              and np.array_equal(sort_rows([t.cell(c)[0] for c in range(t.cell_end())
                                            if t.cell_alive(c)]), t.canonical()), "")
        raises("cell of a dead id", "DD_ERR_UNKNOWN_CELL", t.cell, t.cell_end() + 5)
        raises("locate_from a bad hint", "DD_ERR_UNKNOWN_CELL", t.locate_from, [0.5] * 3,
               t.cell_end() + 5)


def test_write():
    rng = np.random.default_rng(5)
    with Triangulation(rng.random((60, 3))) as t, tempfile.TemporaryDirectory() as d:
        for ext in ("vtu", "mesh"):
            path = os.path.join(d, "m." + ext)
            t.write(path)
            check("write ." + ext, os.path.getsize(path) > 0, path)
        # the Medit file's tetrahedra, 1-based over the vertices in index order
        words = open(os.path.join(d, "m.mesh")).read().split()
        k = words.index("Tetrahedra")
        m = int(words[k + 1])
        tets = np.array(words[k + 2:k + 2 + 5 * m], dtype=np.int64).reshape(m, 5)[:, :4] - 1
        finite = t.canonical()[(t.canonical() >= 0).all(axis=1)]
        check("write .mesh: the finite cells",
              np.array_equal(sort_rows(t.vertices()[tets]), finite), "%d tetrahedra" % m)
        raises("write an unknown extension", "DD_ERR_UNKNOWN_FORMAT", t.write,
               os.path.join(d, "m.unknown"))
        # a .vtu is binary (appended raw data), ASCII on request
        data = {}
        for name, kw in (("m.vtu", {}), ("a.vtu", {"ascii": True}), ("m.ascii.vtu", {})):
            t.write(os.path.join(d, name), **kw)
            data[name] = open(os.path.join(d, name), "rb").read()
        check("write .vtu binary", b'<AppendedData encoding="raw">' in data["m.vtu"]
              and b'format="ascii"' not in data["m.vtu"], "")
        check("write .vtu ascii=True", b'format="ascii"' in data["a.vtu"]
              and b"AppendedData" not in data["a.vtu"], "")
        check("write .ascii.vtu as ascii=True", data["m.ascii.vtu"] == data["a.vtu"], "")
        code = t._write_ex(os.path.join(d, "b.vtu"), 2)
        check("write_ex an unknown flag", dtdel.STATUS_NAMES[code] == "DD_ERR_ARG"
              and not os.path.exists(os.path.join(d, "b.vtu")), dtdel.STATUS_NAMES[code])


def test_stable_indices():
    rng = np.random.default_rng(9)
    xyz = rng.random((40, 3))
    with Triangulation(xyz, stable_indices=True) as t:
        t.delete(3)
        i = t.insert([0.3, 0.3, 0.3])
        check("stable indices: no reuse", i == 40, str(i))
    with Triangulation(xyz) as t:
        t.delete(3)
        check("default reuses", t.insert([0.3, 0.3, 0.3]) == 3, "")
    with Triangulation(xyz, weights=np.zeros(40), stable_indices=True) as t:
        check("weights with stable indices", t.is_weighted and t.num_vertices == 40)
    raises("bad weights shape", "DD_ERR_ARG", Triangulation, xyz, np.zeros(3))


INSTALLED = ("import dtdel, numpy as np, sys; "
             "t = dtdel.Delaunay([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]); "
             "print(dtdel.__file__, t.nsimplex, dtdel.version())")


def run_installed(python, env, cwd):
    r = subprocess.run([python, "-c", INSTALLED], cwd=cwd, env=env, capture_output=True, text=True)
    return r.returncode, r.stdout.split(), r.stderr[-400:]


def test_install():
    """make install into a temporary prefix (pip, as a user installs), then
    `pip install --no-build-isolation --no-index python/` into a virtual
    environment made with --system-site-packages: each imports the
    installed compiled package, not the source tree's."""
    top = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    build = os.path.dirname(os.path.abspath(CLI))
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    with tempfile.TemporaryDirectory() as pre:
        r = subprocess.run(["make", "-s", "--no-print-directory", "install", "PREFIX=" + pre,
                            "B=" + build], cwd=top, capture_output=True, text=True)
        check("make install", r.returncode == 0, r.stderr[-400:])
        sites = [os.path.dirname(os.path.dirname(f)) for f in
                 glob.glob(os.path.join(pre, "**", "dtdel", "__init__.py"), recursive=True)]
        check("make install: one package under PREFIX", len(sites) == 1, str(sites))
        if len(sites) == 1:
            rc, out, err = run_installed("/usr/bin/python3", dict(env, PYTHONPATH=sites[0]), pre)
            check("make install: the installed package imports and builds",
                  rc == 0 and out[:2] == [os.path.join(sites[0], "dtdel", "__init__.py"), "2"], str(out) + err)
    with tempfile.TemporaryDirectory() as d:
        venv = os.path.join(d, "venv")
        r = subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv],
                           capture_output=True, text=True)
        check("venv", r.returncode == 0, r.stderr[-400:])
        py = os.path.join(venv, "bin", "python")
        r = subprocess.run([py, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--quiet",
                            "--config-settings=builddir=" + os.path.join(build, "pip"),
                            os.path.join(top, "python")], cwd=d, env=env, capture_output=True, text=True)
        check("pip install python/ in a venv", r.returncode == 0, r.stdout[-300:] + r.stderr[-600:])
        rc, out, err = run_installed(py, env, d)
        check("venv: the installed package imports and builds",
              rc == 0 and out[:1] and out[0].startswith(venv) and out[1] == "2", str(out) + err)


def cgal_weighted(xyz, w, discard):
    """CGAL's (canonical cells, hidden indices) of the weighted points,
    through the CLI's cgal-tets and cgal-hidden on an .xyzw file."""
    with tempfile.NamedTemporaryFile("w", suffix=".xyzw", delete=False) as f:
        for p, wi in zip(xyz, w):
            f.write("%r %r %r %r\n" % (float(p[0]), float(p[1]), float(p[2]), float(wi)))
        path = f.name
    flag = ["--discard-hidden"] if discard else []
    try:
        tets = subprocess.run([CLI, "cgal-tets", path] + flag, check=True, capture_output=True,
                              text=True).stdout
        hid = subprocess.run([CLI, "cgal-hidden", path] + flag, check=True, capture_output=True,
                             text=True).stdout
    finally:
        os.unlink(path)
    rows = np.array([[int(x) for x in line.split()] for line in tets.splitlines() if line.strip()],
                    dtype=np.int32).reshape(-1, 4)
    return rows, np.array([int(x) for x in hid.split()], dtype=np.int64)


def test_weighted():
    rng = np.random.default_rng(43)
    n = 300
    xyz = rng.random((n, 3))
    w = rng.random(n) * 0.04           # a few tens of hidden points
    for discard in (False, True):
        tag = "weighted/%s: " % ("discard" if discard else "keep")
        ref_cells, ref_hidden = cgal_weighted(xyz, w, discard)
        with Triangulation(xyz, weights=w, discard_hidden=discard) as t:
            check(tag + "is_weighted", t.is_weighted)
            check(tag + "cells as CGAL's", np.array_equal(t.canonical(), ref_cells),
                  "%d cells, CGAL %d" % (len(t.canonical()), len(ref_cells)))
            h = t.hidden()
            check(tag + "hidden as CGAL's", np.array_equal(h, ref_hidden), "%s vs %s" % (h[:8], ref_hidden[:8]))
            check(tag + "weights", all(t.weight(i) == w[i] for i in range(n)))
            flags = np.array([t.is_hidden(i) for i in range(n)])
            check(tag + "is_hidden agrees with hidden()", np.array_equal(np.flatnonzero(flags), h))
            both = [i for i in range(n) if t.is_vertex(i) and t.is_hidden(i)]
            check(tag + "no vertex is hidden", not both, str(both[:5]))
            if not discard:
                check(tag + "every point a vertex or hidden", t.num_vertices + len(h) == n and len(h) > 0,
                      "%d vertices + %d hidden of %d" % (t.num_vertices, len(h), n))
            else:
                check(tag + "nothing kept hidden", len(h) == 0 and t.num_vertices < n)
    # insertions: a light point next to a vertex ends hidden (its lifted
    # point lies above the vertex's: the same position, lower weight), a
    # heavy one becomes a vertex; then the whole set as CGAL's, keeping
    with Triangulation(xyz, weights=w) as t:
        v = next(i for i in range(n) if t.is_vertex(i))
        a = t.insert_weighted(xyz[v], w[v] - 1.0)
        check("weighted/insert light at a vertex: hidden", a == n and t.is_hidden(a) and t.is_vertex(v))
        b = t.insert_weighted(xyz[v], w[v] + 1.0)
        check("weighted/insert heavy at a vertex: vertex, the old one hidden",
              b == n + 1 and t.is_vertex(b) and t.is_hidden(v) and not t.is_vertex(v))
        extra = rng.random((40, 3))
        ew = rng.random(40) * 0.04
        idx = [t.insert_weighted(p, wi) for p, wi in zip(extra, ew)]
        check("weighted/insert indices", idx == list(range(n + 2, n + 42)), str(idx[:5]))
        allx = np.vstack([xyz, [xyz[v], xyz[v]], extra])
        allw = np.concatenate([w, [w[v] - 1.0, w[v] + 1.0], ew])
        ref_cells, ref_hidden = cgal_weighted(allx, allw, False)
        check("weighted/inserted as CGAL's", np.array_equal(t.canonical(), ref_cells)
              and np.array_equal(t.hidden(), ref_hidden))
        t.check()
        check("weighted/check after inserts", True)
    # zero weights: the Delaunay triangulation; unweighted: no weights
    with Triangulation(xyz, weights=np.zeros(n)) as z, Triangulation(xyz) as u:
        check("weighted/zero weights are the DT", np.array_equal(z.canonical(), u.canonical()))
        check("weighted/unweighted", not u.is_weighted and u.weight(3) == 0.0 and len(u.hidden()) == 0)
        raises("weighted/insert_weighted unweighted", "DD_ERR_UNSUPPORTED", u.insert_weighted, [0.5] * 3, 0.1)
    bad = w.copy()
    bad[7] = np.nan
    raises("weighted/nan weight", "DD_ERR_NAN", Triangulation, xyz, bad)
    bad[7] = np.inf
    raises("weighted/infinite weight", "DD_ERR_INFINITE", Triangulation, xyz, bad)
    raises("weighted/weights shape", "DD_ERR_ARG", Triangulation, xyz, w[:5])
    with Triangulation(xyz, weights=w) as t:
        before = t.canonical()
        raises("weighted/insert nan weight", "DD_ERR_NAN", t.insert_weighted, [0.5] * 3, float("nan"))
        check("weighted/refused insert changes nothing", np.array_equal(t.canonical(), before)
              and t.num_input == n)
        raises("weighted/weight of no point", "DD_ERR_ARG", t.weight, n + 5)


def test_weighted_edits():
    """Moves, re-weightings, set deletion and re-insertion of weighted
    points, hidden points kept: the result is CGAL's regular triangulation
    of the points as they are left (keep mode is that, whatever the order)."""
    rng = np.random.default_rng(44)
    n = 300
    xyz = rng.random((n, 3))
    w = rng.random(n) * 0.04
    gone = set()

    def same_as_cgal(t, tag):
        sel = np.array([i for i in range(n) if i not in gone])
        cells, hidden = cgal_weighted(xyz[sel], w[sel], False)
        mapped = np.where(cells < 0, -1, sel[np.maximum(cells, 0)])
        mapped = np.sort(mapped, axis=1)
        mapped = mapped[np.lexsort(mapped.T[::-1])]
        check(tag + " as CGAL's", np.array_equal(t.canonical(), mapped)
              and np.array_equal(t.hidden(), np.sort(sel[hidden])),
              "%d cells, CGAL %d" % (len(t.canonical()), len(mapped)))
        t.check()

    with Triangulation(xyz, weights=w) as t:
        h = 0.15
        for k in range(12):
            v = int(rng.integers(n))
            p = xyz[v] + (rng.random(3) - 0.5) * (h if k % 3 else 1e-3)
            nw = w[v] * (4.0 if k % 4 == 1 else 1.0)
            if k % 2:
                t.move_weighted(v, p, nw)
            else:
                nw = w[v]
                t.move(v, p)
            xyz[v], w[v] = p, nw
        same_as_cgal(t, "wedit/moves")
        v = next(i for i in range(n) if t.is_vertex(i))
        t.move_weighted(v, xyz[v], w[v] + 0.3)            # heavy: hides its neighbours
        w[v] += 0.3
        check("wedit/re-weighted up hides others", len(t.hidden()) > 0 and t.is_vertex(v))
        t.move_weighted(v, xyz[v], w[v] - 1.0)            # light: hidden itself
        w[v] -= 1.0
        check("wedit/re-weighted down is hidden", t.is_hidden(v))
        same_as_cgal(t, "wedit/re-weightings")
        hp = int(t.hidden()[0])
        p = xyz[hp] + 0.01
        t.move_weighted(hp, p, w[hp])
        xyz[hp] = p
        same_as_cgal(t, "wedit/hidden point moved")
        vs = [i for i in rng.permutation(n)[:60].tolist()]
        t.delete_set(vs)
        gone.update(vs)
        check("wedit/set deleted", not any(t.is_vertex(i) or t.is_hidden(i) for i in vs))
        same_as_cgal(t, "wedit/set")
        for i in vs[:20]:
            t.reinsert(i)
            gone.discard(i)
        same_as_cgal(t, "wedit/reinserted")
        before = t.canonical()
        v = next(i for i in range(n) if t.is_vertex(i))
        raises("wedit/move nan weight", "DD_ERR_NAN", t.move_weighted, v, xyz[v], float("nan"))
        raises("wedit/move inf weight", "DD_ERR_INFINITE", t.move_weighted, v, xyz[v], float("inf"))
        check("wedit/refused moves change nothing", np.array_equal(t.canonical(), before))
    with Triangulation(xyz) as u:
        raises("wedit/move_weighted unweighted", "DD_ERR_UNSUPPORTED", u.move_weighted, 0, xyz[0], 0.1)


def test_weighted_copies():
    """delete keeps every copy of a hidden weighted point that stays hidden
    (dtdel.h: dd_delete; test_wdelete copies/dropped compares with CGAL):
    the cube's corners, a heavy centre 8 hiding copies 9 and 10 of a and
    a heavier 11 that hides a once 8 is gone."""
    cube = [[k & 1, (k >> 1) & 1, (k >> 2) & 1] for k in range(8)]
    xyz = np.array(cube + [[0.5, 0.5, 0.5], [0.45, 0.4, 0.2]], dtype=float)
    w = np.array([0.0] * 8 + [1.5, 0.0])
    with Triangulation(xyz, weights=w) as t:
        c = t.insert_weighted([0.45, 0.4, 0.2], 0.0)
        b = t.insert_weighted([0.55, 0.4, 0.2], 0.2)
        check("wcopies/hidden before", (c, b) == (10, 11) and list(t.hidden()) == [9, 10, 11])
        t.delete(8)
        check("wcopies/both copies kept", list(t.hidden()) == [9, 10] and t.is_vertex(11),
              str(list(t.hidden())))
        t.delete(10)
        check("wcopies/a copy forgotten", list(t.hidden()) == [9] and not t.is_vertex(10))
        t.check()


def run_groups(groups):
    """Runs each test group (a crash of one is one failure, with its
    traceback), then exits 1 if any check failed."""
    for f in groups:
        try:
            f()
        except Exception as e:  # noqa: BLE001 - a crash of one group is one failure
            import traceback
            traceback.print_exc()
            check(f.__name__, False, "raised %r" % e)
    sys.exit(1 if failed else 0)


def main():
    run_groups((test_bindings, test_module, test_uniform, test_queries_on_build, test_degenerate,
                test_errors, test_cell_handles, test_write, test_stable_indices, test_weighted,
                test_weighted_edits, test_weighted_copies, test_install))


def test_queries_on_build():
    rng = np.random.default_rng(11)
    xyz = rng.random((150, 3))
    with Triangulation(xyz) as t:
        test_queries(t, {i: xyz[i] for i in range(150)}, "built: ")


if __name__ == "__main__":
    main()
