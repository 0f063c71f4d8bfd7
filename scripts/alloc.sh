#!/bin/sh
# alloc.sh -- checks that the engine allocates only through dtdel/alloc.h.
#
#   scripts/alloc.sh [TOP]
#
# Every C source and header under TOP/src and TOP/variants, but src/cgal
# (the C++ shim, above the library) and src/dtdel/alloc.h itself (the
# wrappers), must call no malloc, calloc, realloc, free, strdup or
# strndup of the C library: dd_malloc, dd_calloc, dd_realloc and dd_mfree
# instead, so that a test build can fail any allocation (issue 46).
# Comments and string literals are stripped first (the compiler's
# -fpreprocessed pass, then a sed over "..." and '...'), so a word in a
# comment or a message is not a call.  Prints `ok alloc`, or `FAIL alloc`
# with each call, file:line, and exits non-zero on one.
set -u
top=${1:-$(cd "$(dirname "$0")/.." && pwd)}
CC=${CC:-gcc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/bad"
(cd "$top" && find src variants \( -name '*.c' -o -name '*.h' \) | grep -v '^src/cgal/' | grep -vx 'src/dtdel/alloc.h' | sort) >"$tmp/files"
[ -s "$tmp/files" ] || echo "  no source files under $top" >>"$tmp/bad"
while read -r f; do
    # -fpreprocessed -E: comments removed, nothing included or expanded;
    # -dD keeps the #defines (a macro may hide a call); line markers kept
    if ! "$CC" -fpreprocessed -dD -E -x c "$top/$f" >"$tmp/pp" 2>"$tmp/err"; then
        echo "  $f: cannot be read: $(head -n 1 "$tmp/err")" >>"$tmp/bad"
        continue
    fi
    awk -v f="$f" '
        /^# [0-9]+ / { line = $2 - 1; next }
        { line++
          s = $0
          gsub(/\\./, "", s)                 # escapes, so quotes pair up
          gsub(/"[^"]*"/, "\"\"", s)
          gsub(/\047[^\047]*\047/, "0", s)
          if (match(s, /(^|[^A-Za-z0-9_.>])(malloc|calloc|realloc|free|strdup|strndup)[ \t]*\(/))
              printf "  %s:%d: %s\n", f, line, $0 }' "$tmp/pp" >>"$tmp/bad"
done <"$tmp/files"
if [ -s "$tmp/bad" ]; then
    echo "FAIL alloc: raw allocation calls (use dtdel/alloc.h's dd_malloc, dd_calloc, dd_realloc, dd_mfree)"
    cat "$tmp/bad"
    exit 1
fi
echo "ok alloc"
