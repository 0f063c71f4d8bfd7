"""
_lib.py -- loads libdtdel.so and declares the C prototypes of src/dtdel.h.

Owns: finding the shared library and the ctypes signature of every public
call.  PROTOTYPES is the one table of them: tests/test_python.py checks that
every dd_ function of dtdel.h is in it (or in UNBOUND, with a reason).  A call
missing from the loaded library (an older build) is left out of `lib` and its
binding raises NotImplementedError; nothing else degrades.

Where the library comes from, first found wins:
  1. $DTDEL_LIBRARY (a path to a libdtdel.so);
  2. the path `make install` recorded in _libpath.py (the installed library);
  3. libdtdel.so beside this file (`make python` copies build/libdtdel.so here).
"""
import ctypes
import os
from ctypes import (POINTER, c_char_p, c_double, c_int, c_int32, c_int64,
                    c_size_t, c_uint, c_uint32, c_uint64, c_void_p)

_p_int32 = POINTER(c_int32)
_p_uint32 = POINTER(c_uint32)
_p_double = POINTER(c_double)
_p_cell_id = POINTER(c_int64)

# name: (restype, argtypes).  dd_tri * is a c_void_p; arrays are pointers to
# their element type; the malloc'd outputs are pointers to pointers.
PROTOTYPES = {
    "dd_status_name": (c_char_p, [c_int]),
    "dd_create": (c_int, [POINTER(c_void_p), _p_double, c_uint32, c_char_p, c_size_t]),
    "dd_free": (None, [c_void_p]),
    "dd_errmsg": (c_char_p, [c_void_p]),
    "dd_num_input": (c_uint32, [c_void_p]),
    "dd_num_vertices": (c_uint32, [c_void_p]),
    "dd_num_duplicates": (c_uint32, [c_void_p]),
    "dd_num_tets": (c_size_t, [c_void_p]),
    "dd_num_finite_tets": (c_size_t, [c_void_p]),
    "dd_alias": (c_uint32, [c_void_p, c_uint32]),
    "dd_is_vertex": (c_int, [c_void_p, c_uint32]),
    "dd_degree": (c_uint32, [c_void_p, c_uint32]),
    "dd_on_hull": (c_int, [c_void_p, c_uint32]),
    "dd_canonical": (c_int, [c_void_p, POINTER(_p_int32), POINTER(c_size_t)]),
    "dd_neighbors": (c_uint32, [c_void_p, c_uint32, _p_uint32, c_uint32]),
    "dd_local_canonical": (c_int, [c_void_p, _p_uint32, c_size_t,
                                   POINTER(_p_int32), POINTER(c_size_t)]),
    "dd_canonical_hash": (c_uint64, [_p_int32, c_size_t]),
    "dd_check": (c_int, [c_void_p]),
    "dd_check_msg": (c_int, [c_void_p, c_char_p, c_size_t]),
    "dd_point": (c_int, [c_void_p, c_uint32, _p_double]),
    "dd_cells": (c_int, [c_void_p, POINTER(_p_int32), POINTER(_p_int32),
                         POINTER(c_size_t)]),
    "dd_incident_cells": (c_uint32, [c_void_p, c_uint32, _p_int32, c_uint32]),
    "dd_locate": (c_int, [c_void_p, _p_double, _p_int32]),
    "dd_nearest_vertex": (c_int, [c_void_p, _p_double, _p_uint32]),
    "dd_delete": (c_int, [c_void_p, c_uint32]),
    "dd_delete_with": (c_int, [c_void_p, c_uint32, c_char_p]),
    "dd_delete_set": (c_int, [c_void_p, _p_uint32, c_size_t]),
    "dd_delete_set_with": (c_int, [c_void_p, _p_uint32, c_size_t, c_char_p]),
    "dd_move": (c_int, [c_void_p, c_uint32, _p_double]),
    "dd_insert": (c_int, [c_void_p, _p_double, _p_uint32]),
    "dd_reinsert": (c_int, [c_void_p, c_uint32]),
    "dd_variant_name": (c_char_p, [c_size_t]),
    "dd_variant_description": (c_char_p, [c_size_t]),
    "dd_memory_bytes": (c_size_t, [c_void_p]),
    # issue 42's contract, bound as the calls land (absent: NotImplementedError)
    "dd_version": (c_char_p, []),
    "dd_create_ex": (c_int, [POINTER(c_void_p), _p_double, _p_double, c_uint32,
                             c_uint, c_char_p, c_size_t]),
    "dd_cell_end": (c_int64, [c_void_p]),
    "dd_cell_alive": (c_int, [c_void_p, c_int64]),
    "dd_cell": (c_int, [c_void_p, c_int64, _p_int32, _p_cell_id]),
    "dd_locate_from": (c_int, [c_void_p, _p_double, c_int64, _p_cell_id]),
    "dd_created_cells": (c_int, [c_void_p, POINTER(_p_cell_id), POINTER(c_size_t)]),
    "dd_write": (c_int, [c_void_p, c_char_p]),
    "dd_write_ex": (c_int, [c_void_p, c_char_p, c_uint]),
    # issue 43: weighted points (regular triangulations)
    "dd_is_weighted": (c_int, [c_void_p]),
    "dd_weight": (c_int, [c_void_p, c_uint32, _p_double]),
    "dd_is_hidden": (c_int, [c_void_p, c_uint32]),
    "dd_hidden": (c_int, [c_void_p, POINTER(_p_uint32), POINTER(c_size_t)]),
    "dd_insert_weighted": (c_int, [c_void_p, _p_double, c_double, _p_uint32]),
    "dd_move_weighted": (c_int, [c_void_p, c_uint32, _p_double, c_double]),
    # issue 56: hinted insertion and whole-array calls
    "dd_insert_from": (c_int, [c_void_p, _p_double, c_int64, _p_uint32]),
    "dd_insert_weighted_from": (c_int, [c_void_p, _p_double, c_double, c_int64, _p_uint32]),
    "dd_insert_many": (c_int, [c_void_p, _p_double, _p_double, c_size_t, _p_uint32,
                               POINTER(c_size_t)]),
    "dd_move_many": (c_int, [c_void_p, _p_uint32, _p_double, _p_double, c_size_t]),
    "dd_locate_many": (c_int, [c_void_p, _p_double, c_size_t, _p_cell_id]),
    "dd_nearest_many": (c_int, [c_void_p, _p_double, c_size_t, _p_uint32]),
    "dd_points": (c_int, [c_void_p, _p_double, _p_double]),
    "dd_cells_vertices": (c_int, [c_void_p, _p_cell_id, c_size_t, _p_int32]),
}

