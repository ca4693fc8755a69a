# tests/cli_embed.sh: amorph from other programs (docs/embedding.md). The same robots (genomes of
# two representations, a lattice, an empty lattice) through amorph sim, through libamorph.so from
# Python's ctypes and through an `amorph eval` pipe (docs/examples/eval_pipe.py) give the same
# fitness and hash; amorph eval's results do not depend on --threads and come in input order, a
# batch per empty line; bad input is one line naming the line of stdin, exit 2; make install's
# files (tools/install.sh) serve a C program built with pkg-config. Python parts are skipped
# without python3, the install part without pkg-config.
. tests/shlib.sh
W=$TMPD
set_flags="--cycles 2"
"$AMORPH" random --representation gmx --workspace 8 --seed 7 --out "$W/gmx.genome" 2>/dev/null
"$AMORPH" random --representation dct --workspace 6 --seed 5 --out "$W/dct.genome" 2>/dev/null
"$AMORPH" export --scene sphere:6 --lattice "$W/sphere.lattice" >/dev/null 2>&1
"$AMORPH" export --scene cube:2 --lattice "$W/empty.lattice" >/dev/null 2>&1
sed -i 's/^11$/../' "$W/empty.lattice" # cube:2 with every cell emptied
robots="gmx.genome dct.genome sphere.lattice"
check "the robots were written" test -s "$W/gmx.genome" -a -s "$W/dct.genome" -a -s "$W/sphere.lattice"

# amorph sim's fitness and hash of each robot: "file fitness hash" lines
for r in $robots; do
    # shellcheck disable=SC2086
    "$AMORPH" sim "$W/$r" $set_flags --json 2>/dev/null |
        sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p' | sed "s|^|$r |"
done >"$W/sim.txt"
check "amorph sim gave three results" test "$(grep -c . "$W/sim.txt")" -eq 3

# amorph eval: one batch of the three robots, then a second batch of the first one alone, on 1 and 2 threads
if command -v python3 >/dev/null 2>&1; then
    python3 - "$W" $robots >"$W/in.jsonl" <<'PY'
import json, sys
w = sys.argv[1]
for i, r in enumerate(sys.argv[2:]):
    kind = "genome" if r.endswith(".genome") else "lattice"
    print(json.dumps({"id": 10 + i, kind: open(w + "/" + r).read(), "settings": {"cycles": 2}}))
