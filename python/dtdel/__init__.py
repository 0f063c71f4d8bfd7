"""
dtdel -- exact 3D Delaunay and regular triangulations, identical to CGAL's
simplex for simplex, with fast edits (vertex deletion, insertion, moves).

Two classes, both on the compiled core (_core.pyx, the C library inside):

  Delaunay       scipy.spatial.Delaunay's names, shapes and dtypes for 3D
                 input, plus remove / insert / move, weights and locate;
  Triangulation  the C API one call a method (input indices, cell ids,
                 canonical forms, the deletion strategies).

    import numpy as np, dtdel
    tri = dtdel.Delaunay(np.random.rand(1000, 3))   # scipy.spatial.Delaunay
    tri.simplices, tri.neighbors, tri.find_simplex(q)
    tri.remove([7, 8]); tri.insert(new_points); tri.move(ids, moved)

Weighted points give the regular triangulation (CGAL's
Regular_triangulation_3): Delaunay(xyz, weights=w), its hidden points in
`hidden`.  Every array call releases the GIL: separate triangulations
build in parallel threads, and reads of one run in many threads at once;
an edit holds its own triangulation's lock, no global one.  A failed call
raises DtdelError (a ValueError) with .status and .message, and changes
nothing.
"""
from ._core import (DISCARD_HIDDEN, STABLE_INDICES, STATUS_NAMES, WRITE_ASCII, DtdelError,
                    Triangulation, canonical_hash, status_name, variant_descriptions, variants,
                    version)
from ._scipy import Delaunay

__version__ = version()
__all__ = ["Delaunay", "Triangulation", "DtdelError", "variants", "variant_descriptions",
           "status_name", "version", "canonical_hash", "STATUS_NAMES", "STABLE_INDICES",
           "DISCARD_HIDDEN", "WRITE_ASCII"]
