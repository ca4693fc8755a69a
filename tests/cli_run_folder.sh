# tests/cli_run_folder.sh: no run lost (issue 46): a run folder without its checkpoint is told as it
# is and never overwritten, the tables reach the disk before the checkpoint that counts their rows,
# a resume after a torn write mends what it can or refuses in one line (tables cut short, half a
# row, a kill between the tables and the checkpoint at a counted point), a write failure in an
# accepted resume is a runtime failure (exit 1), a folder where a replaced file goes is found
# before any evaluation, a link to nothing named runs/run-001 is passed over, a key set twice in a
# config file and an empty config.txt are named as such. Run from the repository root.
. tests/shlib.sh

small_cfg "$TMPD/small.cfg"
E="$AMORPH evolve --config $TMPD/small.cfg --quiet --no-pictures"
# snapall DIR: every entry of DIR, a link as its target, a file by its checksum
snapall() { (cd "$1" && for f in $(ls -A | sort); do if [ -L "$f" ]; then echo "$f -> $(readlink "$f")"; elif [ -d "$f" ]; then echo "$f/"; else echo "$f $(cksum <"$f")"; fi; done); }
expect_ok $E --out "$TMPD/a" --threads 1

# --- a folder without its checkpoint: what it holds is said, and --out does not overwrite it ---
for how in missing dangling; do
    d="$TMPD/nock-$how"
    cp -r "$TMPD/a" "$d" && rm "$d/checkpoint.txt"
    if [ $how = dangling ]; then ln -s "$TMPD/nothere" "$d/checkpoint.txt"; fi
    before=$(snapall "$d")
    expect_fail 2 "no checkpoint.txt \(missing, or a link to nothing\), so the run cannot go on; the folder holds what it did: log.csv 6 rows \(generations\), evals.csv 36 rows \(evaluations\), and summary.txt .*keep them" \
        "$AMORPH" evolve --resume "$d" --quiet
    expect_fail 2 "holds the tables of a run without its checkpoint \(log.csv 6 rows.*evals.csv 36 rows.*\): a new run would overwrite them" \
        $E --out "$d"
    if [ "$(snapall "$d")" = "$before" ]; then ok; else ko "$how checkpoint: a refused --resume or --out changed the folder"; fi
done

