#!/bin/sh
# tools/stack.sh BUILD [ROOT]: worst-case stack depth of a build compiled with
#   -fstack-usage -fcallgraph-info=su   (make stack does this)
# from GCC's per-function frame sizes and call graph (BUILD/**/*.ci).
# Method: frame(f) is GCC's static frame size; depth(f) = frame(f) + the deepest depth among f's
# callees. An indirect call (through a function pointer: the command table, the parallel map's
# task, the genotype operation tables) may reach any function nobody calls directly, so it costs
# the deepest of those. Callbacks are told apart by name and an indirect call reaches only its
# own kind (genotype operations, the parallel map task, am_text flush functions, the line
# functions of tool_src_each, the writers of write_stream). Library functions (libc, libgcc) have no frame figure here and count 0: the
# figure is amorph's own stack, the C library's frames (printf) come on top.
# Prints the largest frames, then the deepest chain from ROOT (default main) with its sum.
BUILD=${1:?usage: tools/stack.sh BUILD [ROOT]}
ROOT=${2:-main}
files=$(find "$BUILD" -name '*.ci' | sort)
[ -n "$files" ] || { echo "stack: no .ci files under $BUILD (build with -fcallgraph-info=su)"; exit 1; }
cat $files | awk -v root="$ROOT" '
function q(s) { sub(/^"/, "", s); sub(/"$/, "", s); return s }
/^node:/ {
    t = $0; sub(/.*title: /, "", t); sub(/ label:.*/, "", t); t = q(t)
    l = $0; sub(/.*label: "/, "", l); sub(/".*/, "", l)
    if (match(l, /[0-9]+ bytes/)) {
        b = substr(l, RSTART, RLENGTH); sub(/ bytes/, "", b); frame[t] = b + 0; defined[t] = 1
        if (match(l, /bytes \([a-z,]+\)/)) { qual[t] = substr(l, RSTART + 6, RLENGTH - 6); if (qual[t] ~ /dynamic/) dyn[t] = 1 }
        n = split(l, parts, "\\\\n"); where[t] = parts[2]
    }
    next
}
/^edge:/ {
    s = $0; sub(/.*sourcename: /, "", s); sub(/ targetname:.*/, "", s); s = q(s)
    d = $0; sub(/.*targetname: /, "", d); sub(/ label:.*/, "", d); sub(/ }.*/, "", d); d = q(d)
    if (!((s, d) in seen)) { seen[s, d] = 1; ne[s]++; to[s, ne[s]] = d; if (d != "__indirect_call") called[d] = 1 }
    next
}
# the kind of callback a function is, or of callback an indirect call site takes: a genotype
# operation (the tables of src/geno/geno_dct.c, geno_cppn.c, geno_gmx.c, called by the am_genome_
# functions), the task of the parallel map, an am_text flush function (called by
# base_text.c:drain, or the am_text functions it is inlined into), a line function of
# tool_src_each (or its callers it is inlined into), a writer of cmd_evolve.c:write_stream, a
# whole-text writer of am_text_format (the write_ adapters of the genome, configuration and
# checkpoint formats), the fields of a summary for write_summaries (put_*), the frame sink of the recorder
# (the sink of am_record_frame, tools/trajectory.c), the hooks of an evolution run (its cancel
# test and its per-evaluation record, tools/cmd_evolve.c), the executor of the evolver (its map
# and clock, tools/executor.c), a row function of tool_log_each (plot, report, stats);
# any other indirect call may reach any function of kind "other"
# the name of a function without the suffixes of the clones GCC makes (.part.0, .constprop.0, .isra.0)
function base(f) { sub(/(\.(part|constprop|isra|cold)\.[0-9]+)+$/, "", f); return f }
function kind_of(c) {
    c = base(c)
    if (c ~ /^src\/geno\/geno_(dct|cppn|gmx)\.c:/) return "geno"
    if (c ~ /_task$/) return "task"
    if (c ~ /(_flush|am_text_drop)$/) return "flush"
    if (c ~ /^tools\/.*_line$/) return "line"
    if (c ~ /_writer$/) return "writer"
    if (c ~ /^src\/(evo\/evo_config|geno\/geno_format|io\/io_checkpoint)\.c:write_/) return "textwriter"
    if (c ~ /(^|:)put_[a-z_]+$/) return "put"
    if (c ~ /(^|:)traj_row$/) return "sink"
    if (c ~ /(^|:)(run_cancel|evals_append)$/) return "hook"
    if (c ~ /(^|:)(port_map|port_now)$/) return "exec"
    if (c ~ /(^|:)(plot_log_row|report_row|log_row)$/) return "logrow"
    return "other"
}
function site_of(f) {
    f = base(f)
    if (f ~ /^(am_genome_|src\/geno\/(geno_format|geno_common|geno_levelset)\.c:)/) return "geno"
    if (f ~ /(am_port_parallel_map|am_[a-z0-9]+_parallel_map|map_loop|map_thread)$/) return "task"
    if (f ~ /(base_text\.c:drain|:ck_flush|^am_text_(put|vput|write|flush))$/) return "flush"
    if (f ~ /(^|:)tool_src_each$/ || f ~ /^tool_(read_config|read_genome|genome_to_lattice|load_robot)$/) return "line"
    if (f ~ /:write_stream$/) return "writer"
    if (f ~ /(^|:)am_text_format$/) return "textwriter"
    if (f ~ /(^|:)write_summaries$/) return "put"
    if (f ~ /(^|:)(am_record_frame|record_extra|am_evaluate)$/) return "sink" # record_extra is inlined into am_evaluate
    if (f ~ /(^|:)(eval_task|am_evo_batch_end)$/) return "hook"
    if (f ~ /(^|:)(generations|map_items|clock_of|am_evo_generations?)$/) return "exec" # the executor of the evolver (map, clock)
    if (f ~ /(^|:)log_each_line$/) return "logrow" # the row function of tool_log_each
    return "other"
}
# the deepest callee of an indirect call made by f: a command (cmd_*) when f is the root, else
# any other function nobody calls directly of the kind the call site takes; a function already
# on the chain is never re-entered
function indirect(f,   c, d, best, site) {
    best = 0; ibest[f] = ""; site = site_of(f)
    for (c in cand) {
        if (onpath[c] || ((f == root) != (c ~ /^cmd_/))) continue
        if (f != root && kind_of(c) != site) continue
        d = depth(c); if (d > best) { best = d; ibest[f] = c }
    }
    return best
}
function depth(f,   i, d, best, c) {
    if (f in memo) return memo[f]
    if (onpath[f]) { cycle = cycle " " f; return 0 }
    onpath[f] = 1; best = 0; bestc[f] = ""
    for (i = 1; i <= ne[f]; i++) {
        c = to[f, i]
        d = (c == "__indirect_call") ? indirect(f) : depth(c)
        if (d > best) { best = d; bestc[f] = (c == "__indirect_call") ? "*" ibest[f] : c }
    }
    onpath[f] = 0
    memo[f] = frame[f] + best
    return memo[f]
}
END {
    for (f in defined) if (!(f in called) && f != root && f !~ /(am_reset|on_[a-z_]+|_init|_fini)$/) cand[f] = 1
    total = depth(root)
    printf "largest frames (bytes):\n"
    cmd = "sort -rn | head -n 12"
    for (f in defined) printf "%8d  %s  %s%s\n", frame[f], f, where[f], (f in dyn) ? " " qual[f] : "" | cmd
    close(cmd)
    printf "\ndeepest chain from %s (* = reached through a function pointer):\n", root
    f = root; n = 0
    while (f != "" && n++ < 100) {
        ind = (f ~ /^\*/); if (ind) f = substr(f, 2)
        printf "%8d  %s%s%s\n", frame[f], ind ? "* " : "", f, (f in defined) ? "" : " (library: not counted)"
        f = bestc[f]
    }
    printf "stack_worst_case_bytes=%d (amorph code only; C library frames come on top)\n", total
    if (cycle != "") printf "warning: call cycle (recursion) through:%s\n", cycle
}'