# dd_ names of dtdel.h that get no Python function of their own, and why.
UNBOUND = {
    "dd_is_infinite": "a static inline in the header, not in the library; "
                      "Python tests v < 0",
}

# Status names in the order of dtdel.h's enum dd_status (the test checks it).
STATUS_NAMES = [
    "DD_OK", "DD_ERR_NOMEM", "DD_ERR_IO", "DD_ERR_PARSE", "DD_ERR_NAN",
    "DD_ERR_INFINITE", "DD_ERR_TOO_FEW", "DD_ERR_COLLINEAR", "DD_ERR_COPLANAR",
    "DD_ERR_UNKNOWN_VERTEX", "DD_ERR_UNKNOWN_VARIANT", "DD_ERR_DUPLICATE",
    "DD_ERR_DIMENSION", "DD_ERR_INTERNAL", "DD_ERR_ARG", "DD_ERR_UNSUPPORTED",
    "DD_ERR_UNKNOWN_CELL", "DD_ERR_UNKNOWN_FORMAT",
]


def _find():
    env = os.environ.get("DTDEL_LIBRARY")
    if env:
        return env
    try:
        from ._libpath import LIBRARY  # written by make install
        if os.path.exists(LIBRARY):
            return LIBRARY
    except ImportError:
        pass
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "libdtdel.so")
    if os.path.exists(here):
        return here
    raise ImportError("dtdel: libdtdel.so not found: run `make python` at the "
                      "top of the source tree, or set DTDEL_LIBRARY")


PATH = _find()
_dll = ctypes.CDLL(PATH)


class _Lib:
    """The declared calls the loaded library has, as attributes."""


lib = _Lib()
MISSING = []
for _name, (_res, _args) in PROTOTYPES.items():
    try:
        _f = getattr(_dll, _name)
    except AttributeError:
        MISSING.append(_name)
        continue
    _f.restype = _res
    _f.argtypes = _args
    setattr(lib, _name, _f)

# The C allocator that dd_canonical and dd_cells' arrays come from.
_libc = ctypes.CDLL(None)
libc_free = _libc.free
libc_free.restype = None
libc_free.argtypes = [c_void_p]
