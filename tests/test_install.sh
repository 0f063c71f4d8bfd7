#!/bin/sh
# make install into a temporary prefix, then the README's example program
# (the C block between its example:begin/end markers) built against the
# installed copy with pkg-config, once shared and once static, as a user
# would.  Its output must be the installed CLI's canonical form of the
# cube corners (the example deletes the centre), and its refusal of
# vertex 42 must reach stderr.  Prints ok/FAIL lines.
REL=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

if ! make -C "$top" --no-print-directory -s install-lib PREFIX="$prefix" B="$REL" >"$tmp/log" 2>&1; then
    echo "FAIL install/make-install: $(tail -c 400 "$tmp/log")"
    exit 1
fi
missing=""
for f in bin/dtdel include/dtdel.h include/dtdel_stats.h lib/libdtdel.a lib/libdtdel.so lib/pkgconfig/dtdel.pc; do
    [ -e "$prefix/$f" ] || missing="$missing $f"
done
so=$(readlink "$prefix/lib/libdtdel.so")
[ -n "$so" ] && [ -L "$prefix/lib/$so" ] && [ -f "$prefix/lib/$(readlink "$prefix/lib/$so")" ] || missing="$missing lib/libdtdel.so.N.x.y"
if [ -z "$missing" ]; then echo "ok install/files"; else echo "FAIL install/files: missing$missing"; fi

export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
ver=$(pkg-config --modversion dtdel)
want=$(sed -n 's/^#define DD_VERSION_\(MAJOR\|MINOR\|PATCH\) *\([0-9]*\).*/\2/p' "$top/src/dtdel.h" | paste -sd.)
if [ "$ver" = "$want" ] && pkg-config --libs dtdel | grep -q -- "-L$prefix/lib" &&
   pkg-config --cflags dtdel | grep -q -- "-I$prefix/include"; then
    echo "ok install/pkg-config"
else
    echo "FAIL install/pkg-config: version '$ver' (want $want), libs '$(pkg-config --libs dtdel)'"
fi

sed -n '/<!-- example:begin -->/,/<!-- example:end -->/p' "$top/README.md" | sed '/^<!--/d; /^```/d' >"$tmp/example.c"
grep -q "int main" "$tmp/example.c" || { echo "FAIL install/readme-example: no example between the markers"; exit 1; }
printf '0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n' >"$tmp/cube.xyz"
"$prefix/bin/dtdel" tets "$tmp/cube.xyz" >"$tmp/want" || echo "FAIL install/cli: the installed dtdel fails"

# run_example NAME: runs $tmp/NAME, compares its output with the CLI's
run_example() {
    "$tmp/$1" >"$tmp/$1.out" 2>"$tmp/$1.err"
    rc=$?
    if [ $rc -ne 0 ]; then
        echo "FAIL install/example-$1: exit $rc: $(head -c 300 "$tmp/$1.err")"
    elif ! cmp -s "$tmp/$1.out" "$tmp/want" || [ ! -s "$tmp/want" ]; then
        echo "FAIL install/example-$1: output differs from dtdel tets of the cube"
    elif ! grep -q "dd_delete: no point 42" "$tmp/$1.err"; then
        echo "FAIL install/example-$1: stderr lacks the refusal of 42: $(head -c 300 "$tmp/$1.err")"
    else
        echo "ok install/example-$1"
    fi
}

CC=${CC:-cc}
# shared: it must load the installed libdtdel.so.N
if $CC -Wall -Wextra -Werror "$tmp/example.c" $(pkg-config --cflags --libs dtdel) -o "$tmp/shared" 2>"$tmp/cc.err"; then
    if LD_LIBRARY_PATH="$prefix/lib" ldd "$tmp/shared" | grep -q "$prefix/lib/libdtdel.so"; then
        LD_LIBRARY_PATH="$prefix/lib" run_example shared
    else
        echo "FAIL install/example-shared: does not load $prefix/lib's libdtdel.so"
    fi
else
    echo "FAIL install/example-shared: does not build: $(head -c 300 "$tmp/cc.err")"
fi
# static: no libdtdel.so needed at run time
if $CC -static -Wall -Wextra -Werror "$tmp/example.c" $(pkg-config --static --cflags --libs dtdel) -o "$tmp/static" \
       2>"$tmp/cc.err"; then
    if ldd "$tmp/static" 2>&1 | grep -q "libdtdel"; then
        echo "FAIL install/example-static: linked against libdtdel.so"
    else
        run_example static
    fi
else
    echo "FAIL install/example-static: does not build: $(head -c 300 "$tmp/cc.err")"
fi