print()
print(json.dumps({"genome": open(w + "/" + sys.argv[2]).read(), "settings": {"cycles": "2"}}))
PY
    "$AMORPH" eval --threads 1 <"$W/in.jsonl" >"$W/e1.txt" 2>"$W/err1"
    check "amorph eval --threads 1 succeeds" test $? -eq 0
    "$AMORPH" eval --threads 2 <"$W/in.jsonl" >"$W/e2.txt" 2>"$W/err2"
    check "amorph eval --threads 2 succeeds" test $? -eq 0
    check "amorph eval prints the same on 1 and 2 threads" cmp -s "$W/e1.txt" "$W/e2.txt"
    # five lines: three results, the empty line ending the batch, one result, the empty line of the last batch
    check "amorph eval answers each batch with its results and an empty line" \
        test "$(awk '{ printf "%s", ($0 == "" ? "-" : "r") }' "$W/e1.txt")" = "rrr-r-"
    ids=$(sed -n 's/^{"id": \([0-9]*\),.*/\1/p' "$W/e1.txt" | tr '\n' ' ')
    check "results keep the input order and ids (the line number without an id): $ids" test "$ids" = "10 11 12 5 "
    i=0
    for r in $robots; do
        i=$((i + 1))
        want=$(sed -n "s/^$r //p" "$W/sim.txt")
        got=$(sed -n "${i}p" "$W/e1.txt" | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
        check "$r: amorph eval ($got) is amorph sim ($want)" test -n "$want" -a "$got" = "$want"
    done

    # the material keys change a genome's palette and a lattice's materials as amorph sim's flags do
    for r in gmx.genome sphere.lattice; do
        want=$("$AMORPH" sim "$W/$r" --cycles 2 --mu_static 0.6 --cte 0.02 --mu_kinetic 0.2 --voxel_size 0.02 --period_steps 300 --json 2>/dev/null |
            sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
        got=$(python3 -c 'import json,sys; k = "genome" if sys.argv[1].endswith(".genome") else "lattice"; print(json.dumps({k: open(sys.argv[1]).read(),
"settings": {"cycles": 2, "mu_static": "0.6", "cte": 0.02, "mu_kinetic": "0.2", "voxel_size": "0.02", "period_steps": 300}}))' "$W/$r" |
            "$AMORPH" eval 2>&1 | sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p')
        base=$(sed -n "s/^$r //p" "$W/sim.txt")
        check "$r with material settings: amorph eval ($got) is amorph sim ($want), not the plain result ($base)" \
            test -n "$want" -a "$got" = "$want" -a "$want" != "$base"
    done

    # ctypes and the pipe from the example program
    if grep -q -- '-fsanitize' "$BUILD/flags.txt" 2>/dev/null; then
        echo "cli_embed: a sanitizer build: Python cannot load its libamorph.so: ctypes part skipped"
    else
        (cd "$W" && python3 "$OLDPWD/docs/examples/eval_pipe.py" --lib "$OLDPWD/$BUILD/libamorph.so" --amorph "$OLDPWD/$AMORPH" \
            --set cycles=2 $robots) >"$W/py.txt" 2>"$W/pyerr"
        check "eval_pipe.py runs: $(head -c 300 "$W/pyerr")" test $? -eq 0
        for r in $robots; do
            want=$(sed -n "s/^$r //p" "$W/sim.txt")
            line=$(grep "^$r " "$W/py.txt")
            set -- $line
            check "$r: ctypes ($2 $3 $4) is amorph sim ($want)" test -n "$want" -a "$3 $4" = "$want"
            check "$r: the pipe ($5 $6 $7) is amorph sim ($want)" test -n "$want" -a "$6 $7" = "$want"
        done
    fi

    # an empty lattice: fitness 0, empty, as amorph sim says
    python3 -c 'import json,sys; print(json.dumps({"id": 1, "lattice": open(sys.argv[1]).read()}))' "$W/empty.lattice" >"$W/empty.jsonl"
    case $("$AMORPH" eval <"$W/empty.jsonl" 2>&1) in
    *'"fitness": 0,'*'"voxels": 0,'*'"empty": 1,'*) ok ;; *) ko "an empty lattice: $("$AMORPH" eval <"$W/empty.jsonl" 2>&1 | head -c 300)" ;; esac

    # bad input: one line naming the line of stdin, exit 2; the batches before it answered
    g=$(python3 -c 'import json,sys; print(json.dumps(open(sys.argv[1]).read()))' "$W/gmx.genome")
    printf '{"id": 1, "genome": %s, "settings": {"cycles": 2}}\n\n{"id": 2, "genome": %s}\n{"id": 3, "genome": \n' "$g" "$g" >"$W/bad1.jsonl"
    expect_fail 2 '^amorph: eval: stdin:4: column [0-9]+: expected a string' "$AMORPH" eval <"$W/bad1.jsonl"
    check "the batch before the bad line was answered" test "$(grep -c '"id": 1,' "$TMPD/out")" -eq 1
    check "nothing of the bad line's batch was printed" test "$(grep -c '"id": 2,' "$TMPD/out")" -eq 0
    printf '{"id": 1, "robot": "x"}\n' >"$W/bad2.jsonl"
    expect_fail 2 '^amorph: eval: stdin:1: column [0-9]+: unknown key "robot"' "$AMORPH" eval <"$W/bad2.jsonl"
    printf '{"id": 1, "genome": "amorph-genome 1\\nrepresentation nonsense\\n"}\n' >"$W/bad3.jsonl"
    expect_fail 2 '^amorph: eval: stdin:1: genome:2: ' "$AMORPH" eval <"$W/bad3.jsonl"
    printf '{"id": 1, "lattice": "x", "settings": {"no_such_key": "1"}}\n' >"$W/bad4.jsonl"
    expect_fail 2 "^amorph: eval: stdin:1: column [0-9]+: settings: unknown setting 'no_such_key'" "$AMORPH" eval <"$W/bad4.jsonl"
    printf '{"id": 1, "lattice": "x", "settings": {"a\\u001bb": "1"}}\n' >"$W/bad9.jsonl"
    expect_fail 2 "stdin:1: column [0-9]+: settings: unknown setting 'a.x1bb'" "$AMORPH" eval <"$W/bad9.jsonl"
    printf '{"id": 1, "lattice": "x", "settings": {"population": "4"}}\n' >"$W/bad5.jsonl"
    expect_fail 2 "stdin:1: .*'population' is a setting of an evolution" "$AMORPH" eval <"$W/bad5.jsonl"
    printf '{"id": 1.5, "lattice": "x"}\n' >"$W/bad6.jsonl"
    expect_fail 2 'stdin:1: column [0-9]+: "id" must be an integer' "$AMORPH" eval <"$W/bad6.jsonl"
    printf '{"id": 1, "lattice": "x"} {}\n' >"$W/bad7.jsonl"
    expect_fail 2 'stdin:1: column 27: .{3} after the object' "$AMORPH" eval <"$W/bad7.jsonl"
    printf '{"id": 1, "lattice": "a\\q"}\n' >"$W/bad8.jsonl"
    expect_fail 2 "stdin:1: column [0-9]+: an unknown escape" "$AMORPH" eval <"$W/bad8.jsonl"
    expect_fail 2 "eval: unknown option '--bogus'" "$AMORPH" eval --bogus </dev/null
    # --run DIR: a run folder's settings (config.txt) under the flags and the lines': a genome is
    # evaluated as the run evaluated it (amorph sim DIR --genome FILE), the operators are the run's
    expect_ok "$AMORPH" evolve --representation dct --workspace 5 --population 4 --evaluations 8 --cycles 3 --release_steps 300 \
        --quiet --no-pictures --out "$W/run"
    jl() { python3 -c 'import json, sys; print(json.dumps({"genome": open(sys.argv[1]).read()}))' "$1"; }
    fh() { sed -n 's/.*"fitness": \([^,]*\),.*"hash": "\([0-9a-f]*\)".*/\1 \2/p'; }
    for gf in "$W/run/best.genome" "$W/gmx.genome"; do
        want=$("$AMORPH" sim "$W/run" --genome "$gf" --json 2>/dev/null | fh)
        got=$(jl "$gf" | "$AMORPH" eval --run "$W/run" 2>&1 | fh)
        check "eval --run DIR: ${gf##*/} ($got) as amorph sim DIR --genome ($want)" test -n "$want" -a "$got" = "$want"
        got=$(jl "$gf" | "$AMORPH" eval --run "$W/run/config.txt" 2>&1 | fh)
        check "eval --run DIR/config.txt: ${gf##*/} ($got) the same" test -n "$want" -a "$got" = "$want"
    done
    want=$("$AMORPH" sim "$W/run" --genome "$W/gmx.genome" --cycles 2 --json 2>/dev/null | fh)
    got=$(jl "$W/gmx.genome" | "$AMORPH" eval --run "$W/run" --cycles 2 2>&1 | fh)
    check "eval --run DIR --cycles 2: the flag over the run's 3 ($got, amorph sim: $want)" test -n "$want" -a "$got" = "$want"
    printf '{"op": "seed", "seed": 3}\n{"op": "new"}\n' >"$W/ops.jsonl"
    "$AMORPH" eval --run "$W/run" <"$W/ops.jsonl" >"$W/ops_run.txt" 2>&1
    "$AMORPH" eval <"$W/ops.jsonl" >"$W/ops_def.txt" 2>&1
    check "eval --run DIR: a new genome is of the run's representation (dct), without it the default's: $(grep -o 'repr [a-z]*' "$W/ops_run.txt" "$W/ops_def.txt" | tr '\n' ' ')" \
        sh -c "grep -q 'nrepr dct' '$W/ops_run.txt' && grep -q 'nrepr [a-z]' '$W/ops_def.txt' && ! grep -q 'nrepr dct' '$W/ops_def.txt'"
    { cat "$W/run/config.txt"; echo "cycles = 4"; } >"$W/twice.cfg"
    n=$(wc -l <"$W/twice.cfg")
    expect_fail 2 "^amorph: eval: --run: $W/twice.cfg:$n: cycles set again \(first on line [0-9]+\): say it once$" "$AMORPH" eval --run "$W/twice.cfg" </dev/null
    expect_fail 2 "^amorph: eval: --run: $W/none: " "$AMORPH" eval --run "$W/none" </dev/null
    expect_fail 2 "^amorph: eval: --run needs a run folder" "$AMORPH" eval --run
    expect_fail 2 "^amorph: eval: --run given twice$" "$AMORPH" eval --run "$W/run" --run "$W/run" </dev/null
    sed 's/^cycles = .*/cycles = 100000/; s/^period_steps = .*/period_steps = 10000000/' "$W/run/config.txt" >"$W/long.cfg"
    jl "$W/gmx.genome" >"$W/one.jsonl"
    expect_fail 2 "^amorph: eval: stdin:1: $W/long.cfg: period_steps = 10000000: up to 1e\+12 steps an evaluation" \
        timeout -k 5 60 "$AMORPH" eval --run "$W/long.cfg" <"$W/one.jsonl"
    # issue 46: one bound on every evaluation (10^9 steps): a line over it is refused when it is read,
    # before any robot of its batch runs, naming its line and the setting (timeout: the builds before
    # ran it for ever)
    printf '{"id": 1, "genome": %s}\n{"id": 2, "genome": %s, "settings": {"cycles": "100000", "period_steps": "10000000"}}\n' "$g" "$g" >"$W/long1.jsonl"
    expect_fail 2 '^amorph: eval: stdin:2: settings: period_steps = 10000000: up to 1e\+12 steps an evaluation .*over the budget of 1e\+09' \
        timeout -k 5 60 "$AMORPH" eval <"$W/long1.jsonl"
    check "no robot of the refused line's batch was evaluated" test ! -s "$TMPD/out"
    printf '{"id": 1, "genome": %s, "settings": {"relax_max_steps": "100000000"}}\n' "$g" >"$W/long2.jsonl"
    expect_fail 2 '^amorph: eval: stdin:1: --dt_frac = 1e-06: up to .* over the budget' \
        timeout -k 5 60 "$AMORPH" eval --dt_frac 1e-6 --settle_speed 0 <"$W/long2.jsonl"
    # a period in seconds, at the body's own step: 2 to 10^7 steps, and within the budget
    printf '{"id": 1, "genome": %s, "settings": {"period_s": "1e-9"}}\n' "$g" >"$W/long3.jsonl"
    expect_fail 2 '^amorph: eval: stdin:1: period_s = 1e-09 s is .* steps .*\(a period takes 2 to 10\^7 steps\)$' \
        timeout -k 5 60 "$AMORPH" eval <"$W/long3.jsonl"
    printf '{"id": 1, "genome": %s, "settings": {"period_s": "20", "cycles": "10000"}}\n' "$g" >"$W/long4.jsonl"
    expect_fail 2 '^amorph: eval: stdin:1: cycles = 10000: up to .* over the budget' timeout -k 5 60 "$AMORPH" eval <"$W/long4.jsonl"
