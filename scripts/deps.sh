#!/bin/sh
# Installs the Debian packages the project needs, or says exactly what to
# install when it cannot (not root, no apt-get).  Quiet when all is there.
# python3-meshio, python3-vtk9, python3-numpy: tests/test_write.sh reads the
# mesh files back with them (/usr/bin/python3).  The Python package
# (python/) builds with meson-python and Cython against numpy and
# Python.h; its tests compare with scipy and install it into a venv.
# libtbb-dev: the bench's anchor, CGAL's Parallel_tag construction.
PKGS="libcgal-dev libgmp-dev libmpfr-dev libboost-dev gnuplot-nox libcgal-demo g++ make pkg-config python3-meshio python3-vtk9 python3-numpy
      python3-dev cython3 meson ninja-build python3-mesonpy python3-scipy python3-venv python3-pip libtbb-dev"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "deps: missing Debian packages:$missing" >&2
if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
    echo "deps: cannot install them here; run as root:" >&2
    echo "    apt-get update && apt-get install -y$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null && apt-get install -y -qq --no-install-recommends$missing >/dev/null || {
    echo "deps: apt-get failed; run: apt-get update && apt-get install -y$missing" >&2
    exit 1
}
echo "deps: installed$missing" >&2
