#!/bin/sh
# Mesh files (dd_write through `dtdel tets --out`) read back by real
# readers: meshio (.vtu, .mesh) and VTK's Python module (.vtu), compared
# with the canonical form (tests/test_write.py); the .vtu binary (the
# default) and ASCII (a name ending .ascii.vtu; --ascii writes the same
# bytes under any name).  Needs Debian's
# python3-meshio, python3-vtk9 and python3-numpy (scripts/deps.sh), run
# by /usr/bin/python3.  Prints ok/FAIL lines.
DTDEL=${1:-build/dtdel}
PY=/usr/bin/python3
dir=$(dirname "$0")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! $PY -c 'import meshio, vtk, numpy' 2>"$tmp/err"; then
    echo "FAIL write/readers: $PY cannot import meshio, vtk and numpy (scripts/deps.sh): $(tail -n 1 "$tmp/err")"
    exit 1
fi
"$DTDEL" gen uniform 300 --seed 4 >"$tmp/uniform.xyz"
"$DTDEL" gen grid 125 >"$tmp/grid.xyz"               # cospherical: the perturbation decides
{ "$DTDEL" gen cosphere 200; echo "0 0 0"; } >"$tmp/cosphere.xyz"
# duplicates and a point deleted nowhere: input indices with gaps
{ head -n 50 "$tmp/uniform.xyz"; head -n 3 "$tmp/uniform.xyz"; sed -n 51,80p "$tmp/uniform.xyz"; } >"$tmp/dups.xyz"
for ds in uniform grid cosphere dups; do
    f=$tmp/$ds.xyz
    if ! "$DTDEL" tets "$f" >"$tmp/$ds.canon" 2>"$tmp/err" || ! "$DTDEL" tets "$f" --out "$tmp/$ds.vtu" 2>>"$tmp/err" ||
        ! "$DTDEL" tets "$f" --out "$tmp/$ds.ascii.vtu" 2>>"$tmp/err" ||
        ! "$DTDEL" tets "$f" --out "$tmp/$ds-flag.vtu" --ascii 2>>"$tmp/err" ||
        ! "$DTDEL" tets "$f" --out "$tmp/$ds.mesh" 2>>"$tmp/err"; then
        echo "FAIL write/$ds: dtdel failed: $(head -c 300 "$tmp/err")"
        continue
    fi
    cmp -s "$tmp/$ds.ascii.vtu" "$tmp/$ds-flag.vtu" && echo "ok write/$ds/ascii-flag-as-ascii-name" ||
        echo "FAIL write/$ds/ascii-flag-as-ascii-name: --out X.vtu --ascii and --out X.ascii.vtu differ"
    $PY "$dir/test_write.py" "write/$ds" "$f" "$tmp/$ds.canon" "$tmp/$ds.vtu" "$tmp/$ds.ascii.vtu" "$tmp/$ds.mesh" 2>"$tmp/err" ||
        echo "FAIL write/$ds: test_write.py exited $?: $(tail -n 3 "$tmp/err")"
done
