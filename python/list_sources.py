"""Prints the C library's sources, one a line, relative to python/: the
layers Makefile's LIB_SRC names (src/geom, mesh, delete, wrap, variants,
src/api), so that meson.build compiles exactly the library make builds."""
import glob
import os

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.dirname(here)
for folder in ["src/geom", "src/mesh", "src/delete", "src/wrap", "variants", "src/api"]:
    for f in sorted(glob.glob(os.path.join(top, folder, "*.c"))):
        print(os.path.relpath(f, here))
