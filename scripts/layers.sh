#!/bin/sh
# layers.sh -- checks that the engine's folders call only downwards.
#
#   scripts/layers.sh OBJDIR
#
# OBJDIR is a build's object tree (build/obj).  Each object file belongs
# to a layer, bottom up: src/geom, src/mesh, src/delete, src/wrap,
# variants, src/*.c (the API), src/cli.  For every global symbol an object
# uses (nm -u), the layer that defines it must be the object's own or one
# below it.  Prints `ok layers` or `FAIL layers` with each upward edge
# (caller object -> symbol, defined in layer), and exits non-zero on one.
set -u
obj=${1:-build/obj}
[ -d "$obj" ] || { echo "FAIL layers: $obj is not a directory"; exit 1; }

rank() {   # rank of the layer of object path $1 (relative to $obj)
    case "$1" in
        src/geom/*) echo 0 ;; src/mesh/*) echo 1 ;; src/delete/*) echo 2 ;;
        src/wrap/*) echo 3 ;; variants/*) echo 4 ;; src/cli/*) echo 6 ;;
        src/cgal/*) echo 0 ;; src/*) echo 5 ;; *) echo -1 ;;
    esac
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# the objects of the sources there are now (a build dir may keep objects
# of files since moved or removed)
top=$(cd "$(dirname "$0")/.." && pwd)
(cd "$top" && find src variants -name '*.c' | sed 's/\.c$/.o/' | sort) | while read -r o; do
    [ -f "$obj/$o" ] && echo "$o"
done >"$tmp/objs"
while read -r o; do
    r=$(rank "$o")
    nm --defined-only -g "$obj/$o" | awk -v r="$r" -v o="$o" '$2 ~ /[TDBRC]/ { print $3, r, o }'
done <"$tmp/objs" | sort >"$tmp/defs"
while read -r o; do
    r=$(rank "$o")
    nm -u "$obj/$o" | awk -v r="$r" -v o="$o" '{ print $2, r, o }'
done <"$tmp/objs" | sort >"$tmp/uses"
join "$tmp/uses" "$tmp/defs" | awk '$2 < $4 && $3 != $5 { printf "  %s -> %s (defined in %s)\n", $3, $1, $5 }' >"$tmp/up"
# and the headers: a file may include only headers of its layer or below
(cd "$top" && grep -n '^#include "[a-z]*/' $(find src variants -name '*.[ch]' | sort)) | while IFS= read -r line; do
    file=${line%%:*}
    inc=$(echo "$line" | sed 's/.*#include "\([a-z]*\)\/.*/\1/')
    from=$(rank "$file")
    to=$(rank "src/$inc/x.o")
    [ "$inc" = datasets ] && to=6
    [ "$to" -gt "$from" ] && echo "  $file includes $inc/ (a layer above)"
done >>"$tmp/up"
if [ -s "$tmp/up" ]; then
    echo "FAIL layers: upward calls between src/ folders (docs/architecture.md)"
    cat "$tmp/up"
    exit 1
fi
echo "ok layers"
