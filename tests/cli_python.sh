# tests/cli_python.sh: the Python module (tools/python/amorph.py, docs/embedding.md). Imported
# from another folder it finds the library (AMORPH_LIB, or the checkout's build/ beside it), and
# evaluates a genome and a lattice to amorph sim's fitness and hash; its crowding() (amorph's own run
# written over the ask/tell calls) ends with the best genome and fitness `amorph evolve` reaches
# with the same settings and seed, plain and with evolved phases; a bad setting and a missing
# library are one-line AmorphErrors. Skipped without python3 and in a sanitizer build (Python
# cannot load its library).
. tests/shlib.sh
if ! command -v python3 >/dev/null 2>&1; then echo "cli_python: no python3: skipped"; summary cli_python; exit 0; fi
if grep -q -- '-fsanitize' "$BUILD/flags.txt" 2>/dev/null; then echo "cli_python: a sanitizer build: skipped"; summary cli_python; exit 0; fi
ROOT=$(pwd)
LIB=$ROOT/$BUILD/libamorph.so
[ -f "$LIB" ] || make -s --no-print-directory BUILD="$BUILD" shared >/dev/null
check "the shared library is built" test -f "$LIB"
W=$TMPD
SMALL="--workspace 6 --cycles 2 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100 --gmx_points 6"
"$AMORPH" random --representation gmx --workspace 8 --seed 7 --out "$W/gmx.genome" 2>/dev/null
"$AMORPH" export --scene sphere:6 --lattice "$W/sphere.lattice" >/dev/null 2>&1

