#!/bin/sh
# Copies the tables of a report (results/report.md, which results/report.sh writes) into a page
# (docs/results.md): each table of the report replaces the table of the page that has the same
# header, rows and all; the prose around them is left as it is. Headers are compared without their
# numeric cells, so that a table with a column per 1,000 evaluations finds its older self.
#   sh results/tables.sh [REPORT [PAGE]]      (defaults: results/report.md docs/results.md)
# A report table the page does not have is an error (nothing is written then): a new table goes
# into the page by hand, with its text, the first time. tests/cli_results.sh then checks that the
# page and the report agree.
set -eu
REPORT=${1:-results/report.md} PAGE=${2:-docs/results.md}
for f in "$REPORT" "$PAGE"; do
    [ -f "$f" ] || { echo "tables.sh: $f: no such file" >&2; exit 2; }
done
tmp=$PAGE.tables.$$
trap 'rm -f "$tmp"' EXIT
awk -v report="$REPORT" -v page="$PAGE" '
    # a header without its numeric cells
    function key(h,    c, nc, i, k) {
        nc = split(h, c, "|"); k = ""
        for (i = 1; i <= nc; i++) if (c[i] !~ /^ *[0-9]+ *$/) k = k c[i] "|"
        return k
    }
    # the report: table t is lines head[t], sep[t], then body[t, 1..nb[t]]
    FNR == NR {
        if ($0 ~ /^\|/) {
            if (!intable) { nt++; head[nt] = $0; nb[nt] = -1; intable = 1 }
            else if (nb[nt] < 0) { sep[nt] = $0; nb[nt] = 0 }
            else body[nt, ++nb[nt]] = $0
        } else intable = 0
        next
    }
    { line[++n] = $0 }
    END {
        for (t = 1; t <= nt; t++) {
            if (nb[t] < 0) { printf "tables.sh: %s: the table headed \"%s\" has no separator line\n", report, head[t] > "/dev/stderr"; exit 1 }
            at = 0
            for (i = 1; i < n && !at; i++) if (key(line[i]) == key(head[t]) && line[i + 1] ~ /^\|[-:|]+\|$/) at = i
            if (!at) { printf "tables.sh: %s: no table headed \"%s\" (put it in by hand the first time)\n", page, head[t] > "/dev/stderr"; exit 1 }
            if (at in from) { printf "tables.sh: %s: two tables headed like \"%s\"\n", report, head[t] > "/dev/stderr"; exit 1 }
            from[at] = t
        }
        for (i = 1; i <= n; i++) {
            if (!(i in from)) { print line[i]; continue }
            t = from[i]
            print head[t]; print sep[t]
            for (k = 1; k <= nb[t]; k++) print body[t, k]
            i += 2
            while (i <= n && line[i] ~ /^\|/) i++
            i--
        }
    }' "$REPORT" "$PAGE" >"$tmp"
mv "$tmp" "$PAGE"
trap - EXIT