else
    echo "cli_embed: no python3: the eval, ctypes and pipe checks skipped"
fi

# make install's files: a C program compiled with pkg-config's flags evaluates a lattice as amorph sim does
if command -v pkg-config >/dev/null 2>&1 && [ -f "$BUILD/libamorph.so" ] && ! grep -q -- '-fsanitize\|mingw' "$BUILD/flags.txt"; then
    defs=$(tr ' ' '\n' <"$BUILD/flags.txt" | grep -E '^-DAM_(REAL|PROFILE)_' | tr '\n' ' ')
    sh tools/install.sh "$BUILD" "$W/inst" "$W/inst" "$defs" >/dev/null
    check "tools/install.sh installs" test $? -eq 0
    for f in include/amorph.h include/amorph/api.h lib/libamorph.a lib/libamorph.so bin/amorph lib/pkgconfig/amorph.pc; do
        check "installed $f" test -f "$W/inst/$f"
    done
    # libamorph.so -> libamorph.so.MAJOR -> libamorph.so.MAJOR.MINOR.PATCH, as in the build folder
    so1=$(readlink "$W/inst/lib/libamorph.so") so2=$(readlink "$W/inst/lib/$so1")
    check "installed the shared library's links: libamorph.so -> $so1 -> $so2" test -L "$W/inst/lib/$so1" -a -f "$W/inst/lib/$so2" -a ! -L "$W/inst/lib/$so2"
    cat >"$W/probe.c" <<'C'
