"""test_write.py -- dd_write's files read back by real readers.

    /usr/bin/python3 tests/test_write.py NAME POINTS.xyz CANON.txt OUT.vtu OUT.ascii.vtu OUT.mesh

CANON.txt is `dtdel tets POINTS.xyz` (the canonical form), OUT.vtu,
OUT.ascii.vtu and OUT.mesh are `dtdel tets POINTS.xyz --out ...`: the
binary .vtu (appended raw data, UInt64 headers) and the ASCII one.  Each
.vtu is read with meshio and with VTK's own XML reader, the .mesh with
meshio; each must give the live vertices (in input index order,
coordinates exact), the finite cells of the canonical form, and every
tetrahedron with positive volume: exactly ((b - a) x (c - a)) . (d - a) >
0 in rationals, and by VTK's vtkTetra.ComputeVolume.  The binary file
must hold no ASCII data array and the ASCII file no appended data.
Prints "ok NAME" / "FAIL NAME: why" lines.
"""
import sys
from fractions import Fraction

import numpy as np


def check(ok, name, why):
    print(("ok %s" % name) if ok else ("FAIL %s: %s" % (name, why)))
    sys.stdout.flush()


def read_points(path):
    pts = []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].split()
            if line:
                pts.append(tuple(float(x) for x in line[:3]))
    return pts


def read_canonical(path):
    cells = set()
    with open(path) as f:
        for line in f:
            c = tuple(int(x) for x in line.split())
            if min(c) >= 0:
                cells.add(c)
    return cells


def positive(p):
    a, b, c, d = [[Fraction(x) for x in q] for q in p]
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return sum(cross[i] * w[i] for i in range(3)) > 0


def compare(name, points, tets, index, pts, canon):
    """points (N x 3), tets (M x 4, 0-based), index: input index of each point."""
    live = sorted({i for c in canon for i in c})
    check(list(index) == live, name + "/points-are-the-live-vertices",
          "%d points, %d live vertices" % (len(index), len(live)))
    bad = sum(1 for k, i in enumerate(index) if tuple(float(x) for x in points[k]) != pts[i])
    check(bad == 0, name + "/coordinates-exact", "%d points differ from the input" % bad)
    mine = {tuple(sorted(int(index[j]) for j in t)) for t in tets}
    check(len(tets) == len(canon) and mine == canon, name + "/cells-are-the-canonical-finite-cells",
          "%d cells read, %d distinct, %d canonical finite cells, %d missing"
          % (len(tets), len(mine), len(canon), len(canon - mine)))
    neg = sum(1 for t in tets if not positive([points[j] for j in t]))
    check(neg == 0, name + "/orientation-positive", "%d of %d tetrahedra not positive" % (neg, len(tets)))


def encoding(path):
    """'binary' for appended raw data and no ASCII array, 'ascii' for ASCII
    arrays and no appended data, else what the header says."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"<AppendedData")
    head = data[:end] if end >= 0 else data
    if end >= 0 and b'<AppendedData encoding="raw">' in data and b'header_type="UInt64"' in head \
            and b'format="ascii"' not in head:
        return "binary"
    if end < 0 and b'format="ascii"' in head and b'format="appended"' not in head:
        return "ascii"
    return "neither (%s)" % head[:200]


def check_vtu(name, vtu, want, pts, canon):
    """The .vtu at vtu, written binary or ascii (want), by meshio and VTK."""
    enc = encoding(vtu)
    check(enc == want, name + "/data-" + want, "the file's data arrays are %s" % enc)
    import meshio
    m = meshio.read(vtu)
    tets = [c.data for c in m.cells if c.type == "tetra"]
    others = [c.type for c in m.cells if c.type != "tetra"]
    check(len(tets) == 1 and not others, name + "/meshio-tetra-only", "cell blocks %s" % [c.type for c in m.cells])
    index = np.asarray(m.point_data.get("input_index", []))
    compare(name + "/meshio", m.points, tets[0] if tets else [], index, pts, canon)

    import vtk
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(vtu)
    r.Update()
    g = r.GetOutput()
    points = [g.GetPoint(k) for k in range(g.GetNumberOfPoints())]
    types = {g.GetCellType(k) for k in range(g.GetNumberOfCells())}
    check(types <= {vtk.VTK_TETRA}, name + "/vtk-cell-types", "types %s" % types)
    tets = []
    negvol = 0
    for k in range(g.GetNumberOfCells()):
        ids = g.GetCell(k).GetPointIds()
        t = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
        tets.append(t)
        negvol += vtk.vtkTetra.ComputeVolume(*[points[j] for j in t]) <= 0
    arr = g.GetPointData().GetArray("input_index")
    index = [int(arr.GetValue(k)) for k in range(arr.GetNumberOfTuples())] if arr else []
    compare(name + "/vtk", points, tets, index, pts, canon)
    check(negvol == 0, name + "/vtk-volume-positive", "%d tetrahedra with VTK volume <= 0" % negvol)


def main():
    name, xyz, canon_path, vtu, ascii_vtu, mesh = sys.argv[1:7]
    pts = read_points(xyz)
    canon = read_canonical(canon_path)
    check_vtu(name + "/vtu-binary", vtu, "binary", pts, canon)
    check_vtu(name + "/vtu-ascii", ascii_vtu, "ascii", pts, canon)

    import meshio
    m = meshio.read(mesh)
    tets = [c.data for c in m.cells if c.type == "tetra"]
    live = sorted({i for c in canon for i in c})
    check(len(tets) == 1, name + "/meshio-mesh-tetra-only", "cell blocks %s" % [c.type for c in m.cells])
    compare(name + "/meshio-mesh", m.points, tets[0] if tets else [], live if len(m.points) == len(live) else [],
            pts, canon)


if __name__ == "__main__":
    main()
