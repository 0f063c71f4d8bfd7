#!/bin/sh
# layers.sh -- checks that the engine's folders use only downwards.
#
#   scripts/layers.sh OBJDIR
#
# OBJDIR is a release build's object tree (build/obj).  Each source file
# belongs to a layer, bottom up (docs/architecture.md):
#
#   src/dtdel (the shared types), src/geom, src/mesh, src/delete, src/wrap,
#   variants, src/api and src/*.h (the API): the library; then the
#   command's side, which the library must not use at all: datasets and
#   src/cgal (the points and the CGAL reference, side by side), src/tool
#   (what the command's two halves share), src/bench (the benchmark
#   harness) and, on top, src/cli (the user's commands and the command
#   table, which dispatches the bench's too).
#
# Two checks, each failing the run:
#  - calls: for every global symbol an object uses (nm -u), the layer of
#    the object defining it must be the user's own or one below it.  Every
#    source file must have its object in OBJDIR, and nm must read each;
#  - includes: every #include of every source file (any spacing after
#    the #, "..." or <...>), resolved to the file it names as the compiler
#    does (a "..." name in the including file's folder first, then in
#    src and . (-Isrc -I.); a <...> name in src and .), must be of the
#    including file's layer or one below.  A "..." name that resolves to
#    no file is an error too; a <...> one is a system header.
# Prints `ok layers`, or `FAIL layers` with each violation, and exits
# non-zero on one.
set -u
obj=${1:-build/obj}
[ -d "$obj" ] || { echo "FAIL layers: $obj is not a directory"; exit 1; }
obj=$(cd "$obj" && pwd)
top=$(cd "$(dirname "$0")/.." && pwd)

