#!/bin/sh
# The reference runs in the background of a work period (docs/results.md, How the runs are made):
# two runners at nice 19, each working through the rounds of results/run.sh in order, one thread
# each, and stopped at a checkpoint before the runs are shipped.
#   sh results/runners.sh start AMORPH DIR   starts them; AMORPH and run.sh are copied to
#                                            DIR/.runners first, so that a rebuild or an edit while
#                                            they go changes nothing
#   sh results/runners.sh status DIR         each runner: going or not, and its log's last line
#   sh results/runners.sh stop DIR           SIGTERM to each runner's process group (the loop ends
#                                            at once, run.sh when its amorph has; amorph evolve
#                                            finishes its running evaluation, brings the checkpoint
#                                            up to its last whole generation and ends, as on
#                                            Ctrl-C), then waits until all have ended
# (SIGTERM, not SIGINT: a background job of a shell without job control ignores SIGINT, so the
# shells would go on to the next run.)
# The rounds (RUNNER_STAGES overrides them): fig6-1000 fig6-2000 others-2000 fig6-3000 fig6-4000
# fig6-5000 full-20000. Both runners take the same rounds: run.sh lets two share a stage (a run
# folder the other is working in is skipped), so all the runs of a round reach its count before
# any goes beyond it. Each runner's log is DIR/.runners/runner-K.log; its process group is in
# runner-K.pid. RUNNERS sets how many (2: one a core of the 2-core VMs); STOP_WAIT how long stop
# waits (300 s).
# A runner that is going is not started twice; start after stop resumes every run exactly.
set -eu
STAGES=${RUNNER_STAGES:-fig6-1000 fig6-2000 others-2000 fig6-3000 fig6-4000 fig6-5000 full-20000}
N=${RUNNERS:-2}
HERE=$(cd "$(dirname "$0")" && pwd)
usage() { echo "usage: sh results/runners.sh start AMORPH DIR | status DIR | stop DIR" >&2; exit 2; }
[ $# -ge 1 ] || usage
cmd=$1
shift
case $cmd in
start) [ $# -eq 2 ] || usage; AMORPH=$1 DIR=$2 ;;
status | stop) [ $# -eq 1 ] || usage; DIR=$1 ;;
*) usage ;;
esac
case $N in '' | *[!0-9]* | 0) echo "runners.sh: RUNNERS='$N': a whole number from 1" >&2; exit 2 ;; esac
WAIT=${STOP_WAIT:-300}
case $WAIT in '' | *[!0-9]*) echo "runners.sh: STOP_WAIT='$WAIT': a whole number of seconds" >&2; exit 2 ;; esac
R=$DIR/.runners

# going K: 0 when runner K's process group has a process left
going() {
    [ -f "$R/runner-$1.pid" ] || return 1
    pg=$(cat "$R/runner-$1.pid")
    case $pg in '' | *[!0-9]*) return 1 ;; esac
    kill -0 "-$pg" 2>/dev/null
}

case $cmd in
start)
    [ -x "$AMORPH" ] || { echo "runners.sh: $AMORPH: not an executable" >&2; exit 2; }
    [ -d "$DIR" ] || { echo "runners.sh: $DIR: no such folder" >&2; exit 2; }
    command -v setsid >/dev/null || { echo "runners.sh: setsid (util-linux) is needed to stop the runners at a checkpoint" >&2; exit 2; }
    mkdir -p "$R"
    k=1
    while [ "$k" -le "$N" ]; do
        if going "$k"; then
            echo "runners.sh: runner $k is going already (process group $(cat "$R/runner-$k.pid"))" >&2
            exit 1
        fi
        k=$((k + 1))
    done
    # copies of the program and of run.sh: a rebuild or an edit leaves the runs on what they
    # started with
    cp "$AMORPH" "$R/amorph.new"
    mv "$R/amorph.new" "$R/amorph"
    cp "$HERE/run.sh" "$R/run.sh.new"
    mv "$R/run.sh.new" "$R/run.sh"
    k=1
    while [ "$k" -le "$N" ]; do
        # its own session, so its process group (the loop, run.sh and amorph) can be stopped whole;
        # the loop writes its pid, the group's, itself (setsid may have forked to lead it)
        rm -f "$R/runner-$k.pid"
        # shellcheck disable=SC2016 # the loop's own $$ and arguments, expanded by the inner sh
        nice -n 19 setsid sh -c 'echo $$ >"$5.new" && mv "$5.new" "$5" || exit 1
            for st in $1; do sh "$2/run.sh" "$3" "$4" "$st" || exit 1; done
            echo "$(date -u +%FT%TZ) all rounds done"' \
            runner "$STAGES" "$R" "$R/amorph" "$DIR" "$R/runner-$k.pid" >>"$R/runner-$k.log" 2>&1 </dev/null &
        t=0
        while [ ! -s "$R/runner-$k.pid" ]; do
            [ "$t" -lt 100 ] || { echo "runners.sh: runner $k did not start (its log: $R/runner-$k.log)" >&2; exit 1; }
            sleep 0.1 2>/dev/null || sleep 1
            t=$((t + 1))
        done
        echo "runner $k: process group $(cat "$R/runner-$k.pid") (log $R/runner-$k.log)"
        k=$((k + 1))
    done
    ;;
status)
    k=1
    while [ "$k" -le "$N" ]; do
        last=$(tail -n 1 "$R/runner-$k.log" 2>/dev/null || true)
        if going "$k"; then echo "runner $k: going: $last"; else echo "runner $k: not going: $last"; fi
        k=$((k + 1))
    done
    ;;
stop)
    k=1
    while [ "$k" -le "$N" ]; do
        if going "$k"; then kill -TERM "-$(cat "$R/runner-$k.pid")" 2>/dev/null || true; fi
        k=$((k + 1))
    done
    # an evaluation finishes in seconds (an unsettled body's relaxation, the longest, well under a
    # minute on the 2-core VMs); STOP_WAIT seconds at the most
    t=0
    while :; do
        left=0
        k=1
        while [ "$k" -le "$N" ]; do
            if going "$k"; then left=$((left + 1)); fi
            k=$((k + 1))
        done
        [ "$left" -gt 0 ] || break
        if [ "$t" -ge "$WAIT" ]; then
            echo "runners.sh: $left runner(s) still going after $WAIT s" >&2
            exit 1
        fi
        sleep 1
        t=$((t + 1))
    done
    echo "runners stopped"
    ;;
esac