# --- the tables are on the disk before the checkpoint that counts their rows ---
# strace lists every write, fsync and rename: no checkpoint is renamed into place while a row
# written to log.csv or evals.csv has not been synced
if command -v strace >/dev/null 2>&1 && strace -f -o /dev/null true 2>/dev/null; then
    strace -f -y -e trace=write,fsync,rename,renameat,renameat2 -o "$TMPD/trace" $E --out "$TMPD/st" >/dev/null 2>&1
    if awk '/write\(.*\/st\/(log|evals)\.csv>/ { t = $0; sub(/.*\/st\//, "", t); sub(/>.*/, "", t); dirty[t] = 1 }
            /fsync\(.*\/st\/(log|evals)\.csv>/ { t = $0; sub(/.*\/st\//, "", t); sub(/>.*/, "", t); dirty[t] = 0; synced[t]++ }
            /rename.*"[^"]*\/st\/checkpoint\.txt"/ { n++; if (dirty["log.csv"] || dirty["evals.csv"]) bad = 1 }
            END { exit bad || n < 7 || synced["log.csv"] < 6 || synced["evals.csv"] < 6 }' "$TMPD/trace"; then ok
    else ko "a checkpoint was written while table rows were not synced: $(grep -E 'csv>|checkpoint.txt"' "$TMPD/trace" | head -12)"; fi
    if cmp -s "$TMPD/st/evals.csv" "$TMPD/a/evals.csv" && [ "$(sumval "$TMPD/st" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ]; then ok
    else ko "the run under strace differs"; fi
else
    echo "SKIPPED: the sync order test (strace cannot trace here)"
fi

# --- a torn write: the tables shorter than the checkpoint says ---
# log.csv without its last row, or with half of it: the checkpoint holds that row's figures, and
# the resume puts it back byte for byte
for cut in row half; do
    d="$TMPD/torn-$cut"
    cp -r "$TMPD/a" "$d"
    if [ $cut = row ]; then head -n -1 "$TMPD/a/log.csv" >"$d/log.csv"
    else head -c -10 "$TMPD/a/log.csv" >"$d/log.csv"; fi
    expect_ok "$AMORPH" evolve --resume "$d" --quiet --no-pictures
    if cmp -s "$d/log.csv" "$TMPD/a/log.csv" && [ "$(sumval "$d" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ]; then ok
    else ko "log.csv torn ($cut): not mended: $(tail -n 2 "$d/log.csv" | tr '\n' ' ') $(cat "$TMPD/err")"; fi
done
# two rows gone, or evals.csv short (its rows cannot be made again): one line, the folder as it was
d="$TMPD/torn2"
cp -r "$TMPD/a" "$d" && head -n -2 "$TMPD/a/log.csv" >"$d/log.csv"
before=$(snapall "$d")
expect_fail 2 "torn2/log.csv: 4 whole rows, but the checkpoint counts 6 generations: the rows a crash took back cannot be rebuilt" \
    "$AMORPH" evolve --resume "$d" --quiet
d="$TMPD/torn3"
cp -r "$TMPD/a" "$d" && head -c -10 "$TMPD/a/evals.csv" >"$d/evals.csv"
expect_fail 2 "torn3/evals.csv: 35 whole rows, but the checkpoint counts 36 evaluations: the rows a crash took back cannot be rebuilt" \
    "$AMORPH" evolve --resume "$d" --quiet
if [ "$(snapall "$TMPD/torn2")" = "$before" ] && cmp -s "$d/log.csv" "$TMPD/a/log.csv"; then ok; else ko "a refused torn resume changed the folder"; fi

# --- a kill between the tables and the checkpoint (AMORPH_TEST_INTERRUPT=KILL:checkpoint:N: just
# before the checkpoint at N evaluations, its rows written and synced), then --resume ---
d="$TMPD/kc"
AMORPH_TEST_INTERRUPT=KILL:checkpoint:24 $E --out "$d" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ] && grep -qx "evaluations 18" "$d/checkpoint.txt" && [ $(($(wc -l <"$d/log.csv") - 1)) -eq 4 ] &&
   [ $(($(wc -l <"$d/evals.csv") - 1)) -eq 24 ]; then ok
else ko "KILL:checkpoint:24: exit $rc, checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt"), $(cat "$TMPD/err")"; fi
expect_ok "$AMORPH" evolve --resume "$d" --quiet --no-pictures
if [ "$(nowall "$d/log.csv")" = "$(nowall "$TMPD/a/log.csv")" ] && cmp -s "$d/evals.csv" "$TMPD/a/evals.csv" &&
   [ "$(sumval "$d" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ]; then ok
else ko "killed between the tables and the checkpoint, the resumed run differs"; fi
# Ctrl-C at that point: the checkpoint is written, the run stops there
d="$TMPD/ic"
AMORPH_TEST_INTERRUPT=INT:checkpoint:12 $E --out "$d" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 130 ] && grep -q "interrupted after 12 evaluations" "$TMPD/err" && grep -qx "evaluations 12" "$d/checkpoint.txt"; then ok
else ko "INT:checkpoint:12: exit $rc, $(cat "$TMPD/err")"; fi

# --- a full disk during an accepted resume is a runtime failure (exit 1), not bad input: a file
# size limit of 512 bytes (ulimit -f, SIGXFSZ ignored) fails the resume's rewrite of evals.csv,
# which it cuts back to its checkpoint (past it, half a row that a kill left) ---
cp -r "$TMPD/a" "$TMPD/fd" && printf '36,6,2,3,1,gmx,1' >>"$TMPD/fd/evals.csv"
(trap '' XFSZ; ulimit -f 1; exec "$AMORPH" evolve --resume "$TMPD/fd" --quiet --no-pictures) >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 1 ] && grep -q "fd/evals.csv: .*File too large" "$TMPD/err" && [ "$(wc -l <"$TMPD/err")" -eq 1 ]; then ok
else ko "a write failure in an accepted resume: exit $rc (want 1): $(cat "$TMPD/err")"; fi
expect_ok "$AMORPH" evolve --resume "$TMPD/fd" --quiet --no-pictures
if cmp -s "$TMPD/fd/evals.csv" "$TMPD/a/evals.csv"; then ok; else ko "the run after a failed resume differs"; fi

# --- a folder where the run replaces a file: refused before the first evaluation ---
for f in summary.txt summary.json best.genome; do
    d="$TMPD/pl-$f"
    cp -r "$TMPD/a" "$d" && rm "$d/$f" && mkdir "$d/$f"
    before=$(snapall "$d")
    expect_fail 2 "pl-$f/$f: not a regular file \(a folder, FIFO or device\): refused \(the run replaces $f: move it away\)" \
        "$AMORPH" evolve --resume "$d" --evaluations 48 --quiet --no-pictures
    if [ "$(snapall "$d")" = "$before" ]; then ok; else ko "planted $f: the refused resume changed the folder (evaluated?)"; fi
done
for f in best.png fitness.svg summary.txt; do
    d="$TMPD/new-$f"
    mkdir -p "$d/$f"
    expect_fail 2 "new-$f/$f: not a regular file .*move it away" "$AMORPH" evolve --config "$TMPD/small.cfg" --quiet --out "$d"
    if [ ! -e "$d/log.csv" ] && [ ! -e "$d/checkpoint.txt" ]; then ok; else ko "planted $f in a new run: files written"; fi
done
# without pictures, a folder named best.png is none of the run's business
expect_ok $E --out "$TMPD/new-best.png"

# --- the default run folder passes over a link to nothing named run-001 ---
mkdir -p "$TMPD/dl/runs" && ln -s "$TMPD/nowhere" "$TMPD/dl/runs/run-001"
ABS=$(cd "$(dirname "$AMORPH")" && pwd)/$(basename "$AMORPH")
(cd "$TMPD/dl" && exec "$ABS" evolve --config "$TMPD/small.cfg" --evaluations 6 --quiet --no-pictures) >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 0 ] && [ -s "$TMPD/dl/runs/run-002/summary.txt" ] && [ -L "$TMPD/dl/runs/run-001" ] && [ ! -e "$TMPD/nowhere" ]; then ok
else ko "default folder beside a dangling run-001: exit $rc, $(cat "$TMPD/err"), $(ls "$TMPD/dl/runs" | tr '\n' ' ')"; fi

# --- a key set twice in a config file: an error at the second line ---
printf 'population = 6\nseed = 3\n# again\npopulation = 8\n' >"$TMPD/dup.cfg"
expect_fail 2 "dup.cfg:4: population set again \(first on line 1\)" "$AMORPH" evolve --config "$TMPD/dup.cfg" --print-config
cp -r "$TMPD/a" "$TMPD/dupr" && echo "seed = 11" >>"$TMPD/dupr/config.txt"
expect_fail 2 "dupr/config.txt:[0-9]+: seed set again \(first on line [0-9]+\)" "$AMORPH" evolve --resume "$TMPD/dupr" --quiet

# --- an empty config.txt is said to be empty ---
cp -r "$TMPD/a" "$TMPD/ec" && : >"$TMPD/ec/config.txt"
expect_fail 2 "ec/config.txt is empty: the run's settings are not there" "$AMORPH" evolve --resume "$TMPD/ec" --quiet
printf '# nothing\n\n' >"$TMPD/ec/config.txt"
expect_fail 2 "ec/config.txt is empty" "$AMORPH" evolve --resume "$TMPD/ec" --quiet

summary tests/cli_run_folder.sh