# The layers, as awk functions both passes share: rank(path) of a file
# (relative to the top), bottom up; files of no layer (tests, scripts)
# rank above all.  layer(rank) names one, for messages.
LAYERS_AWK='
function rank(p) {
    if (p ~ /^src\/dtdel\//) return 0
    if (p ~ /^src\/geom\//) return 1
    if (p ~ /^src\/mesh\//) return 2
    if (p ~ /^src\/delete\//) return 3
    if (p ~ /^src\/wrap\//) return 4
    if (p ~ /^variants\//) return 5
    if (p ~ /^src\/api\// || p ~ /^src\/[^\/]*$/) return 6
    if (p ~ /^(src\/cgal|datasets)\//) return 7
    if (p ~ /^src\/tool\//) return 8
    if (p ~ /^src\/bench\//) return 9
    if (p ~ /^src\/cli\//) return 10
    return 99
}
function layer(r) {
    return r == 0 ? "src/dtdel" : r == 1 ? "geom" : r == 2 ? "mesh" : r == 3 ? "delete" : r == 4 ? "wrap" : \
           r == 5 ? "variants" : r == 6 ? "the API" : r == 7 ? "datasets and CGAL" : r == 8 ? "tool" : \
           r == 9 ? "bench" : r == 10 ? "cli" : "no layer"
}'

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/up"

# ---- calls ----------------------------------------------------------------
# the objects of the sources there are now (a build dir may keep objects
# of files since moved or removed); each must be there
(cd "$top" && find src variants datasets -name '*.c' -o -name '*.cpp' | sed 's/\.c\(pp\)\{0,1\}$/.o/' | sort) >"$tmp/objs"
[ -s "$tmp/objs" ] || echo "  no source files under $top" >>"$tmp/up"
while read -r o; do
    if [ -f "$obj/$o" ]; then echo "$o"; else echo "  $o: no object in $obj (build first)" >>"$tmp/up"; fi
done <"$tmp/objs" >"$tmp/have"
n=$(wc -l <"$tmp/have")
[ "$n" -gt 0 ] || echo "  no object read in $obj" >>"$tmp/up"
# one nm for all: "OBJ:ADDR TYPE SYMBOL" a definition, "OBJ: U SYMBOL" a
# use.  nm failing, or listing nothing for an object, fails the check.
: >"$tmp/nm"
if [ "$n" -gt 0 ]; then
    if ! (cd "$obj" && xargs nm -A -g <"$tmp/have") >"$tmp/nm" 2>"$tmp/nm.err"; then
        echo "  nm cannot read every object: $(head -n 1 "$tmp/nm.err")" >>"$tmp/up"
    fi
    cut -d: -f1 "$tmp/nm" | sort -u >"$tmp/read"
    sort "$tmp/have" | comm -23 - "$tmp/read" | sed 's/$/: nm cannot read it (no symbols listed)/; s/^/  /' >>"$tmp/up"
fi
awk -v defs="$tmp/defs.u" -v uses="$tmp/uses.u" "$LAYERS_AWK"'
{
    i = index($0, ":")
    o = substr($0, 1, i - 1)
    split(substr($0, i + 1), f, " ")
    if (f[1] == "U") print f[2], rank(o), o > uses
    else if (f[2] ~ /^[TDBRCVW]$/) print f[3], rank(o), o > defs
}' "$tmp/nm"
touch "$tmp/defs.u" "$tmp/uses.u"
sort "$tmp/defs.u" >"$tmp/defs"
sort "$tmp/uses.u" >"$tmp/uses"
# a use defined in a layer above the user's (not by the user itself)
join "$tmp/uses" "$tmp/defs" | awk "$LAYERS_AWK"'
$2 < $4 && $3 != $5 { printf "  %s (%s) calls %s, defined in %s (%s)\n", $3, layer($2), $1, $5, layer($4) }' >>"$tmp/up"

# ---- includes ---------------------------------------------------------------
# One awk pass over every source file: each include line ("# include",
# "#include", any blanks), its name resolved as the compiler does, the
# layers compared.
cd "$top" || exit 1
find src variants datasets -name '*.[ch]' -o -name '*.cpp' | sort >"$tmp/files"
xargs awk "$LAYERS_AWK"'
function norm(p,    n, i, k, part, out) {   # a/./b/../c -> a/c
    n = split(p, part, "/")
    k = 0
    for (i = 1; i <= n; i++) {
        if (part[i] == "." || part[i] == "") continue
        if (part[i] == ".." && k > 0 && out[k] != "..") { k--; continue }
        out[++k] = part[i]
    }
    p = ""
    for (i = 1; i <= k; i++) p = p (i > 1 ? "/" : "") out[i]
    return p
}
function exists(p,    line, r) {
    r = (getline line < p)
    if (r >= 0) close(p)
    return r >= 0
}
/^[ \t]*#[ \t]*include[ \t]*["<]/ {
    inc = $0
    sub(/^[ \t]*#[ \t]*include[ \t]*/, "", inc)
    q = substr(inc, 1, 1) == "\""
    name = substr(inc, 2)
    sub(/[">].*$/, "", name)
    shown = q ? "\"" name "\"" : "<" name ">"
    dir = FILENAME
    sub(/\/[^\/]*$/, "", dir)
    to = ""
    if (q && exists(norm(dir "/" name))) to = norm(dir "/" name)
    else if (exists(norm("src/" name))) to = norm("src/" name)
    else if (exists(norm(name))) to = norm(name)
    if (to == "") {
        if (q) printf "  %s includes %s, which names no file (from its folder, src or .)\n", FILENAME, shown
        next
    }
    from = rank(FILENAME)
    r = rank(to)
    if (r > from) printf "  %s (%s) includes %s = %s (%s)\n", FILENAME, layer(from), shown, to, layer(r)
}' <"$tmp/files" >>"$tmp/up"

if [ -s "$tmp/up" ]; then
    echo "FAIL layers: upward or unchecked uses between layers (docs/architecture.md)"
    cat "$tmp/up"
    exit 1
fi
echo "ok layers ($n objects)"
