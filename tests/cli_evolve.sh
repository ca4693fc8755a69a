# tests/cli_evolve.sh: `amorph evolve` and `amorph experiment` as a researcher runs them: run
# folders, config files and flags, identical runs for 1, 2 and 3 threads, Ctrl-C, SIGTERM and
# kill -9 (sent at a chosen evaluation through AMORPH_TEST_INTERRUPT, no timing) followed by
# --resume ending exactly like an uninterrupted run, and every bad input refused with
# one line and a non-zero exit without damaging the run. Run from the repository root.
. tests/shlib.sh

# a small configuration: each run takes a second or two
cat >"$TMPD/small.cfg" <<'CFG'
# small test run
workspace = 8
population = 6
evaluations = 36
cycles = 2
period_steps = 100
relax_max_steps = 400
relax_min_steps = 50
release_steps = 100
gmx_points = 24
seed = 11
CFG
E="$AMORPH evolve --config $TMPD/small.cfg --quiet --no-pictures"

# --- a run and its folder ---
expect_ok $E --out "$TMPD/a" --threads 1
for f in config.txt log.csv evals.csv best.genome best.lattice summary.txt checkpoint.txt; do
    if [ -s "$TMPD/a/$f" ]; then ok; else ko "run folder lacks $f"; fi
done
if [ "$(head -n 1 "$TMPD/a/log.csv")" = "generation,evaluations,best,mean,median,diverged,empty,wall_s,unsettled" ]; then ok
else ko "log header: $(head -n 1 "$TMPD/a/log.csv")"; fi
rows=$(($(wc -l <"$TMPD/a/log.csv") - 1))
if [ "$rows" -eq 6 ]; then ok; else ko "36 evaluations of 6 should log 6 generations, got $rows rows"; fi
if [ "$(tail -n 1 "$TMPD/a/log.csv" | cut -d, -f2)" = 36 ]; then ok; else ko "last row: $(tail -n 1 "$TMPD/a/log.csv")"; fi
# best fitness never decreases under deterministic crowding
if cut -d, -f3 "$TMPD/a/log.csv" | tail -n +2 | awk 'NR > 1 && $1 < prev { bad = 1 } { prev = $1 } END { exit bad }'; then ok
else ko "best fitness decreased: $(cut -d, -f3 "$TMPD/a/log.csv" | tr '\n' ' ')"; fi
# the best genome and lattice are readable robots, and the best genome simulates to the logged best
if grep -q "^amorph-genome" "$TMPD/a/best.genome" && "$AMORPH" sim "$TMPD/a/best.lattice" --cycles 1 >/dev/null 2>&1; then ok
else ko "best.genome / best.lattice unreadable"; fi
# the run folder replays: amorph sim DIR simulates the best robot in the run's settings to its logged fitness
f=$("$AMORPH" sim "$TMPD/a" | sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" = "$(sumval "$TMPD/a" best_fitness)" ]; then ok
else ko "amorph sim RUN gives fitness '$f', the run logged $(sumval "$TMPD/a" best_fitness)"; fi
# evals.csv: one row per evaluation, numbered 0..35 in order, generation 0 without parents, the
# later ones with parents made before them; its best row is the summary's best robot
EV="$TMPD/a/evals.csv"
if [ "$(head -n 1 "$EV")" = "evaluation,generation,parent_a,parent_b,placed,representation,voxels,voxels_m1,voxels_m2,fitness,dx,dy,dz,settled,diverged,empty,relax_steps,steps,state_hash" ]; then ok
else ko "evals.csv header: $(head -n 1 "$EV")"; fi
if tail -n +2 "$EV" | awk -F, '$1 != NR - 1 || $2 != int($1 / 6) || ($2 == 0) != ($3 == -1) || ($2 > 0 && ($3 >= $2 * 6 || $4 >= $2 * 6)) ||
       $7 != $8 + $9 || $6 != "gmx" { bad = 1 } END { exit bad || NR != 36 }'; then ok
else ko "evals.csv rows: $(tail -n +2 "$EV" | head -3)"; fi
best_row=$(tail -n +2 "$EV" | awk -F, '$15 == 0 && (!n++ || $10 > b) { b = $10; h = $19 } END { print h }')
if [ -n "$best_row" ] && [ "$best_row" = "$(sumval "$TMPD/a" best_state_hash)" ]; then ok
else ko "evals.csv best row's hash '$best_row', summary $(sumval "$TMPD/a" best_state_hash)"; fi
# dx, dy give the fitness (horizontal travel) of a body that settled; one that did not has no score
# (-1); an empty body scores 0; and the placed rows of the last generation with those of earlier
# ones are the final population (as many as the population)
if tail -n +2 "$EV" | awk -F, '$15 == 0 && $14 == 1 { d = sqrt($11 * $11 + $12 * $12) - $10; if (d > 1e-9 || d < -1e-9) bad = 1 }
        $15 == 0 && $16 == 0 && $14 == 0 && $10 != -1 { bad = 1 } $16 == 1 && $10 != 0 { bad = 1 }
        $15 == 0 && $14 == 1 { settled++ } END { exit bad || !settled }'; then ok
else ko "evals.csv fitness is not the horizontal travel dx, dy (or -1 when not settled, 0 when empty)"; fi
# summary.json: one JSON line with the summary's values; --json prints the same as the last line
SJ="$TMPD/a/summary.json"
if [ "$(wc -l <"$SJ")" -eq 1 ] && grep -q "^{\"run\": \"$TMPD/a\", \"representation\": \"gmx\", \"evaluations\": 36, " "$SJ" &&
   grep -q "\"run_hash\": \"$(sumval "$TMPD/a" run_hash)\"" "$SJ" && grep -q "\"best_evaluation\": $(sumval "$TMPD/a" best_evaluation)," "$SJ"; then ok
else ko "summary.json: $(head -c 400 "$SJ")"; fi
expect_ok $E --out "$TMPD/aj" --threads 1 --json
if [ "$(wc -l <"$TMPD/out")" -eq 1 ] && grep -q "^{.*\"run_hash\": \"$(sumval "$TMPD/a" run_hash)\".*}$" "$TMPD/out"; then ok
else ko "evolve --json: $(head -c 400 "$TMPD/out")"; fi
if grep -q "^population = 6$" "$TMPD/a/config.txt" && grep -q "^representation = gmx$" "$TMPD/a/config.txt"; then ok
else ko "config.txt does not hold the effective configuration"; fi

# --- pictures at the end of a run (unless --no-pictures) ---
expect_ok "$AMORPH" evolve --config "$TMPD/small.cfg" --evaluations 12 --quiet --out "$TMPD/pic"
if [ "$(head -c 8 "$TMPD/pic/best.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] && grep -q "<svg" "$TMPD/pic/fitness.svg" &&
   grep -q "<canvas" "$TMPD/pic/best.html"; then ok
else ko "run folder pictures: $(ls "$TMPD/pic")"; fi
if [ ! -e "$TMPD/a/best.png" ] && [ ! -e "$TMPD/a/best.html" ]; then ok; else ko "--no-pictures still drew pictures"; fi

# --- 1, 2 and 3 threads: the same run ---
expect_ok $E --out "$TMPD/t2" --threads 2
expect_ok $E --out "$TMPD/t3" --threads 3
h1=$(sumval "$TMPD/a" run_hash); h2=$(sumval "$TMPD/t2" run_hash); h3=$(sumval "$TMPD/t3" run_hash)
if [ -n "$h1" ] && [ "$h1" = "$h2" ] && [ "$h2" = "$h3" ]; then ok; else ko "run hashes differ: $h1 $h2 $h3"; fi
if [ "$(nowall "$TMPD/a/log.csv")" = "$(nowall "$TMPD/t3/log.csv")" ] && cmp -s "$TMPD/a/best.genome" "$TMPD/t3/best.genome" &&
   cmp -s "$TMPD/a/evals.csv" "$TMPD/t3/evals.csv"; then ok
else ko "logs or best genomes differ between 1 and 3 threads"; fi

# --- configuration: file, flags over file, print-config round trip ---
"$AMORPH" evolve --config "$TMPD/small.cfg" --population 8 --print-config >"$TMPD/p1.cfg" 2>"$TMPD/err"
if grep -q "^population = 8$" "$TMPD/p1.cfg" && grep -q "^workspace = 8$" "$TMPD/p1.cfg"; then ok
else ko "flags do not override the file: $(head -c 300 "$TMPD/p1.cfg")"; fi
"$AMORPH" evolve --config "$TMPD/p1.cfg" --print-config >"$TMPD/p2.cfg" 2>&1
if cmp -s "$TMPD/p1.cfg" "$TMPD/p2.cfg"; then ok; else ko "--print-config does not read back to itself"; fi
"$AMORPH" evolve --print-config >"$TMPD/d.cfg"
for kv in "representation = gmx" "materials = 2" "workspace = 20" "population = 20" "cte = 0.01" "amplitude = 30" \
          "period_steps = 500" "mu_kinetic = 0.3" "mu_static = 1" "cte_mode = volumetric"; do
    if grep -qx "$kv" "$TMPD/d.cfg"; then ok; else ko "default configuration lacks '$kv'"; fi
done
"$AMORPH" evolve --workspace=5x6x7 --print-config | grep -qx "workspace = 5x6x7" && ok || ko "--key=value form"
"$AMORPH" evolve --period-steps 250 --print-config | grep -qx "period_steps = 250" && ok || ko "dashes in flag names"

# --- bad input: one line, exit 2, nothing written ---
expect_fail 2 "unknown option '--bogus'" "$AMORPH" evolve --bogus 1
expect_fail 2 "population = 7.*even" "$AMORPH" evolve --population 7 --out "$TMPD/bad1"
expect_fail 2 "population = 'x'" "$AMORPH" evolve --population x --out "$TMPD/bad1"
expect_fail 2 "workspace = '50'.*profile" "$AMORPH" evolve --workspace 50 --out "$TMPD/bad1"
expect_fail 2 "--population needs a value" "$AMORPH" evolve --population
printf 'population = 6\nfrobnicate = 3\n' >"$TMPD/bad.cfg"
expect_fail 2 "bad.cfg:2: unknown key 'frobnicate'" "$AMORPH" evolve --config "$TMPD/bad.cfg" --out "$TMPD/bad1"
printf 'population 6\n' >"$TMPD/bad2.cfg"
expect_fail 2 "bad2.cfg:1: expected 'key = value'" "$AMORPH" evolve --config "$TMPD/bad2.cfg" --out "$TMPD/bad1"
expect_fail 2 "nothere.cfg: cannot open" "$AMORPH" evolve --config "$TMPD/nothere.cfg"
if [ ! -e "$TMPD/bad1" ]; then ok; else ko "a refused run left a folder behind"; fi
expect_fail 2 "holds a run already" $E --out "$TMPD/a"
# a folder left by a run stopped before its first checkpoint (config.txt and a log header, as a
# kill or a full disk leaves it) cannot be resumed, says so, and is started over by --out
mkdir "$TMPD/early" && cp "$TMPD/a/config.txt" "$TMPD/early/" && head -n 1 "$TMPD/a/log.csv" >"$TMPD/early/log.csv"
printf 'evaluation,partial' >"$TMPD/early/evals.csv"
expect_fail 2 "no checkpoint.txt: the run stopped before its first checkpoint.*start it again with --out" "$AMORPH" evolve --resume "$TMPD/early"
# the dead process's temporaries go when the run is started over, as on a resume (an older
# build's NAME.tmp.PID and this one's NAME.tmp.PID.NONCE)
printf 'config (partial' >"$TMPD/early/config.txt.tmp.999999"
printf 'checkpoint (partial' >"$TMPD/early/checkpoint.txt.tmp.999999.00112233aabbccdd"
expect_ok $E --out "$TMPD/early" --threads 1
if [ ! -e "$TMPD/early/config.txt.tmp.999999" ] && [ ! -e "$TMPD/early/checkpoint.txt.tmp.999999.00112233aabbccdd" ]; then ok
else ko "--out left a dead process's temporaries: $(ls "$TMPD/early" | tr '\n' ' ')"; fi
# a run killed before it wrote config.txt (only its lock there) says how to restart as well
mkdir "$TMPD/early0" && : >"$TMPD/early0/lock"
expect_fail 2 "no checkpoint.txt: the run stopped before its first checkpoint.*start it again with --out" "$AMORPH" evolve --resume "$TMPD/early0"
if [ "$(sumval "$TMPD/early" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ] && cmp -s "$TMPD/early/evals.csv" "$TMPD/a/evals.csv"; then ok
else ko "a run started over in a folder left before its first checkpoint differs"; fi

# --- resume: bad cases leave the run as it was ---
cp -r "$TMPD/a" "$TMPD/r"
snap() { (cd "$1" && cat config.txt log.csv best.genome checkpoint.txt lock | cksum); }
before=$(snap "$TMPD/r")
expect_fail 2 "configuration changed: population" "$AMORPH" evolve --resume "$TMPD/r" --population 8 --quiet
sed -i 's/^mu_static = 1$/mu_static = 2/' "$TMPD/r/config.txt"
expect_fail 2 "configuration changed: mu_static" "$AMORPH" evolve --resume "$TMPD/r" --quiet
cp "$TMPD/a/config.txt" "$TMPD/r/config.txt"
sed -i 's/^evaluations 36$/evaluations 37/' "$TMPD/r/checkpoint.txt"
expect_fail 2 "checkpoint.txt:[0-9]+: checksum mismatch" "$AMORPH" evolve --resume "$TMPD/r" --quiet
head -c 2000 "$TMPD/a/checkpoint.txt" >"$TMPD/r/checkpoint.txt"
expect_fail 2 "missing checksum" "$AMORPH" evolve --resume "$TMPD/r" --quiet
cp "$TMPD/a/checkpoint.txt" "$TMPD/r/checkpoint.txt"
# a FIFO in place of the checkpoint or the configuration is refused at once, never waited on
# (without the check, the resume would block on the FIFO until the timeout)
mv "$TMPD/r/checkpoint.txt" "$TMPD/ck.keep" && mkfifo "$TMPD/r/checkpoint.txt"
expect_fail 2 "checkpoint.txt: not a regular file" timeout 60 "$AMORPH" evolve --resume "$TMPD/r" --quiet
rm "$TMPD/r/checkpoint.txt" && mv "$TMPD/ck.keep" "$TMPD/r/checkpoint.txt"
mv "$TMPD/r/config.txt" "$TMPD/cfg.keep" && mkfifo "$TMPD/r/config.txt"
expect_fail 2 "config.txt: not a regular file" timeout 60 "$AMORPH" evolve --resume "$TMPD/r" --quiet
rm "$TMPD/r/config.txt" && mv "$TMPD/cfg.keep" "$TMPD/r/config.txt"
if [ "$(snap "$TMPD/r")" = "$before" ]; then ok; else ko "a refused resume changed the run folder"; fi
# a checkpoint whose line ends became CRLF (a Windows editor or transfer) resumes as the same run
cp -r "$TMPD/a" "$TMPD/crlf" && sed -i 's/$/\r/' "$TMPD/crlf/checkpoint.txt"
expect_ok "$AMORPH" evolve --resume "$TMPD/crlf" --quiet --no-pictures
if [ "$(sumval "$TMPD/crlf" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ]; then ok; else ko "a CRLF checkpoint resumed differently: $(cat "$TMPD/err")"; fi
# what a kill during an atomic write leaves (NAME.tmp.PID beside the file) is removed by --resume,
# once the folder is locked and the run accepted; nothing else is touched, and a refused resume
# removes nothing
cp -r "$TMPD/a" "$TMPD/stale"
printf 'checkpoint v2 (partial' >"$TMPD/stale/checkpoint.txt.tmp.12345"
printf '4,30,0.1' >"$TMPD/stale/log.csv.tmp.7"
printf 'my notes\n' >"$TMPD/stale/notes.tmp.txt"
printf 'x\n' >"$TMPD/stale/x.tmp."
expect_fail 2 "configuration changed: population" "$AMORPH" evolve --resume "$TMPD/stale" --population 8 --quiet
if [ -f "$TMPD/stale/checkpoint.txt.tmp.12345" ] && [ -f "$TMPD/stale/log.csv.tmp.7" ]; then ok
else ko "a refused resume removed the temporaries: $(ls "$TMPD/stale" | tr '\n' ' ')"; fi
expect_ok "$AMORPH" evolve --resume "$TMPD/stale" --quiet --no-pictures
if [ ! -e "$TMPD/stale/checkpoint.txt.tmp.12345" ] && [ ! -e "$TMPD/stale/log.csv.tmp.7" ]; then ok
else ko "--resume left stale temporaries: $(ls "$TMPD/stale" | tr '\n' ' ')"; fi
if [ "$(cat "$TMPD/stale/notes.tmp.txt")" = "my notes" ] && [ "$(cat "$TMPD/stale/x.tmp.")" = "x" ] &&
   [ "$(sumval "$TMPD/stale" run_hash)" = "$(sumval "$TMPD/a" run_hash)" ]; then ok
else ko "--resume touched other files or changed the run: $(ls "$TMPD/stale" | tr '\n' ' ')"; fi
expect_fail 2 "cannot open" "$AMORPH" evolve --resume "$TMPD/nothere" --quiet

# --- nothing written where the user did not point (issue 31) ---
# snapall DIR: every entry of DIR, a link as its target, a file by its checksum (the lock included)
snapall() { (cd "$1" && for f in $(ls -A | sort); do if [ -L "$f" ]; then echo "$f -> $(readlink "$f")"; else echo "$f $(cksum <"$f")"; fi; done); }
# a refused --out on a run, and a refused --resume, leave the folder byte for byte as it was
cp -r "$TMPD/a" "$TMPD/refused"
before=$(snapall "$TMPD/refused")
expect_fail 2 "holds a run already" $E --out "$TMPD/refused"
expect_fail 2 "configuration changed: population" "$AMORPH" evolve --resume "$TMPD/refused" --population 8 --quiet
expect_fail 2 "evaluations = 6 is below the 36 already done" "$AMORPH" evolve --resume "$TMPD/refused" --evaluations 6 --quiet
if [ "$(snapall "$TMPD/refused")" = "$before" ]; then ok; else ko "a refused command changed the run folder (its lock?)"; fi
# a run folder from someone else: a lock that is a link is refused, never opened through
printf 'secret\n' >"$TMPD/victim"
cp -r "$TMPD/a" "$TMPD/ln"
ln -sf "$TMPD/victim" "$TMPD/ln/lock"
before=$(snapall "$TMPD/ln")
expect_fail 2 "ln/lock: a symbolic link: refused" $E --out "$TMPD/ln"
expect_fail 2 "ln/lock: a symbolic link: refused" "$AMORPH" evolve --resume "$TMPD/ln" --evaluations 48 --quiet
rm "$TMPD/ln/lock" && ln "$TMPD/victim" "$TMPD/ln/lock"
expect_fail 2 "ln/lock: a file with 2 names \(a hard link\): refused" "$AMORPH" evolve --resume "$TMPD/ln" --evaluations 48 --quiet
rm "$TMPD/ln/lock" && ln -s "$TMPD/victim" "$TMPD/ln/lock"
if [ "$(cat "$TMPD/victim")" = secret ] && [ "$(snapall "$TMPD/ln")" = "$before" ]; then ok
else ko "a linked lock was written through: victim '$(cat "$TMPD/victim")'"; fi
# the tables that a resume appends to: a link in their place is refused before anything is written
for t in log.csv evals.csv; do
    rm -rf "$TMPD/ln" && cp -r "$TMPD/a" "$TMPD/ln" && cp "$TMPD/a/$t" "$TMPD/victim" && ln -sf "$TMPD/victim" "$TMPD/ln/$t"
    before=$(snapall "$TMPD/ln")
    expect_fail 2 "ln/$t: a symbolic link: refused" "$AMORPH" evolve --resume "$TMPD/ln" --evaluations 48 --quiet --no-pictures
    if cmp -s "$TMPD/victim" "$TMPD/a/$t" && [ "$(snapall "$TMPD/ln")" = "$before" ]; then ok
    else ko "a resume appended to a linked $t, or changed the folder"; fi
done
# a temporary's name is not predictable, and a file planted at the name it had is never written
# through: the symlink stays (removed later as stale) and out.lattice is a file of its own
printf 'secret\n' >"$TMPD/victim"
(cd "$TMPD" && sh -c 'ln -s "$1" out.lattice.tmp.$$; exec "$2" export --scene cube:2 --lattice out.lattice' sh "$TMPD/victim" "$(cd "$OLDPWD" && realpath "$AMORPH")") 2>"$TMPD/err"
if [ "$(cat "$TMPD/victim")" = secret ] && [ -f "$TMPD/out.lattice" ] && [ ! -L "$TMPD/out.lattice" ] && grep -q "^size 2 2 2" "$TMPD/out.lattice"; then ok
else ko "export wrote through a planted temporary: victim '$(cat "$TMPD/victim")', $(cat "$TMPD/err")"; fi
# a write into a folder that is not there names the user's file, not the temporary
expect_fail 1 "nodir/out.lattice: cannot create: No such file or directory$" "$AMORPH" export --scene cube:2 --lattice "$TMPD/nodir/out.lattice"
expect_fail 1 "nodir/t.csv: cannot create: No such file or directory$" "$AMORPH" sim --scene cube:2 --cycles 1 --trajectory "$TMPD/nodir/t.csv"
# a lock that cannot be opened is not blamed on another amorph
cp -r "$TMPD/a" "$TMPD/lockdir" && rm "$TMPD/lockdir/lock" && mkdir "$TMPD/lockdir/lock"
expect_fail 2 "lockdir/lock: not a regular file \(a folder, FIFO or device\): refused$" "$AMORPH" evolve --resume "$TMPD/lockdir" --quiet
# a relation between keys set in a file names the file and the line
printf 'seed = 3\npopulation = 3\n' >"$TMPD/odd.cfg"
expect_fail 2 "^amorph: $TMPD/odd.cfg:2: population = 3: must be even" "$AMORPH" evolve --config "$TMPD/odd.cfg" --out "$TMPD/bad1"
expect_fail 2 "^amorph: evolve: population = 5: must be even" "$AMORPH" evolve --config "$TMPD/odd.cfg" --population 5 --out "$TMPD/bad1"
expect_fail 2 "--out does not apply" "$AMORPH" evolve --resume "$TMPD/r" --out "$TMPD/x"
# a finished run resumed with more evaluations goes on; the result equals a longer run from scratch
expect_ok "$AMORPH" evolve --resume "$TMPD/r" --evaluations 48 --quiet --no-pictures
expect_ok $E --out "$TMPD/long" --evaluations 48
if [ "$(nowall "$TMPD/r/log.csv")" = "$(nowall "$TMPD/long/log.csv")" ] && cmp -s "$TMPD/r/best.genome" "$TMPD/long/best.genome"; then ok
else ko "extending a finished run differs from a longer run"; fi

# --- where the steps go: the summary's step account against evals.csv, counted by awk ---
# a 4^3 workspace: small bodies, some of them repeated (the same body evaluated again gives the
# same final state hash), some empty, some that do not settle in 400 steps
acct() { grep -E '^(steps_|evals_|relax_share|diverged_share|unsettled_share|repeat_share)' "$1/summary.txt"; }
expect_ok $E --out "$TMPD/acct" --workspace 4 --evaluations 60 --seed 1 --gmx_points 16
want=$(tail -n +2 "$TMPD/acct/evals.csv" | awk -F, '$16 == 1 { empty++; next }
    { n++; relax += $17; move += $18 - $17; vs += $18 * $7; rvs += $17 * $7
      if ($15 == 1) div++; else if ($14 == 0) { uns++; uvs += $18 * $7 }
      if (seen[$19]++) { rep++; pvs += $18 * $7 } }
    END { printf "%d %d %d %d %d %d %.6f %.6f %.6f", relax, move, empty, div, uns, rep, rvs / vs, uvs / vs, pvs / vs }')
got="$(sumval "$TMPD/acct" steps_relax) $(sumval "$TMPD/acct" steps_move) $(sumval "$TMPD/acct" evals_empty) $(sumval "$TMPD/acct" evals_diverged)"
got="$got $(sumval "$TMPD/acct" evals_unsettled) $(sumval "$TMPD/acct" evals_repeat)"
got="$got$(for k in relax_share unsettled_share repeat_share; do printf ' %.6f' "$(sumval "$TMPD/acct" $k)"; done)"
if [ "$want" = "$got" ] && [ "$(echo "$want" | cut -d' ' -f6)" -gt 0 ] && [ "$(echo "$want" | cut -d' ' -f5)" -gt 0 ]; then ok
else ko "step account: summary '$got', evals.csv by awk '$want' (the test wants repeats and unsettled bodies)"; fi
if grep -q '"steps_relax": [0-9]' "$TMPD/acct/summary.json" && grep -q '"repeat_share": ' "$TMPD/acct/summary.json"; then ok
else ko "summary.json lacks the step account: $(head -c 300 "$TMPD/acct/summary.json")"; fi
# same body, same result: repeated bodies take the result they gave before (at most the repeats
# the final state hashes show: bodies set down at another height are one body), and --no-reuse,
# which simulates every one, changes nothing but the count
reused=$(sumval "$TMPD/acct" evals_reused)
if [ "$reused" -gt 0 ] && [ "$reused" -le "$(sumval "$TMPD/acct" evals_repeat)" ] &&
   awk -v s="$(sumval "$TMPD/acct" reused_share)" 'BEGIN { exit !(s > 0 && s <= 1) }'; then ok
else ko "evals_reused '$reused', reused_share '$(sumval "$TMPD/acct" reused_share)' (evals_repeat $(sumval "$TMPD/acct" evals_repeat))"; fi
expect_ok $E --out "$TMPD/acct0" --workspace 4 --evaluations 60 --seed 1 --gmx_points 16 --no-reuse
if cmp -s "$TMPD/acct/evals.csv" "$TMPD/acct0/evals.csv" && [ "$(nowall "$TMPD/acct/log.csv")" = "$(nowall "$TMPD/acct0/log.csv")" ] &&
   cmp -s "$TMPD/acct/best.genome" "$TMPD/acct0/best.genome" && [ "$(sumval "$TMPD/acct0" evals_reused)" = 0 ] &&
   [ "$(sumval "$TMPD/acct0" run_hash)" = "$(sumval "$TMPD/acct" run_hash)" ]; then ok
else ko "--no-reuse: evals.csv, log or best differ, or evals_reused '$(sumval "$TMPD/acct0" evals_reused)' is not 0"; fi
# resumed with reuse after a start without it: the table fills from there, the results the same
expect_ok $E --out "$TMPD/acct1" --workspace 4 --evaluations 30 --seed 1 --gmx_points 16 --no-reuse
expect_ok "$AMORPH" evolve --resume "$TMPD/acct1" --evaluations 60 --quiet --no-pictures
if cmp -s "$TMPD/acct/evals.csv" "$TMPD/acct1/evals.csv" && [ "$(sumval "$TMPD/acct1" evals_reused)" -lt "$reused" ]; then ok
else ko "--no-reuse then reuse: evals.csv differs or evals_reused $(sumval "$TMPD/acct1" evals_reused) not below $reused"; fi

# --- interruptions: Ctrl-C (SIGINT), SIGTERM and kill -9, then --resume ---
# AMORPH_TEST_INTERRUPT=SIG:N makes the run send itself SIG when it is about to start evaluation
# N + 1 (docs/evolve.md, Testing interruptions): the interruption lands at the same point on any
# machine, however fast, with no sleep and no race. Population 6: a generation ends at every
# multiple of 6, so 27 and 50 fall inside a generation (its evaluations are dropped and done
# again on resume) and 36 between two.
L="--evaluations 120"
expect_ok $E --out "$TMPD/ref" $L
# interrupt SIG:N ROWS: a run interrupted at N; its log then holds ROWS rows (the whole
# generations before N), and the resumed run ends exactly like the uninterrupted one
interrupt() {
    how=${1%%:*}; d="$TMPD/int-$how"
    AMORPH_TEST_INTERRUPT=$1 $E --out "$d" $L >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    if [ $how = KILL ]; then
        if [ $rc -eq 137 ]; then ok; else ko "kill -9 at $1: exit $rc, stderr: $(cat "$TMPD/err")"; fi
    elif [ $rc -eq 130 ] && grep -q "resume with: amorph evolve --resume $d\$" "$TMPD/err" &&
         grep -q "interrupted after $(($2 * 6)) evaluations" "$TMPD/err"; then ok
    else ko "$how at $1: exit $rc, stderr: $(cat "$TMPD/err")"; fi
    done_rows=$(($(wc -l <"$d/log.csv") - 1))
    if [ "$done_rows" -eq "$2" ] && [ "$done_rows" -lt 20 ]; then ok
    else ko "$how at $1: $done_rows rows when interrupted, want $2 of 20"; fi
    if grep -qx "evaluations $(($2 * 6))" "$d/checkpoint.txt"; then ok
    else ko "$how at $1: checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt"), want $(($2 * 6))"; fi
    resumed "$how" "$d"
}
# resumed WHAT DIR: DIR resumed (without the test variable) ends exactly like the reference run
resumed() {
    expect_ok "$AMORPH" evolve --resume "$2" --quiet --no-pictures
    if [ "$(nowall "$2/log.csv")" = "$(nowall "$TMPD/ref/log.csv")" ]; then ok
    else nowall "$2/log.csv" >"$TMPD/l1"; nowall "$TMPD/ref/log.csv" >"$TMPD/l2"; ko "$1: resumed log differs: $(diff "$TMPD/l1" "$TMPD/l2" | head -5)"; fi
    if cmp -s "$2/best.genome" "$TMPD/ref/best.genome" && cmp -s "$2/best.lattice" "$TMPD/ref/best.lattice"; then ok
    else ko "$1: resumed best genome or lattice differs"; fi
    if [ "$(sumval "$2" run_hash)" = "$(sumval "$TMPD/ref" run_hash)" ]; then ok; else ko "$1: run hash differs"; fi
    if cmp -s "$2/evals.csv" "$TMPD/ref/evals.csv"; then ok
    else ko "$1: resumed evals.csv differs: $(diff "$2/evals.csv" "$TMPD/ref/evals.csv" | head -4)"; fi
    # the summary's step account covers the whole run, the part before the interruption included
    if [ -n "$(acct "$2")" ] && [ "$(acct "$2")" = "$(acct "$TMPD/ref")" ]; then ok
    else ko "$1: resumed step account differs: $(acct "$2" | tr '\n' ' ') / $(acct "$TMPD/ref" | tr '\n' ' ')"; fi
}
interrupt INT:27 4
interrupt TERM:36 6
interrupt KILL:50 8
# checkpoints at most every N seconds instead of every generation: the log has rows the
# checkpoint has not seen, which the resume cuts back and does again. With 3600 s the only
# checkpoint before the kill is the first one (before any evaluation), on any machine.
d="$TMPD/slow"
AMORPH_TEST_INTERRUPT=KILL:50 $E --out "$d" $L --checkpoint-seconds 3600 >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ] && [ $(($(wc -l <"$d/log.csv") - 1)) -eq 8 ] && [ $(($(wc -l <"$d/evals.csv") - 1)) -eq 48 ] &&
   grep -qx "evaluations 0" "$d/checkpoint.txt"; then ok
else ko "checkpoint_seconds 3600, kill -9 at 50: exit $rc, $(($(wc -l <"$d/log.csv") - 1)) rows, checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt")"; fi
resumed "checkpoint_seconds 3600" "$d"
# every second: whichever checkpoints the machine's speed gave, the resume ends the same
d="$TMPD/slow1"
AMORPH_TEST_INTERRUPT=KILL:50 $E --out "$d" $L --checkpoint-seconds 1 >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ]; then ok; else ko "checkpoint_seconds 1, kill -9 at 50: exit $rc"; fi
resumed "checkpoint_seconds 1" "$d"
# two processes on one run folder: the first stops itself (SIGSTOP) just before evaluation 15,
# holding the folder; a second one, resuming or starting there, is refused with one line; the
# first then ends exactly like the reference run, its logs without a duplicated row
d="$TMPD/two"
AMORPH_TEST_INTERRUPT=STOP:14 $E --out "$d" $L >"$TMPD/out1" 2>"$TMPD/err1" &
pid=$!
k=0
while [ -e "/proc/$pid" ] && [ "$(cut -d' ' -f3 "/proc/$pid/stat" 2>/dev/null)" != T ] && [ $k -lt 1200 ]; do sleep 0.1; k=$((k + 1)); done
if [ "$(cut -d' ' -f3 "/proc/$pid/stat" 2>/dev/null)" = T ]; then ok; else ko "the first process did not stop itself"; fi
expect_fail 2 "two/lock: in use by process $pid \(another amorph is working in" "$AMORPH" evolve --resume "$d" --quiet
expect_fail 2 "two/lock: in use by process $pid" $E --out "$d"
kill -CONT $pid
wait $pid; rc=$?
if [ $rc -eq 0 ]; then ok; else ko "the first process, continued: exit $rc: $(cat "$TMPD/err1")"; fi
if [ "$(nowall "$d/log.csv")" = "$(nowall "$TMPD/ref/log.csv")" ] && cmp -s "$d/evals.csv" "$TMPD/ref/evals.csv"; then ok
else ko "two processes on one folder: the logs differ from the reference"; fi
# a run folder from a build without evals.csv resumes; its evals.csv starts at the checkpoint
d="$TMPD/noevals"
AMORPH_TEST_INTERRUPT=KILL:50 $E --out "$d" $L >"$TMPD/out" 2>"$TMPD/err"
rm -f "$d/evals.csv"
expect_ok "$AMORPH" evolve --resume "$d" --quiet --no-pictures
if [ "$(head -n 1 "$d/evals.csv")" = "$(head -n 1 "$TMPD/ref/evals.csv")" ] &&
   [ "$(tail -n +2 "$d/evals.csv")" = "$(tail -n +50 "$TMPD/ref/evals.csv")" ]; then ok
