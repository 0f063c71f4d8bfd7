#!/bin/sh
# test_layers.sh -- scripts/layers.sh can fail: on a copy of the sources
# and of a build's objects it says ok on the clean tree, and FAIL, naming
# the culprit, on each violation planted in turn: no objects, a missing
# object, nm failing, upward includes of every spelling (a relative
# path, blanks after the #, no folder, <...>, a name that resolves to no
# file), the engine including or calling datasets/ or src/cgal, an
# upward call, and the command's own boundaries: src/bench including or
# calling src/cli, src/tool calling src/bench, and src/cgal calling
# src/tool; and that src/cli calling src/bench, a downward call, passes.
#
#   sh tests/test_layers.sh OBJDIR      (a release build's build/obj)
set -u
obj=${1:-build/obj}
top=$(cd "$(dirname "$0")/.." && pwd)
CC=${CC:-gcc}
[ -d "$obj" ] || { echo "FAIL layers-test: $obj is not a directory"; exit 1; }
obj=$(cd "$obj" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# the clean copy: sources, the script, the objects of src, variants, datasets
mkdir -p "$tmp/clean/scripts" "$tmp/clean/obj"
(cd "$top" && cp -r src variants datasets "$tmp/clean/") || exit 1
cp "$top/scripts/layers.sh" "$tmp/clean/scripts/" || exit 1
(cd "$obj" && find src variants datasets -name '*.o' | tar cf - -T -) | (cd "$tmp/clean/obj" && tar xf -) || exit 1
w="$tmp/w"
failed=0

fresh() {   # a working copy of the clean one
    rm -rf "$w"
    cp -r "$tmp/clean" "$w"
}

# run NAME WANT PATTERN: runs the check on the working copy; WANT ok or
# FAIL; with FAIL the report must contain PATTERN (a fixed string).
run() {
    name=$1 want=$2 pat=$3
    sh "$w/scripts/layers.sh" "$w/obj" >"$tmp/out" 2>&1
    rc=$?
    first=$(head -n 1 "$tmp/out")
    case "$want" in
        ok) if [ $rc -eq 0 ] && [ "${first#ok layers}" != "$first" ]; then echo "ok layers-test/$name"; return; fi ;;
        FAIL) if [ $rc -ne 0 ] && [ "${first#FAIL layers}" != "$first" ] && grep -qF -- "$pat" "$tmp/out"; then
                  echo "ok layers-test/$name"; return
              fi ;;
    esac
    echo "FAIL layers-test/$name: wanted $want${pat:+ naming '$pat'}, got status $rc:"
    sed 's/^/    /' "$tmp/out" | head -n 8
    failed=$((failed + 1))
}

plant_include() {   # plant_include FILE LINE: appends LINE to FILE
    printf '%s\n' "$2" >>"$w/$1"
}

# plant_call FILE SYMBOL: a source FILE (of its layer) whose object calls
# SYMBOL, compiled into the objects
plant_call() {
    printf 'int %s(void);\nint dd_planted_%s(void);\nint dd_planted_%s(void) { return %s(); }\n' \
        "$2" "$2" "$2" "$2" >"$w/$1"
    mkdir -p "$(dirname "$w/obj/${1%.c}.o")"
    $CC -w -c "$w/$1" -o "$w/obj/${1%.c}.o" || echo "FAIL layers-test: cannot compile $1"
}

fresh
run clean ok ""

fresh
rm -rf "$w/obj" && mkdir "$w/obj"
run no-objects FAIL "no object read"

fresh
rm -f "$w/obj/src/mesh/flip.o"
run missing-object FAIL "src/mesh/flip.o: no object"

fresh
echo "not an object" >"$w/obj/src/geom/pred.o"
run nm-unreadable FAIL "src/geom/pred.o: nm cannot read it"

fresh
mkdir -p "$tmp/bin"
printf '#!/bin/sh\nexit 1\n' >"$tmp/bin/nm" && chmod +x "$tmp/bin/nm"
path=$PATH
PATH="$tmp/bin:$PATH"     # an nm that fails, saying nothing
run nm-fails FAIL "nm cannot read every object"
PATH=$path

fresh
plant_include src/mesh/flip.c '#include "../wrap/wrap.h"'
run include-relative-path FAIL 'src/mesh/flip.c (mesh) includes "../wrap/wrap.h" = src/wrap/wrap.h'

fresh
plant_include src/geom/lift.c '  #  include   "delete/delete.h"'
run include-blanks-after-hash FAIL 'src/geom/lift.c (geom) includes "delete/delete.h"'

fresh
plant_include src/mesh/mesh.h '#include "dtdel.h"'
run include-no-folder FAIL 'src/mesh/mesh.h (mesh) includes "dtdel.h" = src/dtdel.h (the API)'

fresh
plant_include src/delete/qdt.c '#include "wrap.h"'
run include-no-such-file FAIL 'src/delete/qdt.c includes "wrap.h", which names no file'

fresh
plant_include src/mesh/locate.c '#include <wrap/wrap.h>'
run include-angle FAIL 'src/mesh/locate.c (mesh) includes <wrap/wrap.h> = src/wrap/wrap.h'

fresh
plant_include src/geom/pred.c '#include "mesh/mesh.h"'
run include-upward FAIL 'src/geom/pred.c (geom) includes "mesh/mesh.h"'

fresh
plant_include src/delete/grr.c '#include "datasets/datasets.h"'
run include-datasets FAIL 'src/delete/grr.c (delete) includes "datasets/datasets.h"'

fresh
plant_include src/api/api.c '#include "cgal/cgal_shim.h"'
run include-cgal FAIL 'src/api/api.c (the API) includes "cgal/cgal_shim.h"'

fresh
plant_call src/mesh/planted.c dd_gen
run call-datasets FAIL 'src/mesh/planted.o (mesh) calls dd_gen, defined in datasets/'

fresh
plant_call src/api/planted.c dd_cgal_build
run call-cgal FAIL 'src/api/planted.o (the API) calls dd_cgal_build, defined in src/cgal/'

fresh
plant_call src/mesh/planted.c dd_wrap_fill
run call-upward FAIL 'src/mesh/planted.o (mesh) calls dd_wrap_fill, defined in src/wrap/'

fresh
plant_include src/bench/bench.c '#include "cli/cli.h"'
run include-bench-cli FAIL 'src/bench/bench.c (bench) includes "cli/cli.h" = src/cli/cli.h (cli)'

fresh
plant_call src/bench/planted.c cmd_delete
run call-bench-cli FAIL 'src/bench/planted.o (bench) calls cmd_delete, defined in src/cli/cli_delete.o (cli)'

fresh
plant_call src/tool/planted.c gen_points
run call-tool-bench FAIL 'src/tool/planted.o (tool) calls gen_points, defined in src/bench/options.o (bench)'

fresh
plant_call src/cgal/planted.c usage_error
run call-cgal-tool FAIL 'src/cgal/planted.o (datasets and CGAL) calls usage_error, defined in src/tool/tool.o (tool)'

fresh
plant_call src/cli/planted.c gen_points
run call-cli-bench ok ""

[ "$failed" -eq 0 ]
