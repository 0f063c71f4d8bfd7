#!/bin/sh
# test_alloc.sh -- scripts/alloc.sh, the check that the engine allocates
# only through dtdel/alloc.h: ok on the tree as it is; on a copy of the
# sources, FAIL naming file and line for each raw call planted in turn
# (malloc in the library, free in a header, realloc in variants/, strdup
# in the CLI, calloc with a blank before the parenthesis), and ok still
# for the words in a comment, a string or a member call, and for the C++
# shim (src/cgal, above the library).
#
#   sh tests/test_alloc.sh
set -u
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
check() {   # check NAME WANT PATTERN [ROOT]
    name=$1 want=$2 pat=$3 root=${4:-$tmp/w}
    sh "$top/scripts/alloc.sh" "$root" >"$tmp/out" 2>&1
    rc=$?
    first=$(head -n 1 "$tmp/out")
    if [ "$want" = ok ] && [ $rc -eq 0 ] && [ "$first" = "ok alloc" ]; then
        echo "ok alloc-test/$name"
    elif [ "$want" = FAIL ] && [ $rc -ne 0 ] && [ "$first" != "${first#FAIL alloc}" ] && grep -qF "$pat" "$tmp/out"; then
        echo "ok alloc-test/$name"
    else
        echo "FAIL alloc-test/$name: wanted $want ($pat), got status $rc:"
        sed 's/^/    /' "$tmp/out"
        failed=1
    fi
}
fresh() { rm -rf "$tmp/w"; mkdir -p "$tmp/w"; (cd "$top" && cp -r src variants "$tmp/w/"); }
plant() {   # plant FILE LINE: appends LINE to the copy's FILE
    printf '%s\n' "$2" >>"$tmp/w/$1"
}

check tree ok "" "$top"
fresh; check clean-copy ok ""
n=$(($(wc -l <"$top/src/mesh/mesh.c") + 1))
fresh; plant src/mesh/mesh.c 'static void *x_(void) { return malloc(8); }'
check malloc FAIL "src/mesh/mesh.c:$n:"
fresh; plant src/geom/pred.h 'static inline void y_(void *p) { free(p); }'
check free-in-header FAIL "src/geom/pred.h:"
fresh; plant variants/auto.c 'static void *z_(void *p) { return realloc (p, 8); }'
check realloc-blank FAIL "variants/auto.c:"
fresh; plant src/cli/cli.c 'static char *w_(const char *s) { return strdup(s); }'
check strdup-cli FAIL "src/cli/cli.c:"
fresh; plant src/api/api.c 'static void *v_(void) { return calloc(1, 8); }'
check calloc FAIL "src/api/api.c:"
fresh
plant src/api/api.c '/* a comment may say free(p) or malloc(n) */'
plant src/api/api.c 'static const char *u_ = "free (recorded) malloc(\"x\")";'
plant src/api/api.c 'struct k_ { void (*free)(void *); }; static void t_(struct k_ *k, void *p) { k->free(p); }'
plant src/api/api.c 'static void s_(void *p) { dd_mfree(p); (void)dd_malloc(1); }'
check words-not-calls ok ""
fresh; printf 'void q_(void *p) { free(p); }\n' >>"$tmp/w/src/cgal/cgal_shim.cpp"
check cgal-excluded ok ""
exit $failed
