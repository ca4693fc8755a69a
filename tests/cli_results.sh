# tests/cli_results.sh: the reference runs shipped in results/ (docs/results.md) still give what
# they recorded: each run folder's best robot, simulated by `amorph sim DIR` in the run's own
# settings, ends in the recorded state hash (and, for a finished run, at the recorded fitness).
# A change to the simulator that moves a published result fails here, and must re-run or re-pin
# the results deliberately. Float desktop builds only (the runs are float, at 20^3). Run from the
# repository root.
. tests/shlib.sh

if ! "$AMORPH" --help 2>/dev/null | grep -q 'am_real=float' || ! "$AMORPH" --help 2>/dev/null | grep -q 'profile=desktop'; then
    echo "cli_results: not a float desktop build: the shipped results are not checked"
    summary cli_results
    exit $?
fi
n=0
for ck in results/*/*/checkpoint.txt; do
    [ -f "$ck" ] || continue
    d=${ck%/checkpoint.txt}
    [ -f "$d/best.genome" ] || continue
    n=$((n + 1))
    # the best individual's state hash: the summary's when the run is finished, else the checkpoint's
    if [ -f "$d/summary.txt" ]; then want=$(sumval "$d" best_state_hash); fit=$(sumval "$d" best_fitness)
    else want=$(awk '$1 == "individual" && $2 == "best" { print $9 }' "$ck"); fit=""; fi
    expect_ok "$AMORPH" sim "$d" --json
    got=$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/out")
    if [ -n "$want" ] && [ "$got" = "$want" ]; then ok
    else ko "$d: best robot ends in state $got, the run recorded $want"; fi
    if [ -n "$fit" ]; then
        got=$(sed -n 's/.*"fitness": \([-0-9.e+]*\).*/\1/p' "$TMPD/out")
        if [ "$got" = "$fit" ]; then ok; else ko "$d: best robot's fitness $got, the run recorded $fit"; fi
    fi
    # evals.csv, shipped compressed (results/ship.sh): a row per evaluation of the checkpoint, and
    # the fittest row is the best robot, with its state hash
    if [ -f "$d/evals.csv.gz" ]; then
        gzip -dc "$d/evals.csv.gz" >"$TMPD/evals.csv"
        rows=$(($(wc -l <"$TMPD/evals.csv") - 1))
        done_evals=$(awk '$1 == "evaluations" && NF == 2 { print $2; exit }' "$ck")
        if [ "$rows" = "$done_evals" ]; then ok; else ko "$d: evals.csv.gz holds $rows evaluations, the checkpoint $done_evals"; fi
        best_row=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "fitness") f = i; if ($i == "state_hash") h = i } next }
            f && (NR == 2 || $f + 0 > best) { best = $f + 0; hash = $h } END { print hash }' "$TMPD/evals.csv")
        if [ -n "$want" ] && [ "$best_row" = "$want" ]; then ok; else ko "$d: the fittest row of evals.csv.gz has state $best_row, the best robot $want"; fi
    fi
    # the best robot kept at a round's count (run.sh's best-N.genome; results/ship.sh simulated it
    # against evals.csv): at most the run's count, and the best robot itself while the run is there
    done_evals=$(awk '$1 == "evaluations" && NF == 2 { print $2; exit }' "$ck")
    for g in "$d"/best-[0-9]*.genome; do
        [ -f "$g" ] || continue
        at=${g##*/best-}
        at=${at%.genome}
        if [ "$at" -le "$done_evals" ]; then ok; else ko "$g: kept at $at evaluations, beyond the run's $done_evals"; fi
        if [ "$at" != "$done_evals" ] || cmp -s "$g" "$d/best.genome"; then ok; else ko "$g: the run is at $at evaluations, and its best.genome differs"; fi
    done
done
if [ $n -gt 0 ]; then ok; else ko "results/: no run folder found"; fi
# docs/results.md tells what the shipped runs show: every table row of results/report.md (which
# report.sh writes from the folders) stands in it word for word, so re-shipped runs cannot leave
# the page describing the runs before them
if [ -f results/report.md ]; then
    rows=0
    while IFS= read -r row; do
        case "$row" in "|"*) ;; *) continue ;; esac
        rows=$((rows + 1))
        if grep -qxF -- "$row" docs/results.md; then ok
        else ko "docs/results.md: lacks results/report.md's row '$row' (sh results/tables.sh copies report.md's tables into the page)"; fi
    done <results/report.md
    if [ $rows -gt 0 ]; then ok; else ko "results/report.md: no table row"; fi
    # and no row of an older report stays: a row that names a shipped run, a window of
    # evaluations, a round (fig6-2000) or the runs behind a mean is report.sh's, so it must be in
    # report.md
    grep -E '^\| ([a-z-]+/[^ |]+|[a-z0-9]+-[0-9]+) \||^\| [0-9]+ \|.*runs?\) \|' docs/results.md >"$TMPD/docrows" || true
    n_doc=0
    while IFS= read -r row; do
        n_doc=$((n_doc + 1))
        if grep -qxF -- "$row" results/report.md; then ok
        else ko "docs/results.md: row '$row' is not in results/report.md (an older report's?)"; fi
    done <"$TMPD/docrows"
    if [ $n_doc -gt 0 ]; then ok; else ko "docs/results.md: no row of report.sh's tables found"; fi
fi
# every link of the pages to a file of the repository (a filmstrip or plot of docs/results.md and
# results/report.md, another page) names one that is there, from the page's folder
nl=0
for page in README.md docs/*.md results/report.md; do
    [ -f "$page" ] || continue
    for target in $(grep -oE '\]\([^)# ]+\)' "$page" | sed 's/^](//; s/)$//' | grep -v '^[a-z][a-z]*:' | sort -u); do
        nl=$((nl + 1))
        if [ -e "$(dirname "$page")/$target" ]; then ok; else ko "$page: links to $target, which is not there"; fi
    done
done
if [ $nl -gt 0 ]; then ok; else ko "no link of the pages to a file found"; fi
summary cli_results
