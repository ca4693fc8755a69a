#!/bin/sh
# The per-robot figures of docs/results.md, from the run folders results/run.sh makes:
#   sh results/report.sh AMORPH DIR [--pictures]
# For each run folder DIR/EXPERIMENT/RUN (config.txt, log.csv, best.genome) it writes
# RUN/gait30.json, the best robot simulated in the run's settings over 30 actuation cycles instead
# of the evolved 10 (`amorph sim RUN --cycles 30 --json`: travel per cycle, sustained, airborne,
# the gait's name, the material mix), and with --pictures RUN/best.png, its filmstrip over the
# evolved cycles (`amorph render --keep-same`, 1200 x 300 pixels: a file already holding the same
# pixels stays as it is, so git sees no change for a robot that did not change). Then it prints
# Markdown: a table with a row per run (evaluations done, best fitness, voxels and the material
# mix, the 30-cycle gait); the filmstrips to show (of each representation or other experiment and
# each gait, the furthest best, linked to its best.png); the Figure 6 table, the mean +- standard
# error of the best fitness so far of each representation's runs (DIR/representations/<rep>-<k>)
# every 500 evaluations, over the runs that reached them, and each run's best so far every 1,000; the mean size of the bodies
# each representation evaluated, every 500 evaluations; the statistics of amorph stats (the
# representations compared by Welch's t-test and the Mann-Whitney test at every 1,000 evaluations
# all the runs of each have reached,
# and on the sustained score of the best robots, cycles 11-30 of gait30.json, with their gaits,
# at the largest multiple of 1,000 that every run at 1,000 or more has reached: a run beyond it
# at its best robot then, best-N.genome, into gait30-N.json);
# the other experiments' runs, each at 2,000 evaluations (OTHERS_EVALS)
# against the range of the GMX runs (the seed's settings) at that count; and the compute each run
# took (the sum of log.csv's wall_s), and each round (per group and experiment, every 1,000
# evaluations). With --pictures it also draws DIR/representations/fitness.svg
# (`amorph plot`: the seed's Figure 6 from the runs that have reached FIG6_MIN_EVALS evaluations,
# 2,000 unless set, or from every run when none has), DIR/actuation/fitness.svg (the actuation
# experiment's variants, from the runs that have reached ACT_EVALS), DIR/others.svg (every other experiment's runs
# against the mean of the GMX runs, the seed's settings, to OTHERS_EVALS) and DIR/gaits.svg (each
# best robot's travel in each of its 30 cycles, a row per run).
# The numbers of log.csv come from the program (`amorph report last`, `fig6`, `compute`, `best-at`,
# `range`, `bodies` and `amorph stats`); this script calls it and assembles the page.
# The files are deterministic (gait30.json leaves out the wall time): the same run folders give
# the same files on every float build.
set -eu
AMORPH=$1 DIR=$2 PICTURES=${3:-}
[ -x "$AMORPH" ] || { echo "report.sh: $AMORPH: not an executable" >&2; exit 2; }
[ -d "$DIR" ] || { echo "report.sh: $DIR: no such folder" >&2; exit 2; }

# json FILE KEY: a number or string field of a one-line JSON object
json() { sed -n "s/.*\"$2\": *\"\{0,1\}\([^\",]*\)\"\{0,1\}[,}].*/\1/p" "$1"; }
# jarr FILE KEY: an array field, its items separated by spaces, strings unquoted
jarr() { sed -n "s/.*\"$2\": *\[\([^]]*\)\].*/\1/p" "$1" | tr -d '"' | sed 's/, */ /g'; }