#include <stdio.h>
#include "amorph.h"
static am_api_work work;
static char text[1 << 20];
int main(int argc, char** argv)
{
    char err[AM_ERR_MAX];
    am_result r;
    FILE* f = argc > 1 ? fopen(argv[1], "rb") : NULL;
    if (!f) return 2;
    text[fread(text, 1, sizeof text - 1, f)] = 0;
    fclose(f);
    if (AM_LAYOUT_CHECK(err, sizeof err) != AM_OK || am_api_init(&work, sizeof work, err, sizeof err) != AM_OK || am_api_set(&work, "cycles", "2", err, sizeof err) != AM_OK ||
        am_api_eval_lattice(&work, text, &r, err, sizeof err) != AM_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    printf("%.9g %016llx\n", r.fitness, (unsigned long long)r.hash);
    return 0;
}
C
    # shellcheck disable=SC2046
    cc -std=c11 -o "$W/probe" "$W/probe.c" $(PKG_CONFIG_PATH="$W/inst/lib/pkgconfig" pkg-config --cflags --libs amorph) 2>"$W/ccerr"
    check "a C program builds with pkg-config --cflags --libs amorph: $(head -c 300 "$W/ccerr")" test $? -eq 0
    got=$(LD_LIBRARY_PATH="$W/inst/lib" "$W/probe" "$W/sphere.lattice" 2>&1)
    want=$(sed -n 's/^sphere.lattice //p' "$W/sim.txt")
    check "the installed library's result ($got) is amorph sim's ($want)" test -n "$want" -a "$got" = "$want"
else
    echo "cli_embed: no pkg-config (or no $BUILD/libamorph.so, or a sanitizer or Windows build): the install checks skipped"
fi
summary cli_embed
