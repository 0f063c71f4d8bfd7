#!/bin/sh
# readme-table.sh TABLE [README] -- puts TABLE (results/readme-table.md,
# written by build/summarize) into README (default README.md) between its
# two marker lines
#     <!-- bench-table:begin -->
#     <!-- bench-table:end -->
# replacing what was there; the markers and every other line stay as they
# were.  Fails (exit 1), changing nothing, unless each marker is a whole
# line of its own exactly once, begin before end.  scripts/bench.sh runs
# it after each bench, so the README's table is the last run's.
begin='<!-- bench-table:begin -->'
end='<!-- bench-table:end -->'
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: readme-table.sh TABLE [README]" >&2
    exit 2
fi
table=$1
readme=${2:-README.md}
die() { echo "readme-table: $*" >&2; exit 1; }
[ -f "$table" ] && [ -r "$table" ] || die "cannot read the table $table"
[ -f "$readme" ] && [ -r "$readme" ] || die "cannot read $readme"
nb=$(grep -c -x -F -- "$begin" "$readme")
ne=$(grep -c -x -F -- "$end" "$readme")
[ "$nb" -eq 1 ] && [ "$ne" -eq 1 ] ||
    die "$readme must hold the line '$begin' once and the line '$end' once, as whole lines (found $nb and $ne); not changed"
lb=$(grep -n -x -F -- "$begin" "$readme" | cut -d: -f1)
le=$(grep -n -x -F -- "$end" "$readme" | cut -d: -f1)
[ "$lb" -lt "$le" ] || die "$readme: '$end' (line $le) comes before '$begin' (line $lb); not changed"
tmp=$(mktemp) || die "cannot create a temporary file"
trap 'rm -f "$tmp"' EXIT
# blank lines around the table: Markdown ends the comment's HTML block there
awk -v lb="$lb" -v le="$le" -v table="$table" '
    NR == lb {
        print; print ""
        while ((got = (getline line < table)) > 0) print line
        if (got < 0) exit 1
        print ""; next
    }
    NR > lb && NR < le { next }
    { print }' "$readme" >"$tmp" || die "cannot write the new $readme; not changed"
cat "$tmp" >"$readme" || die "cannot write $readme"