else ko "evals.csv of a resumed run without one: $(sed -n 2p "$d/evals.csv")"; fi
# a malformed setting is refused before anything is written
for v in INT HUP:3 INT: INT:x INT:-2 KILL:3:4 int:3 " INT:3" TERM:5x; do
    expect_fail 2 "AMORPH_TEST_INTERRUPT = '$v': expected SIG:N" env AMORPH_TEST_INTERRUPT="$v" $E --out "$TMPD/bad2"
done
expect_fail 2 "AMORPH_TEST_INTERRUPT = 'x'" env AMORPH_TEST_INTERRUPT=x "$AMORPH" experiment representations --out "$TMPD/bad2"
if [ ! -e "$TMPD/bad2" ]; then ok; else ko "a refused AMORPH_TEST_INTERRUPT left a folder behind"; fi
# a point past the end of the run never comes: the run ends normally
expect_ok env AMORPH_TEST_INTERRUPT=INT:120 $E --out "$TMPD/late" $L
if [ "$(sumval "$TMPD/late" run_hash)" = "$(sumval "$TMPD/ref" run_hash)" ]; then ok; else ko "INT:120 changed the run"; fi

# --- progress: a live line on a terminal, plain lines otherwise, nothing with --quiet ---
P="$AMORPH evolve --config $TMPD/small.cfg --evaluations 18 --no-pictures"
$P --out "$TMPD/p1" >"$TMPD/out" 2>"$TMPD/err"
if [ "$(grep -c 'evaluations 18/18  best' "$TMPD/err")" -eq 1 ] && ! grep -q "$(printf '\r')" "$TMPD/err"; then ok
else ko "progress without a terminal: $(head -c 300 "$TMPD/err")"; fi
$P --out "$TMPD/p2" --quiet >"$TMPD/out" 2>"$TMPD/err"
if [ ! -s "$TMPD/err" ] && grep -q "^run_hash = " "$TMPD/out"; then ok; else ko "--quiet printed: $(head -c 300 "$TMPD/err")"; fi
if command -v script >/dev/null 2>&1; then
    script -qc "$P --out $TMPD/p3" /dev/null >"$TMPD/tty" 2>&1
    esc=$(printf '\r\033\[K')
    if [ "$(grep -o "${esc}evaluations [0-9]*/18" "$TMPD/tty" | wc -l)" -ge 3 ] && grep -q "s left" "$TMPD/tty"; then ok
    else ko "progress on a terminal: $(od -c "$TMPD/tty" | head -5)"; fi
