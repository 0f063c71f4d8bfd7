#!/bin/sh
# test_make.sh -- `make -jN` on a fresh machine compiles nothing before the
# Debian packages are installed: every file the build makes (objects,
# archives, programs, test programs) has the deps stamp as a prerequisite.
# A dry run (make -n -p) into an empty build location, so nothing is
# built; the data base lists each target with its prerequisites.
# Prints "ok NAME" / "FAIL NAME: why" lines; exits 1 on a failure.
top=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok make/$1"; }
bad() { echo "FAIL make/$1: $2"; fail=1; }

x=$tmp/x
stamp=$x/.deps-stamp
vars="B=$x A=$x/asan K=$x/count F=$x/fuzz DEPS_STAMP=$stamp"
# every goal that make test, make bench and make fuzz build
goals=$(cd "$top" && make -s --no-print-directory $vars print-goals 2>/dev/null)
[ -n "$goals" ] || { bad goals "make print-goals listed nothing"; exit 1; }
(cd "$top" && make -n -p $vars $goals) >"$tmp/db" 2>"$tmp/err" ||
    { bad dry-run "make -n -p failed: $(head -c 300 "$tmp/err")"; exit 1; }

# the target lines of files the build makes (not the stamp itself)
grep -E "^$x/[^ :]+:" "$tmp/db" | grep -v "^$stamp:" | grep -v -E "^[^ :]+: [A-Za-z_]+ [:+?]?= " >"$tmp/targets"
n=$(wc -l <"$tmp/targets")
[ "$n" -ge 50 ] && ok "targets-seen" || bad targets-seen "only $n build targets in the data base"
missing=$(grep -v -F "| $stamp" "$tmp/targets" | grep -v -F " $stamp" | cut -d: -f1)
if [ -z "$missing" ]; then
    ok "every-target-waits-for-deps"
else
    bad every-target-waits-for-deps "no deps stamp prerequisite on: $(echo "$missing" | head -n 5 | tr '\n' ' ')"
fi
# the CGAL shim is the object that broke: named explicitly
grep -q -E "^$x/obj/src/cgal/cgal_shim.o:.*\| $stamp" "$tmp/targets" &&
    ok "cgal-shim-waits-for-deps" || bad cgal-shim-waits-for-deps "cgal_shim.o does not wait for the deps stamp"
# and the stamp is made by the deps script
grep -A12 "^$stamp:" "$tmp/db" | grep -q "scripts/deps.sh" &&
    ok "stamp-runs-deps" || bad stamp-runs-deps "the stamp's recipe does not run scripts/deps.sh"
exit $fail