echo "| run | evaluations | best fitness (m) | voxels | material mix | gait (30 cycles) | travel per cycle, first / last half (mm) | sustained | airborne |"
echo "|---|---:|---:|---:|---|---|---:|---:|---:|"
shown=
for cfg in "$DIR"/*/*/config.txt; do
    [ -f "$cfg" ] || continue
    run=${cfg%/config.txt}
    [ -f "$run/best.genome" ] || continue
    name=${run#"$DIR"/}
    last=$("$AMORPH" report last "$run") || exit 1 # "EVALUATIONS BEST" of the last generation logged
    evals=${last% *} best=${last#* }
    "$AMORPH" sim "$run" --cycles 30 --json 2>/dev/null | sed 's/"wall_seconds": [^,]*, //' >"$run/gait30.json"
    if [ "$PICTURES" = "--pictures" ]; then
        "$AMORPH" render "$run" --width 1200 --height 300 --keep-same --out "$run/best.png" >/dev/null
    fi
    g=$run/gait30.json
    names=$(jarr "$g" materials)
    counts=$(jarr "$g" material_voxels)
    mix=$(echo "$names" "|" "$counts" | awk -F'|' '{ n = split($1, a, " "); split($2, b, " "); s = "";
        for (i = 1; i <= n; i++) s = s (i > 1 ? ", " : "") a[i] " " b[i]; print s }')
    first=$(json "$g" travel_first_half)
    last=$(json "$g" travel_last_half)
    printf '| %s | %s | %.4f | %s | %s | %s | %.2f / %.2f | %.2f | %.2f |\n' "$name" "$evals" "$best" "$(json "$g" voxels)" \
        "$mix" "$(json "$g" gait)" "$(echo "$first" | awk '{ print $1 * 1000 }')" "$(echo "$last" | awk '{ print $1 * 1000 }')" \
        "$(json "$g" sustained)" "$(json "$g" airborne)"
    shown="$shown$name $evals $best $(json "$g" gait) $(json "$g" sustained) $([ -f "$run/best.png" ] && echo 1 || echo 0)
"
done

# the filmstrips the page shows: of each group (a Figure 6 representation, or another experiment
# whole) and each gait its best robots have, the run whose best travelled furthest (the first in
# the table above on a tie), with its filmstrip when the run has one (--pictures), linked as
# ../FOLDER/RUN/best.png: right from DIR/report.md and, DIR being results/, from docs/
echo
echo "| group | gait | furthest best | evaluations | best fitness (m) | sustained | filmstrip |"
echo "|---|---|---|---:|---:|---:|---|"
printf '%s' "$shown" | awk -v top="${DIR%/}" '
    BEGIN { sub(/.*\//, "", top); ng = split("still flop scoot bounce roll", G, " ") }
    NF == 6 {
        grp = $1; sub(/\/.*/, "", grp)
        if (grp == "representations") { grp = $1; sub(/-[0-9]+$/, "", grp) }
        if (!(grp in seen)) { seen[grp] = 1; order[++n] = grp }
        k = grp SUBSEP $4
        if (!(k in run) || $3 + 0 > fit[k]) { run[k] = $1; evals[k] = $2; fit[k] = $3 + 0; sus[k] = $5; png[k] = $6 }
    }
    END {
        for (i = 1; i <= n; i++) for (j = 1; j <= ng; j++) {
            k = order[i] SUBSEP G[j]
            if (!(k in run)) continue
            pic = png[k] ? sprintf("![best robot of %s](../%s/%s/best.png)", run[k], top, run[k]) : "(not drawn)"
            printf "| %s | %s | %s | %d | %.4f | %.2f | %s |\n", order[i], G[j], run[k], evals[k], fit[k], sus[k], pic
        }
    }'

# Figure 6: best fitness so far (m) at every 500 evaluations, mean +- standard error over the runs
# of each representation that reached it, (n) the number of those runs; then each run's best so
# far at every 1,000 evaluations it reached, the runs behind the means
set --
for log in "$DIR"/representations/*-[0-9]*/log.csv; do [ -f "$log" ] && set -- "$@" "${log%/log.csv}"; done
if [ $# -gt 0 ]; then
    echo
    "$AMORPH" report fig6 "$@" || exit 1
fi

# statistics (amorph stats; docs/results.md, Statistics): at every 1,000 evaluations that all the
# runs of a representation have reached, each representation's best fitness so far and each pair
# compared by Welch's t-test and the Mann-Whitney test, with Cohen's d, Hedges' g and the runs a
# group needs for 80% power, then the ranking with the differences each test finds at 0.05; then,
# when every run has its gait30.json, the same on the sustained score of the best robots (travel
# per cycle over cycles 11-30) with each representation's gaits
stats_tables() {
    err=$(mktemp)
    if out=$("$AMORPH" stats "$@" 2>"$err"); then rm -f "$err"
    else cat "$err" >&2; rm -f "$err"; exit 1; fi
    [ -z "$out" ] || printf '\n%s\n' "$out"
}
set --
for d in "$DIR"/representations/*-[0-9]*; do [ -f "$d/log.csv" ] && set -- "$@" "$d"; done
if [ $# -gt 0 ]; then
    stats_tables "$@"
    all=1
    for d in "$@"; do [ -f "$d/gait30.json" ] || all=0; done
    # the sustained score of the best robots at one count, SUS_AT: the largest multiple of 1,000
    # that every run of 1,000 evaluations or more has reached (every run, at its best as it
    # stands, when none has reached 1,000). A run just started (its best of a few generations) is
    # left out; a run beyond SUS_AT is compared at its best robot then, best-SUS_AT.genome (kept
    # by run.sh at the end of each round), simulated in the run's settings into
    # gait30-SUS_AT.json; a run beyond it without one, at its best as it stands
    counts=$(for d in "$@"; do last=$("$AMORPH" report last "$d") || exit 1; echo "${last% *}"; done) || exit 1
    SUS_AT=$(echo "$counts" | awk '$1 >= 1000 && (m == "" || $1 < m) { m = $1 } END { print m == "" ? 0 : int(m / 1000) * 1000 }')
    if [ $all = 1 ]; then
        sus=$(mktemp -d)
        trap 'rm -rf "$sus"' EXIT
        n=$# i=0
        for d in "$@"; do
            rm -f "$d"/gait30-[0-9]*.json
            i=$((i + 1))
            e=$(echo "$counts" | sed -n "${i}p") # the run's count, read above
            [ "$e" -ge "$SUS_AT" ] || continue
            g=$d/gait30.json
            if [ "$e" -gt "$SUS_AT" ] && [ -f "$d/best-$SUS_AT.genome" ]; then
                g=$d/gait30-$SUS_AT.json
                "$AMORPH" sim "$d" --genome "$d/best-$SUS_AT.genome" --cycles 30 --json 2>/dev/null |
                    sed 's/"wall_seconds": [^,]*, //' >"$g"
            fi
            # amorph stats reads RUN/gait30.json, and groups the runs by their folders' names
            mkdir -p "$sus/${d##*/}"
            cp "$g" "$sus/${d##*/}/gait30.json"
            set -- "$@" "$sus/${d##*/}"
        done
        shift "$n"
        stats_tables --score sustained "$@"
        rm -rf "$sus"
        trap - EXIT
    fi
fi

# body size: the mean voxels of the bodies each representation evaluated in each window of 500
# evaluations (evals.csv.gz of every run; the workspace holds 8,000), the seed's "CPPN fills the
# workspace" in numbers
set --
for f in "$DIR"/representations/*-[0-9]*/evals.csv.gz; do [ -f "$f" ] && set -- "$@" "${f%/evals.csv.gz}"; done
echo
if [ $# -gt 0 ]; then "$AMORPH" report bodies "$@" || exit 1
else echo "| evaluations | DCT voxels | CPPN voxels | GMX voxels |"; echo "|---:|---:|---:|---:|"; fi

# the other experiments: each run's best fitness after OTHERS_EVALS evaluations (2,000, their
# length) against the seed's settings at the same count, the GMX runs of Figure 6 (the
# representation and settings the other runs start from): their mean +- standard error and range,
# and whether the run is above, within or below that range; the settings a run changes are the
# lines of its config.txt that differ from representations/gmx-1's (but for the evaluations, the
# seed and the threads); the gait is its best robot's over 30 cycles (gait30.json)
n_at=${OTHERS_EVALS:-2000}
base=$DIR/representations/gmx-1/config.txt
if [ -f "$base" ]; then
    # the GMX runs' best fitness so far at n_at evaluations: runs, mean, standard error, range
    # (amorph report range), and each other run's (amorph report best-at: nothing before it got there)
    set --
    for log in "$DIR"/representations/gmx-[0-9]*/log.csv; do
        [ -f "$log" ] && set -- "$@" "${log%/log.csv}"
    done
    range=
    if [ $# -gt 0 ]; then range=$("$AMORPH" report range "$n_at" "$@") || exit 1; fi
    rows=$(for cfg in "$DIR"/*/*/config.txt; do
        case $cfg in "$DIR"/representations/* | "$DIR"/actuation/*) continue ;; esac
        [ -f "$cfg" ] || continue
        run=${cfg%/config.txt}
        b=$("$AMORPH" report best-at "$n_at" "$run") || exit 1
        [ -n "$b" ] || continue
        changed=$(awk -F' = ' 'NR == FNR { if (NF == 2) v[$1] = $2; next }
            NF == 2 && $1 != "evaluations" && $1 != "seed" && $1 != "threads" && v[$1] != $2 { s = s (s ? ", " : "") $1 "=" $2 }
            END { print s ? s : "the seed'"'"'s" }' "$base" "$cfg")
        where=$(echo "$b $range" | awk '{ print ($1 > $6 ? "above the range" : $1 < $5 ? "below the range" : "within the range") }')
        gait=""
        [ -f "$run/gait30.json" ] && gait=$(json "$run/gait30.json" gait)
        echo "| ${run#"$DIR"/} | $changed | $b | $where | $gait |"
    done)
    if [ -n "$range" ] && [ -n "$rows" ]; then
        echo
        echo "| run | settings | best fitness at $n_at evaluations (m) | against the seed's settings | gait (30 cycles) |"
        echo "|---|---|---:|---|---|"
        echo "$range" | awk '{ printf "| representations/gmx-* | the seed'"'"'s (GMX, %d run%s) | %.4f +- %.4f (%.4f to %.4f) | | |\n", $1, $1 == 1 ? "" : "s", $2, $3, $4, $5 }'
        echo "$rows"
    fi
fi

# the actuation experiment (results/run.sh actuation-N, docs/results.md): GMX and CPPN on a 10^3
# workspace, the seed's palette or the follow-up's four materials, global or evolved phase, and two
# of the follow-up's materials (its soft tissue and one muscle) with global phase. Per
# variant, over its runs that reached ACT_EVALS (2,000) evaluations: the best fitness then (mean
# +- standard error), the best robot's travel over 30 cycles in body lengths per cycle (the
# follow-up's measure: gait30.json's mean cycle travel over its body_length), its sustained travel
# (cycles 11-30, mm per cycle) and the gaits; then amorph stats on the planned pairs of variants
# (--pair), a family of Holm's correction per question, at every ACT_EVALS evaluations all their
# runs reached, and on the sustained score (the tables' first header cell says "actuation" and the
# family, so that they are not the Figure 6 ones)
a_at=${ACT_EVALS:-2000}
if [ -d "$DIR/actuation" ]; then
    rows=$(for v in gmx-seed-global gmx-two-global gmx-four-global gmx-seed-phase gmx-four-phase cppn-seed-global cppn-two-global cppn-four-global \
        cppn-seed-phase cppn-four-phase; do
        for run in "$DIR"/actuation/$v-[0-9]*; do
            [ -f "$run/log.csv" ] && [ -f "$run/gait30.json" ] || continue
            b=$("$AMORPH" report best-at "$a_at" "$run") || exit 1
            [ -n "$b" ] || continue
            g=$run/gait30.json
            echo "$v $b $(json "$g" body_length) $(json "$g" sustained_travel) $(json "$g" gait) $(jarr "$g" cycle_travel)"
        done
    done | awk '
        { v = $1; n[v]++; s[v] += $2; q[v] += $2 * $2; L = $3; t = 0; for (c = 6; c <= NF; c++) t += $c
          bl[v] += L > 0 ? t / (NF - 5) / L : 0; sus[v] += $4 * 1000; gait[v, $5]++; if (!(v in order)) order[v] = ++nv; name[order[v]] = v }
        END {
            for (i = 1; i <= nv; i++) {
                v = name[i]; m = s[v] / n[v]; sd = n[v] > 1 ? sqrt((q[v] - n[v] * m * m) / (n[v] - 1)) : 0
                gs = ""; split("still flop scoot bounce roll", G, " ")
                for (k = 1; k <= 5; k++) if (gait[v, G[k]]) gs = gs (gs ? ", " : "") G[k] " " gait[v, G[k]]
                se = n[v] > 1 ? sd / sqrt(n[v]) : 0
                printf "| actuation/%s | %d | %.4f +- %.4f | %.4f | %.3f | %s |\n", v, n[v], m, se, bl[v] / n[v], sus[v] / n[v], gs
            }
        }')
    if [ -n "$rows" ]; then
        echo
        echo "| variant | runs at $a_at evaluations | best fitness (m), mean +- standard error | body lengths per cycle (30 cycles) | sustained (mm per cycle) | gaits |"
        echo "|---|---:|---:|---:|---:|---|"
        echo "$rows"
        # the runs that reached ACT_EVALS (a run still short of it would hold its variant out of the
        # tests: amorph stats compares a group at the counts all its runs reached)
        set --
        for d in "$DIR"/actuation/*-[0-9]*; do
            [ -f "$d/log.csv" ] || continue
            b=$("$AMORPH" report best-at "$a_at" "$d") || exit 1
            [ -z "$b" ] || set -- "$@" "$d"
        done
        all=1
        for d in "$@"; do [ -f "$d/gait30.json" ] || all=0; done
        scores=best
        [ $all = 0 ] || scores="best sustained"
        # (through a variable: a failure of amorph stats ends the script, as it does above)
        acts=$(for score in $scores; do
            # each variant's numbers once (amorph stats's first table), then the planned comparisons,
            # a family for Holm's correction per question of the follow-up's, each pair of both
            # representations whose variants have runs: the count of materials (four against two of
            # the follow-up's), their properties (two of the follow-up's against the seed's two), both
            # together (four against the seed's, with global and with evolved phase), and evolved
            # against global phase (each palette). Their tables' first header cell names the family,
            # so that no two tables of the page are headed alike
            first=1
            for fam in count:four-global,two-global properties:two-global,seed-global \
                both:four-global,seed-global+four-phase,seed-phase phase:seed-phase,seed-global+four-phase,four-global; do
                pairs=
                for r in gmx cppn; do
                    for p in $(echo "${fam#*:}" | tr + ' '); do
                        a=$r-${p%,*} b=$r-${p#*,}
                        # both variants among the runs taken (a variant with none at ACT_EVALS is no group)
                        case " $* " in *"/actuation/$a-"[0-9]*) ;; *) continue ;; esac
                        case " $* " in *"/actuation/$b-"[0-9]*) pairs="$pairs --pair $a,$b" ;; esac
                    done
                done
                [ -n "$pairs" ] || continue
                # shellcheck disable=SC2086
                out=$(stats_tables --score $score --every "$a_at" $pairs "$@") || exit 1
                # table 1: the variants (the first family's call only); table 2: the family's pairs
                printf '%s\n' "$out" | awk -v first=$first 'NF && !t { n++; t = 1 } !NF { t = 0 } (n == 1 && first) || n == 2 || !NF' |
                    sed "s/^| evaluations | group |/| evaluations (actuation) | group |/; s/^| score | group |/| score (actuation) | group |/
                         s/^| evaluations | pair |/| evaluations (actuation: ${fam%%:*}) | pair |/; s/^| score | pair |/| score (actuation: ${fam%%:*}) | pair |/"
                first=0
            done
        done)
        printf '%s\n' "$acts" | cat -s
    fi
fi

# compute: hours of one thread per run, the sum of log.csv's wall_s. A generation that took more
# than 5 times the median of its window of 1,000 evaluations was paused (the runners are stopped
# while other work needs the machine, and a VM may be suspended): it counts as that median, and the
# last column says how many
set --
for log in "$DIR"/*/*/log.csv; do [ -f "$log" ] && set -- "$@" "${log%/log.csv}"; done
echo
comp=
if [ $# -gt 0 ]; then
    comp=$("$AMORPH" report compute --root "$DIR" "$@") || exit 1
    printf '%s\n' "$comp"
else echo "| run | evaluations | hours | paused generations |"; echo "|---|---:|---:|---:|"; fi

# the rounds left: results/run.sh's rounds in the runners' order (ROUNDS), each with its runs, those
# at its count, and what is left until it is complete from where the runs stand, every run taken to
# the largest count of the rounds up to it (so each row counts the rounds before it too):
# evaluations, and hours of one runner at each group's pace so far (the compute table's hours,
# log.csv's wall time, over the group's evaluations: the pace of runners that share the machine
# with a work period's builds and tests; a group not started yet at the GMX runs', the seed's
# settings, which the other experiments vary). run.sh's RUN_PLAN lists the runs and their counts
# without running any.
ROUNDS=${ROUNDS:-fig6-1000 fig6-2000 others-2000 fig6-3000 fig6-4000 fig6-5000 full-20000}
HERE=$(cd "$(dirname "$0")" && pwd)
if [ -f "$HERE/run.sh" ]; then
    plan=$(for st in $ROUNDS; do
        out=$(RUN_PLAN=1 sh "$HERE/run.sh" "$AMORPH" "$DIR" "$st") || exit 1
        printf '%s\n' "$out" | sed "s|^|$st |"
    done) || exit 1
    echo
    { printf '%s\n' "$comp"; echo "--"; printf '%s\n' "$plan"; } | awk -v dir="$DIR/" '
        # a group whose hours round to 0 (a few generations) is not measured yet either
        function rate(g) { return gh[g] > 0 ? gh[g] / ge[g] : gh["representations/gmx"] > 0 ? gh["representations/gmx"] / ge["representations/gmx"] : 0 }
        function flush(   r, left, hours, l) {
            if (cur == "") return
            left = 0; hours = 0
            for (r in T) { l = T[r] - D[r]; if (l > 0) { left += l; hours += l * rate(G[r]) } }
            printf "| %s | %d | %d | %d | %.1f |\n", cur, runs, at, left, hours
        }
        BEGIN { FS = "|"; part = 1
            print "| round | runs | at its count | evaluations left | runner-hours left |"; print "|---|---:|---:|---:|---:|" }
        $0 == "--" { part = 2; next }
        part == 1 {
            # the compute table: "| EXPERIMENT/RUN | EVALUATIONS | HOURS | PAUSED |"
            if (NF == 6 && $2 ~ /\// && $3 ~ /^ *[0-9]+ *$/) {
                r = $2; gsub(/ /, "", r); g = r; sub(/-[0-9]+$/, "", g); ge[g] += $3; gh[g] += $4
            }
            next
        }
        {
            split($0, w, " "); st = w[1]; f = w[2]
            if (index(f, dir) == 1) f = substr(f, length(dir) + 1)
            if (st != cur) { flush(); cur = st; runs = 0; at = 0 }
            g = f; sub(/-[0-9]+$/, "", g); G[f] = g
            D[f] = w[3] + 0
            if (!(f in T) || T[f] < w[4] + 0) T[f] = w[4] + 0
            runs++; if (w[3] + 0 >= w[4] + 0) at++
        }
        END { flush() }'
fi

if [ "$PICTURES" = "--pictures" ] && [ -d "$DIR/representations" ]; then
    # the runs that have reached FIG6_MIN_EVALS (2,000: the first stage of results/run.sh), so
    # that a run just started does not end its representation's mean where it stands; every run
    # when none has
    min=${FIG6_MIN_EVALS:-2000}
    fig6() {
        "$AMORPH" plot "$DIR/representations" --min-evals "$1" --out "$DIR/representations/fitness.svg" \
            --title "DCT, CPPN and GMX at 20^3: the runs with $1 evaluations or more"
    }
    fig6 "$min" >/dev/null 2>&1 || fig6 0 >/dev/null
    # actuation/fitness.svg: the actuation experiment's variants, the runs that reached ACT_EVALS
    # (every run when none has)
    if [ -d "$DIR/actuation" ]; then
        act() {
            "$AMORPH" plot "$DIR/actuation" --min-evals "$1" --out "$DIR/actuation/fitness.svg" \
                --title "bodies and actuation evolved together at 10^3: the runs with $1 evaluations or more"
        }
        act "$a_at" >/dev/null 2>&1 || act 0 >/dev/null
    fi
    # others.svg: every other experiment's runs against the GMX runs' mean and band (amorph plot's
    # DIR/VARIANT), up to the count their table compares them at; none when no other experiment has
    # runs (the GMX runs alone are Figure 6's)
    set --
    for d in three-materials dynamic friction; do [ -d "$DIR/$d" ] && set -- "$@" "$DIR/$d"; done
    if [ $# -gt 0 ]; then
        for g in "$DIR"/representations/gmx-*/log.csv; do [ -f "$g" ] && set -- "$DIR/representations/gmx" "$@"; break; done
        "$AMORPH" plot "$@" --max-evals "$n_at" --out "$DIR/others.svg" \
            --title "the other experiments against the GMX runs (the seed's settings)" >/dev/null
    fi
    # gaits.svg: a row per run, the travel of each of its best robot's 30 cycles as bars on one
    # scale, with its gait and sustained figure: a flop's bars stop, a scoot's go on
    for g in "$DIR"/*/*/gait30.json; do
        [ -f "$g" ] || continue
        run=${g%/gait30.json}
        echo "${run#"$DIR"/} $(json "$g" gait) $(json "$g" sustained) $(jarr "$g" cycle_travel)"
    done | awk '
        { name[NR] = $1; gait[NR] = $2; sus[NR] = $3; n[NR] = NF - 3
          for (c = 4; c <= NF; c++) { v[NR, c - 3] = $c * 1000; if ($c * 1000 > top) top = $c * 1000 } }
        END {
            if (NR == 0) exit
            if (top <= 0) top = 1
            W = 960; rowh = 54; left = 300; bw = (W - left - 20) / 30; H = 60 + NR * rowh
            printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H, W, H
            printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H
            printf "<text x=\"10\" y=\"20\" font-size=\"14\" font-weight=\"bold\">travel of the centre of mass in each of 30 actuation cycles (mm; bar height %.2f mm at the most)</text>\n", top
            for (r = 1; r <= NR; r++) {
                y0 = 40 + (r - 1) * rowh; base = y0 + rowh - 12
                printf "<text x=\"10\" y=\"%d\">%s</text>\n", y0 + 20, name[r]
                printf "<text x=\"10\" y=\"%d\" fill=\"#555\">%s, sustained %.2f</text>\n", y0 + 36, gait[r], sus[r]
                printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#999\"/>\n", left, base, W - 20, base
                for (c = 1; c <= n[r]; c++) {
                    hgt = v[r, c] / top * (rowh - 16); if (hgt < 0) hgt = 0
                    printf "<rect class=\"bar\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", left + (c - 1) * bw + 1, base - hgt, bw - 2, hgt, c <= 10 ? "#1f77b4" : "#9ecae1"
                }
            }
            printf "<text x=\"%d\" y=\"%d\" fill=\"#555\">dark: the 10 evolved cycles; light: the 20 after them</text>\n", left, H - 2
            print "</svg>"
        }' >"$DIR/gaits.svg.new" && mv "$DIR/gaits.svg.new" "$DIR/gaits.svg"
fi