# evaluate, from another folder: the module's result is amorph sim's
for r in gmx.genome sphere.lattice; do
    want=$("$AMORPH" sim "$W/$r" --cycles 2 --json 2>/dev/null | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
    got=$(cd "$W" && AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
r = amorph.Workspace({"cycles": 2}).evaluate(open(sys.argv[2]).read())
print("%.9g %016x" % (r.fitness, r.hash))' "$ROOT" "$r" 2>&1)
    check "$r: the module ($got) is amorph sim ($want)" test -n "$want" -a "$got" = "$want"
done
# VXA text: the module evaluates a VoxCAD and an evosoro file as amorph sim FILE runs them (their own
# environment, layers and run length)
for v in voxcad_quadruped.vxa evosoro_phase.vxa evosoro_stiffness.vxa; do
    want=$("$AMORPH" sim "tests/data/$v" --json 2>/dev/null | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
    got=$(AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
r = amorph.Workspace().evaluate(open(sys.argv[2]).read())
print("%.9g %016x" % (r.fitness, r.hash))' "$ROOT" "tests/data/$v" 2>&1)
    check "$v: the module ($got) is amorph sim ($want)" test -n "$want" -a "$got" = "$want"
    got=$(python3 -c 'import json, sys; print(json.dumps({"vxa": open(sys.argv[1]).read()}))' "tests/data/$v" | "$AMORPH" eval 2>&1 |
        sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
    check "$v: through amorph eval ($got) is amorph sim ($want)" test -n "$want" -a "$got" = "$want"
done
# without AMORPH_LIB: the checkout's build/ beside the module (the default build only)
if [ "$BUILD" = build ]; then
    got=$(cd "$W" && env -u AMORPH_LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
print("%.9g" % amorph.Workspace({"cycles": 2}).evaluate(open("gmx.genome").read()).fitness)' "$ROOT" 2>&1)
    want=$("$AMORPH" sim "$W/gmx.genome" --cycles 2 2>/dev/null | sed -n 's/^fitness = //p')
    check "found beside the module: $got, amorph sim $want" test -n "$want" -a "$got" = "$want"
fi

# crowding(): amorph's run through ask/tell ends where amorph evolve ends
for act in global phase; do
    d=$W/run-$act
    # shellcheck disable=SC2086
    expect_ok "$AMORPH" evolve $SMALL --actuation $act --population 8 --evaluations 32 --seed 5 --threads 1 --quiet --no-pictures --out "$d"
    got=$(cd "$W" && AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph, math
s = {"workspace": 6, "cycles": 2, "period_steps": 100, "relax_max_steps": 400, "relax_min_steps": 50, "release_steps": 100,
     "gmx_points": 6, "actuation": sys.argv[2]}
w = amorph.Workspace(s)
pop = amorph.crowding(w, 8, 3, 5)
top = max(-math.inf if f != f else f for g, f in pop)
# the run keeps the first genome evaluated at the top: members of one body may tie with it
best = open(sys.argv[3]).read()
print("%.9g %d" % (top, any(g == best and f == top for g, f in pop)))' "$ROOT" "$act" "$d/best.genome" 2>&1)
    check "$act: crowding()'s best fitness and genome ($got) are amorph evolve's ($(sumval "$d" best_fitness))" \
        test "$got" = "$(sumval "$d" best_fitness) 1"
done

# Workspace.from_run: a run folder's settings (its config.txt), so a genome evaluates as the run
# evaluated it: its best is amorph sim DIR, another genome amorph sim DIR --genome FILE; a config.txt
# with a key set twice is an AmorphError naming the file and line
rd=$W/run-phase
for g in "$rd/best.genome" "$W/gmx.genome"; do
    want=$("$AMORPH" sim "$rd" --genome "$g" --json 2>/dev/null | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
    got=$(AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
r = amorph.Workspace.from_run(sys.argv[2]).evaluate(open(sys.argv[3]).read())
print("%.9g %016x" % (r.fitness, r.hash))' "$ROOT" "$rd" "$g" 2>&1)
    check "from_run(${rd##*/}) evaluates ${g##*/} ($got) as amorph sim DIR --genome ($want)" test -n "$want" -a "$got" = "$want"
done
want=$("$AMORPH" sim "$rd" --json 2>/dev/null | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
check "amorph sim DIR is amorph sim DIR --genome DIR/best.genome" test -n "$want" -a "$(AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
r = amorph.Workspace.from_run(sys.argv[2]).evaluate(open(sys.argv[2] + "/best.genome").read())
print("%.9g %016x" % (r.fitness, r.hash))' "$ROOT" "$rd" 2>&1)" = "$want"
{ cat "$rd/config.txt"; echo "cycles = 3"; } >"$W/twice.txt"
n=$(wc -l <"$W/twice.txt")
got=$(AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
try:
    amorph.Workspace.from_run(sys.argv[2])
except amorph.AmorphError as e:
    print(e)' "$ROOT" "$W/twice.txt" 2>&1)
check "from_run of a config with cycles set twice: $got" sh -c 'case "$1" in "$2:$3: cycles set again (first on line "*"): say it once") exit 0 ;; *) exit 1 ;; esac' _ "$got" "$W/twice.txt" "$n"

# the same run through an amorph eval pipe: the operators as JSON lines ({"op": "new"}, "pairing",
# "offspring", "crowd"), the evaluations as robot lines, batch by batch
cat >"$W/pipe_ga.py" <<'PY'
import json, math, subprocess, sys
amorph, act, best_path = sys.argv[1], sys.argv[2], sys.argv[3]
s = ["--workspace", "6", "--cycles", "2", "--period_steps", "100", "--relax_max_steps", "400", "--relax_min_steps", "50",
     "--release_steps", "100", "--gmx_points", "6", "--actuation", act]
p = subprocess.Popen([amorph, "eval", "--threads", "2"] + s, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
def batch(lines):
    for l in lines:
        p.stdin.write(json.dumps(l) + "\n")
    p.stdin.write("\n"); p.stdin.flush()
    out = []
    while True:
        line = p.stdout.readline()
        if not line:
            raise SystemExit("eval ended: %s" % p.wait())
        if line == "\n":
            return out
        out.append(json.loads(line))
def score(r):
    return math.nan if r["diverged"] else r["fitness"]
N = 8
batch([{"op": "seed", "seed": 5}])
pop = [r["genome"] for r in batch([{"op": "new"}] * N)]
fit = [score(r) for r in batch([{"genome": g} for g in pop])]
for gen in range(3):
    order = batch([{"op": "pairing", "n": N}])[0]["order"]
    kids = []
    for r in batch([{"op": "offspring", "a": pop[order[k]], "b": pop[order[k + 1]]} for k in range(0, N, 2)]):
        kids += r["genomes"]
    kfit = [score(r) for r in batch([{"genome": g} for g in kids])]
    nul = lambda f: None if f != f else f
    res = batch([{"op": "crowd", "a": pop[order[k]], "fa": nul(fit[order[k]]), "b": pop[order[k + 1]], "fb": nul(fit[order[k + 1]]),
                  "c1": kids[k], "f1": nul(kfit[k]), "c2": kids[k + 1], "f2": nul(kfit[k + 1])} for k in range(0, N, 2)])
    for i, r in enumerate(res):
        k = 2 * i
        for c in range(2):
            if r["replaces"][c]:
                q = order[k + r["meets"][c]]
                pop[q], fit[q] = kids[k + c], kfit[k + c]
p.stdin.close(); p.wait()
top = max(-math.inf if f != f else f for f in fit)
best = open(best_path).read()
print("%.9g %d" % (top, any(g == best and f == top for g, f in zip(pop, fit))))
PY
for act in global phase; do
    d=$W/run-$act
    got=$(python3 "$W/pipe_ga.py" "$AMORPH" $act "$d/best.genome" 2>&1)
    check "$act: the pipe's run ($got) ends at amorph evolve's best ($(sumval "$d" best_fitness))" test "$got" = "$(sumval "$d" best_fitness) 1"
done
# the pipe's operator lines refused in one line each, naming the line
printf '{"op": "fly"}\n' >"$W/bad1.jsonl"
expect_fail 2 'eval: stdin:1: column [0-9]*: unknown op "fly" \(seed, new, pairing, offspring, mutate, distance, crowd\)' sh -c "'$AMORPH' eval <'$W/bad1.jsonl'"
printf '{"op": "new"}\n{"op": "offspring", "a": "x"}\n' >"$W/bad2.jsonl"
expect_fail 2 'eval: stdin:2: column [0-9]*: op "offspring" needs "b"' sh -c "'$AMORPH' eval <'$W/bad2.jsonl'"
printf '{"op": "mutate", "genome": "amorph-genome 1"}\n' >"$W/bad3.jsonl"
expect_fail 2 'eval: stdin:1: genome:1: unexpected end of text: expected .repr dct|cppn|gmx.' sh -c "'$AMORPH' eval <'$W/bad3.jsonl'"
printf '{"a": "x"}\n' >"$W/bad4.jsonl"
expect_fail 2 "eval: stdin:1: column [0-9]*: an operator's inputs without \"op\"" sh -c "'$AMORPH' eval <'$W/bad4.jsonl'"

# docs/examples/map_elites.py: the same output twice (its draws are seeded), and its crowding line is
# amorph evolve's run at the same budget (crowding() is amorph's run)
(cd "$W" && AMORPH_LIB=$LIB python3 "$ROOT/docs/examples/map_elites.py" --evals 40 --seeds 1 --set workspace=6 --set cycles=2) >"$W/me1.txt" 2>&1
(cd "$W" && AMORPH_LIB=$LIB python3 "$ROOT/docs/examples/map_elites.py" --evals 40 --seeds 1 --set workspace=6 --set cycles=2) >"$W/me2.txt" 2>&1
check "map_elites.py: the same output twice: $(head -c 200 "$W/me1.txt")" sh -c "cmp -s '$W/me1.txt' '$W/me2.txt' && grep -q '^seed 1 map-elites best ' '$W/me1.txt'"
expect_ok "$AMORPH" evolve --workspace 6 --cycles 2 --population 20 --evaluations 40 --seed 1 --threads 1 --quiet --no-pictures --out "$W/me-run"
got=$(sed -n 's/^seed 1 crowding   best \([0-9.]*\) m.*/\1/p' "$W/me1.txt")
check "map_elites.py: its crowding ($got) is amorph evolve's ($(sumval "$W/me-run" best_fitness))" \
    test -n "$got" -a "$got" = "$(printf '%.4f' "$(sumval "$W/me-run" best_fitness)")"

# Sim: reset / step / observe; the sinusoid fed back every step is the evaluation (its state hash),
# a held action is another motion, the same calls give the same hash
got=$(cd "$W" && AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph, math
w = amorph.Workspace({"cycles": 2})
text = open("gmx.genome").read()
r = w.evaluate(text)
sim = amorph.Sim(workspace=w)
o0 = sim.reset(text)
for k in range(2 * r.period_steps):
    sc, rt = sim.sinusoid()
    o = sim.step(sc, 1, rt)
same = o["hash"] == r.hash and o["step"] == r.steps and abs(math.hypot(o["com"][0] - o0["com"][0], o["com"][1] - o0["com"][1]) - r.travel) < 1e-9
held = []
for t in range(2):
    sim.reset(text)
    held.append(sim.step({m: 1.0 for m in set(sim.materials)}, 2 * r.period_steps)["hash"])
print(int(same), int(held[0] == held[1] and held[0] != r.hash), sim.nv == r.voxels, len(o["pos"]) == sim.nv)' "$ROOT" 2>&1)
check "Sim: fed back, held, the same twice, per-voxel arrays: $got" test "$got" = "1 1 True True"

# docs/examples/closed_loop.py on a small run: stepping through Sim in calls of 10 steps without
# control travels what the evaluation travels, and the tuned controller is never below its start
(cd "$W" && AMORPH_LIB=$LIB python3 "$ROOT/docs/examples/closed_loop.py" --run "$W/run-global" --cycles 4 --iters 2) >"$W/cl.txt" 2>&1
a1=$(sed -n 's/^open loop (amorph sim --cycles 4): \([0-9.]*\) m$/\1/p' "$W/cl.txt")
a2=$(sed -n 's/^open loop, stepped every 10 steps: \([0-9.]*\) m$/\1/p' "$W/cl.txt")
check "closed_loop.py: open loop $a1, stepped in calls of 10 $a2: $(tail -n 1 "$W/cl.txt")" test -n "$a1" -a "$a1" = "$a2"
check "closed_loop.py: a tuned controller line" grep -q '^tuned controller: [0-9.]* m over 4 cycles' "$W/cl.txt"

# refusals: one line each
got=$(AMORPH_LIB=$LIB python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
try:
    amorph.Workspace({"cycles": "many"})
except amorph.AmorphError as e:
    print("refused:", e)' "$ROOT" 2>&1)
case $got in "refused: cycles = 'many': expected an integer in [0, 100000]") ok ;; *) ko "a bad setting: $got" ;; esac
got=$(cd "$W" && AMORPH_LIB=$W/none.so python3 -c '
import sys; sys.path.insert(0, sys.argv[1] + "/tools/python")
import amorph
try:
    amorph.load("'"$W"'/none.so")
except amorph.AmorphError as e:
    print("refused:", e)' "$ROOT" 2>&1)
case $got in "refused: libamorph not found (make shared, or set AMORPH_LIB); tried: "*none.so) ok ;; *) ko "no library: $got" ;; esac
summary cli_python