else
    echo "SKIPPED: terminal progress test (no 'script' command)"
fi
"$AMORPH" evolve --help-config | grep -qE "^  population +20 +individuals" && ok || ko "--help-config"

# --- experiments ---
expect_ok "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/exp" --quiet
for v in dct-1 dct-2 cppn-1 cppn-2 gmx-1 gmx-2; do
    if [ -s "$TMPD/exp/$v/log.csv" ]; then ok; else ko "experiment lacks run $v"; fi
done
if grep -q "^representation = cppn$" "$TMPD/exp/cppn-2/config.txt" && grep -q "^seed = 12$" "$TMPD/exp/cppn-2/config.txt"; then ok
else ko "experiment run settings: $(grep -E 'representation|seed' "$TMPD/exp/cppn-2/config.txt")"; fi
if [ "$(grep -c '^gmx,' "$TMPD/exp/results.csv")" -eq 2 ] && head -n 1 "$TMPD/exp/results.csv" | grep -q "variant,evaluations,mean_best,stderr_best,runs"; then ok
else ko "results.csv: $(head -c 300 "$TMPD/exp/results.csv")"; fi
if grep -q "evaluations.*dct.*cppn.*gmx" "$TMPD/out"; then ok; else ko "experiment table: $(head -c 300 "$TMPD/out")"; fi
# the summary: the last row's means (those of results.csv) and the variants ranked by them
rank=$(for v in dct cppn gmx; do grep "^$v,12," "$TMPD/exp/results.csv" | cut -d, -f1,3; done | sort -t, -k2 -g -r | cut -d, -f1 | tr '\n' ' ')
if grep -qx "ranking = ${rank% }" "$TMPD/exp/summary.txt" && grep -qx "ranking = ${rank% }" "$TMPD/out" &&
   grep -q "\"ranking\": \[\"$(echo ${rank% } | sed 's/ /", "/g')\"\]}" "$TMPD/exp/summary.json"; then ok
