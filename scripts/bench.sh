#!/bin/sh
# make bench / make bench-quick.  For now: the construction benchmark
# (dtdel against CGAL's range insert, same run), written to results/.
mode=${1:-full}
n=1000000
[ "$mode" = quick ] && n=200000
mkdir -p results
out=results/build.txt
{
    echo "# construction benchmark ($mode), $(date -u +%Y-%m-%dT%H:%MZ), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
    echo "# machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
    build/dtdel build-bench "$n"
} | tee "$out"
