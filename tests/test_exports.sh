#!/bin/sh
# The library exports exactly its public calls: the functions the
# installed headers (src/dtdel.h, src/dtdel_stats.h) declare, no fewer
# and no more.  Compares, both ways, the header's declarations (the
# compiler's own list, gcc -aux-info) with what build/libdtdel.so
# exports (nm -D) and what build/libdtdel.a defines globally (nm -g);
# checks the soname against dtdel.h's version and that the header is
# also valid C++.  Prints ok/FAIL lines.
REL=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# the functions the headers declare (not the static inline helpers)
printf '#include "dtdel_stats.h"\n' >"$tmp/h.c"
gcc -std=c11 -I"$top/src" -aux-info "$tmp/aux" -c "$tmp/h.c" -o "$tmp/h.o" || { echo "FAIL exports/headers: do not compile"; exit 1; }
grep -E '^/\* [^ ]*/src/dtdel(_stats)?\.h:[0-9]+:NC \*/ extern ' "$tmp/aux" |
    sed 's/ *(.*//; s/.*[ *]\([A-Za-z_][A-Za-z0-9_]*\)$/\1/' | sort -u >"$tmp/declared"

compare() {   # compare NAME FILE-OF-NAMES
    if [ ! -s "$tmp/declared" ] || [ ! -s "$2" ]; then
        echo "FAIL exports/$1: an empty list ($(wc -l <"$tmp/declared") declared, $(wc -l <"$2") found)"
    elif cmp -s "$tmp/declared" "$2"; then
        echo "ok exports/$1"
    else
        echo "FAIL exports/$1: declared but not exported: $(comm -23 "$tmp/declared" "$2" | tr '\n' ' ')" \
             "exported but not declared: $(comm -13 "$tmp/declared" "$2" | tr '\n' ' ')"
    fi
}

nm -D --defined-only "$REL/libdtdel.so" | awk '{ print $3 }' | sort -u >"$tmp/shared"
compare shared "$tmp/shared"
nm -g --defined-only "$REL/libdtdel.a" | awk 'NF == 3 { print $3 }' | sort -u >"$tmp/static"
compare static "$tmp/static"

# the soname and the file name come from dtdel.h's version macros
ver() { sed -n "s/^#define DD_VERSION_$1 *\([0-9][0-9]*\).*/\1/p" "$top/src/dtdel.h"; }
want="libdtdel.so.$(ver MAJOR)"
got=$(readelf -d "$REL/libdtdel.so" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [ "$got" = "$want" ] && [ -f "$REL/libdtdel.so.$(ver MAJOR).$(ver MINOR).$(ver PATCH)" ]; then
    echo "ok exports/soname"
else
    echo "FAIL exports/soname: soname '$got', expected '$want' (and $want.$(ver MINOR).$(ver PATCH))"
fi

printf '#include "dtdel_stats.h"\nint main() { return dd_version() == nullptr; }\n' >"$tmp/h.cpp"
if g++ -std=c++17 -Wall -Wextra -I"$top/src" -fsyntax-only "$tmp/h.cpp" 2>"$tmp/err"; then
    echo "ok exports/c++"
else
    echo "FAIL exports/c++: $(head -c 300 "$tmp/err")"
fi