else ko "experiment ranking '$rank': $(grep ranking "$TMPD/exp/summary.txt") / $(head -c 400 "$TMPD/exp/summary.json")"; fi
expect_ok "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/exp" --quiet --json
if [ "$(wc -l <"$TMPD/out")" -eq 1 ] && cmp -s "$TMPD/out" "$TMPD/exp/summary.json"; then ok
else ko "experiment --json: $(head -c 400 "$TMPD/out")"; fi
# mean and standard error agree with the two runs' logs
m=$(awk -F, -v a="$(tail -n 1 "$TMPD/exp/gmx-1/log.csv" | cut -d, -f3)" -v b="$(tail -n 1 "$TMPD/exp/gmx-2/log.csv" | cut -d, -f3)" \
    'BEGIN { m = (a + b) / 2; s = sqrt(((a - m) ^ 2 + (b - m) ^ 2) / 1) / sqrt(2); printf "%.6g %.6g", m, s }')
got=$(grep '^gmx,12,' "$TMPD/exp/results.csv" | awk -F, '{ printf "%.6g %.6g", $3, $4 }')
if [ "$m" = "$got" ]; then ok; else ko "gmx mean/stderr at 12 evaluations: want $m, got $got"; fi
# the same command again: every run is complete, nothing changes
before=$(cat "$TMPD"/exp/*/log.csv | cut -d, -f1-7 | cksum)
expect_ok "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/exp" --quiet
if [ "$(cat "$TMPD"/exp/*/log.csv | cut -d, -f1-7 | cksum)" = "$before" ]; then ok; else ko "re-running a finished experiment changed it"; fi
# a damaged row in a run's log is refused with its file and line (the library's log reader), not
# taken for the end of the log (which made a shorter table)
cp -r "$TMPD/exp" "$TMPD/expbad"
sed -i '3s/^\([0-9]*,[0-9]*\),[^,]*,/\1,zero,/' "$TMPD/expbad/gmx-1/log.csv"
expect_fail 2 "gmx-1/log.csv:3: best \\(column 3\\): not a number: 'zero'" \
    "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/expbad" --quiet
# an experiment interrupted in its first generation (Ctrl-C at evaluation 9 of the 6 runs, which
# evolve in lockstep: one wave) and run again ends the same
env AMORPH_TEST_INTERRUPT=INT:9 "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/exp2" --quiet \
    >"$TMPD/out" 2>"$TMPD/err"; rc=$?
ck=$(ls "$TMPD"/exp2/*/checkpoint.txt 2>/dev/null | wc -l)
if [ $rc -eq 130 ] && grep -q "resume the experiment with the same command and --out $TMPD/exp2" "$TMPD/err" && [ "$ck" -eq 6 ] &&
    [ ! -e "$TMPD/exp2/results.csv" ]; then ok
else ko "experiment interrupted: exit $rc, $ck checkpoints (want all 6 runs started at once), stderr: $(cat "$TMPD/err")"; fi
expect_ok "$AMORPH" experiment representations --config "$TMPD/small.cfg" --evals 12 --runs 2 --out "$TMPD/exp2" --quiet
if cmp -s "$TMPD/exp/results.csv" "$TMPD/exp2/results.csv"; then ok; else ko "an interrupted experiment ended differently"; fi
expect_fail 2 "unknown experiment 'colours'" "$AMORPH" experiment colours
expect_fail 2 "--runs needs" "$AMORPH" experiment friction --runs 0
for x in three-materials dynamic friction; do
    "$AMORPH" experiment --help | grep -q "^  $x " && ok || ko "experiment --help lacks $x"
done

# --- repro: the reference run prints one hash, the same for any thread count ---
r1=$("$AMORPH" repro | sed -n 's/^repro_hash=//p'); r2=$("$AMORPH" repro --threads 3 | sed -n 's/^repro_hash=//p')
if echo "$r1" | grep -qE '^[0-9a-f]{16}$' && [ "$r1" = "$r2" ]; then ok; else ko "repro hashes '$r1' '$r2'"; fi
r3=$("$AMORPH" repro --seed 1 | sed -n 's/^repro_hash=//p')
if [ -n "$r3" ] && [ "$r3" != "$r1" ]; then ok; else ko "repro --seed 1 gave the reference hash"; fi
expect_fail 2 "unknown option '--out'" "$AMORPH" repro --out x

# the sustained score (docs/evolve.md, Fitness): refused without cycles after its window, naming the
# key; a run scored so records as each body's fitness its travel per cycle after cycle 10, which
# `amorph sim` of the run's best gives as sustained_travel, beside a larger whole-movement travel
expect_fail 2 "score = sustained needs cycles above sustained_from .cycles = 10, sustained_from = 10.: say cycles = 30" \
    "$AMORPH" evolve --score sustained --evaluations 20 --out "$TMPD/sus0"
check "a refused sustained run writes no folder" test ! -e "$TMPD/sus0"
printf 'score = sustained\ncycles = 8\nsustained_from = 8\n' >"$TMPD/sus.cfg"
expect_fail 2 "sus.cfg:1: .*score = sustained needs cycles above sustained_from" "$AMORPH" evolve --config "$TMPD/sus.cfg" --out "$TMPD/sus1"
"$AMORPH" evolve --score sustained --cycles 12 --evaluations 20 --population 10 --workspace 6 --quiet --no-pictures --out "$TMPD/sus" >/dev/null 2>&1
check "sustained run: config.txt names the score" grep -q '^score = sustained$' "$TMPD/sus/config.txt"
sim_sus=$("$AMORPH" sim "$TMPD/sus" 2>/dev/null)
fit=$(echo "$sim_sus" | sed -n 's/^fitness = //p') sus=$(echo "$sim_sus" | sed -n 's/^sustained_travel = //p') tr=$(echo "$sim_sus" | sed -n 's/^travel = //p')
check "sustained run: the best's fitness is its sustained travel ($fit, $sus)" test -n "$fit" -a "$fit" = "$sus"
check "sustained run: the best's travel ($tr) is more than a cycle's ($sus)" awk -v t="$tr" -v s="$sus" 'BEGIN { exit !(t > s && s > 0) }'
best_row=$(awk -F, 'NR > 1 && $10 > b { b = $10 } END { printf "%.9g", b }' "$TMPD/sus/evals.csv")
check "sustained run: evals.csv's best fitness ($best_row) is the best's sustained travel ($sus)" \
    awk -v a="$best_row" -v b="$sus" 'BEGIN { d = a - b; exit !(d < 1e-12 && d > -1e-12) }'

# issue 46: one bound on every evaluation (10^9 steps, docs/physics.md): a configuration over it is
# refused before the run starts, naming the file and line or the flag (timeout: the builds before
# started the run, whose first evaluation took 10^12 steps)
expect_fail 2 "^amorph: tests/data/hostile/cycles_period.cfg:3: period_steps = 10000000: up to 1e\+12 steps an evaluation .*over the budget of 1e\+09" \
    timeout -k 5 60 "$AMORPH" evolve --config tests/data/hostile/cycles_period.cfg --population 2 --evaluations 2 --out "$TMPD/overbudget" --quiet
check "a run over the budget makes no folder" [ ! -e "$TMPD/overbudget" ]
expect_fail 2 "^amorph: evolve: dt_frac = 1e-06: up to 7.2e\+10 steps an evaluation" \
    timeout -k 5 60 "$AMORPH" evolve --dt_frac 1e-6 --population 2 --evaluations 2 --out "$TMPD/overbudget" --quiet
expect_fail 2 "^amorph: evolve: cycles = 100000: up to .* over the budget" \
    timeout -k 5 60 "$AMORPH" evolve --cycles 100000 --period_s 0.02 --population 2 --evaluations 2 --out "$TMPD/overbudget" --quiet
# the largest realistic settings stay inside: 30-cycle sustained scoring, the dynamic experiment's period
expect_ok "$AMORPH" evolve --print-config --score sustained --cycles 30 --period_steps 250

summary tests/cli_evolve.sh
