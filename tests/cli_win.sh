#!/bin/sh
# tests/cli_win.sh: the Windows build (port/win32, make TARGET=win64) under wine, against the Linux
# build $BUILD/amorph of the same number type, both of the desktop profile. `make test` builds it
# into $BUILD/windows and sets WIN_BUILD when x86_64-w64-mingw32-gcc and wine are installed;
# skipped otherwise. Checked: the reference computation and a small evolution give the Linux build's
# results on 2 and 3 Windows threads; a run interrupted at a counted evaluation (Ctrl-C's path,
# and TerminateProcess as kill -9) resumes to the uninterrupted run, removing the temporaries a
# killed writer left; a run held (every thread suspended) keeps its folder locked against a
# second process, whose message names the owner, and resumes after a kill -9 from outside;
# checkpoints move between Linux and Windows both ways; folders and devices are refused as input.
# Run from the repository root; wine runs through tools/wine.sh (prefix build/wine).
. tests/shlib.sh

if [ -z "${WIN_BUILD:-}" ] || ! [ -f "$WIN_BUILD/amorph.exe" ]; then
    echo "cli_win: WIN_BUILD not set or not built: Windows tests skipped"
    summary cli_win
    exit $?
fi
if ! command -v wine >/dev/null 2>&1; then
    echo "cli_win: wine not found: Windows tests skipped"
    summary cli_win
    exit $?
fi
WEXE="$WIN_BUILD/amorph.exe"
# W ARGS...: the Windows build under wine; the console's CR LF line ends (the C runtime's text
# mode) become LF, so its output compares with the Linux build's
# amorph never fails without a message; an exit 1 or 127 with nothing on either stream is wine
# failing to start the program (CI saw each once, in runs that passed again unchanged), so it is
# tried once more and said on stderr (a kill's 137, silent by design, is left as it is)
W() {
    tools/wine.sh "$WEXE" "$@" >"$TMPD/w.out" 2>"$TMPD/w.err"
    r=$?
    if { [ $r -eq 1 ] || [ $r -eq 127 ]; } && ! [ -s "$TMPD/w.out" ] && ! [ -s "$TMPD/w.err" ]; then
        echo "cli_win: wine exited $r with no output: started again ($*)" >&2
        tools/wine.sh "$WEXE" "$@" >"$TMPD/w.out" 2>"$TMPD/w.err"
        r=$?
    fi
    tr -d '\r' <"$TMPD/w.out"
    tr -d '\r' <"$TMPD/w.err" >&2
    return $r
}
L="$AMORPH"
# one wine server for the whole test, persistent, stopped at the end: left to itself it exits 3 s
# after its last program, and a program started just then may fail to start (the likely cause of
# an exit 127 with nothing run that CI saw once, at the KILL:20 step below). The first W makes the
# prefix (tools/wine.sh), whose server is then replaced by the persistent one.
WP=${AMORPH_WINEPREFIX:-$(pwd)/build/wine}
W --help >/dev/null 2>&1
WINEPREFIX="$WP" wineserver -k 2>/dev/null
WINEPREFIX="$WP" wineserver -p 2>/dev/null
trap 'WINEPREFIX="$WP" wineserver -k 2>/dev/null; rm -rf "$TMPD"' EXIT

# --- the two builds compute the same thing ---
bw=$(W --help 2>/dev/null | grep '^build:')
bl=$("$L" --help 2>/dev/null | grep '^build:')
if [ -n "$bw" ] && [ "$bw" = "$bl" ]; then ok; else ko "the Windows build is '$bw', the Linux build '$bl': build both with the same REAL and PROFILE"; fi
# the desktop profile: several threads, and a generation evaluated in one batch, so that a point
# inside it interrupts it half done (docs/evolve.md, Testing interruptions)
case "$bw" in
*profile=desktop*) ok ;;
*) ko "$WEXE: '$bw': these tests need desktop-profile builds"; summary cli_win; exit $? ;;
esac
hw=$(W repro | sed -n 's/^repro_hash=//p')
hl=$("$L" repro | sed -n 's/^repro_hash=//p')
if [ -n "$hl" ] && [ "$hw" = "$hl" ]; then ok; else ko "amorph repro: Windows $hw, Linux $hl"; fi

S="--workspace 6 --population 8 --cycles 1 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100 --evaluations 32 --quiet --no-pictures"
# same RUN REF: run folder RUN ended exactly like REF (run hash, best genome and lattice, the log
# without its wall clock, evals.csv)
same() {
    if [ -n "$(sumval "$2" run_hash)" ] && [ "$(sumval "$1" run_hash)" = "$(sumval "$2" run_hash)" ] &&
       cmp -s "$1/best.genome" "$2/best.genome" && cmp -s "$1/best.lattice" "$2/best.lattice" &&
       [ "$(nowall "$1/log.csv")" = "$(nowall "$2/log.csv")" ] && cmp -s "$1/evals.csv" "$2/evals.csv"; then ok
    else ko "$3: $1 ends in run $(sumval "$1" run_hash), $2 in $(sumval "$2" run_hash)"; fi
}
# rows DIR: the generations DIR's log holds
rows() { echo $(($(wc -l <"$1/log.csv") - 1)); }

expect_ok "$L" evolve $S --out "$TMPD/lin"
expect_ok W evolve $S --out "$TMPD/whole"
same "$TMPD/whole" "$TMPD/lin" "Windows run (threads: one per core)"
if cmp -s "$TMPD/whole/config.txt" "$TMPD/lin/config.txt"; then ok; else ko "config.txt differs between Windows and Linux (line ends?)"; fi
expect_ok W evolve $S --threads 3 --out "$TMPD/t3"
same "$TMPD/t3" "$TMPD/lin" "Windows run on 3 threads"

# --- interrupted at a counted evaluation (AMORPH_TEST_INTERRUPT), then resumed ---
# Ctrl-C's path at 20 (inside generation 3: two generations stand), SIGTERM's between generations
d="$TMPD/int"
AMORPH_TEST_INTERRUPT=INT:20 W evolve $S --out "$d" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 130 ] && grep -q "interrupted after 16 evaluations" "$TMPD/err" && grep -q "resume with: amorph evolve --resume $d\$" "$TMPD/err" &&
   [ "$(rows "$d")" -eq 2 ]; then ok
else ko "INT:20: exit $rc, $(rows "$d") rows, stderr: $(cat "$TMPD/err")"; fi
expect_ok W evolve --resume "$d" --quiet --no-pictures
same "$d" "$TMPD/whole" "resumed after INT:20"
d="$TMPD/term"
AMORPH_TEST_INTERRUPT=TERM:24 W evolve $S --out "$d" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 130 ] && [ "$(rows "$d")" -eq 3 ]; then ok; else ko "TERM:24: exit $rc, $(rows "$d") rows: $(cat "$TMPD/err")"; fi
expect_ok W evolve --resume "$d" --quiet --no-pictures
same "$d" "$TMPD/whole" "resumed after TERM:24"
# kill -9's path (TerminateProcess): exit 137, the last checkpoint stands; the resume removes the
# temporaries of killed writes (NAME.tmp.DIGITS, regular files) and nothing else
d="$TMPD/kill"
AMORPH_TEST_INTERRUPT=KILL:20 W evolve $S --out "$d" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ] && [ "$(rows "$d")" -eq 2 ] && grep -qx "evaluations 16" "$d/checkpoint.txt"; then ok
else ko "KILL:20: exit $rc, $(rows "$d") rows, checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt"): $(head -c 300 "$TMPD/err")"; fi
echo partial >"$d/checkpoint.txt.tmp.12345"
echo partial >"$d/log.csv.tmp.7"
echo mine >"$d/notes.tmp.txt"
mkdir "$d/folder.tmp.9"
expect_ok W evolve --resume "$d" --quiet --no-pictures
if [ ! -e "$d/checkpoint.txt.tmp.12345" ] && [ ! -e "$d/log.csv.tmp.7" ] && [ -f "$d/notes.tmp.txt" ] && [ -d "$d/folder.tmp.9" ]; then ok
else ko "stale temporaries after the resume: $(ls "$d" | tr '\n' ' ')"; fi
if [ -z "$(ls "$d" | grep '\.tmp\.[0-9]' | grep -v folder)" ]; then ok; else ko "temporaries left: $(ls "$d" | tr '\n' ' ')"; fi
same "$d" "$TMPD/whole" "resumed after KILL:20"

# --- one process per run folder: the first holds itself just before evaluation 17 (STOP: every
# thread suspended), a second is refused naming the owner's process id (the lock file's text);
# then the first is killed from outside and its folder resumes to the uninterrupted run. The
# checkpoint at 16 is the last file the first process writes before it holds: once it is there,
# the folder stays as it is until the kill, wherever the kill lands ---
d="$TMPD/two"
AMORPH_TEST_INTERRUPT=STOP:16 tools/wine.sh "$WEXE" evolve $S --out "$d" >"$TMPD/out1" 2>"$TMPD/err1" &
pid=$!
k=0
while ! grep -qx "evaluations 16" "$d/checkpoint.txt" 2>/dev/null && kill -0 $pid 2>/dev/null && [ $k -lt 600 ]; do sleep 0.1; k=$((k + 1)); done
owner=$(tr -d '\r\n' <"$d/lock" 2>/dev/null)
if [ -n "$owner" ]; then ok; else ko "the first process wrote no owner into its lock"; fi
expect_fail 2 "two/lock: in use by process $owner \(another amorph is working in" W evolve --resume "$d" --quiet
expect_fail 2 "two/lock: in use by process $owner" W evolve $S --out "$d"
if kill -0 $pid 2>/dev/null; then ok; else ko "the held process has ended: $(cat "$TMPD/err1")"; fi
kill -9 $pid 2>/dev/null
{ wait $pid; } 2>/dev/null; rc=$?
if [ $rc -eq 137 ] && [ "$(rows "$d")" -eq 2 ]; then ok; else ko "the held process: exit $rc, $(rows "$d") rows (want 137, 2)"; fi
expect_ok W evolve --resume "$d" --quiet --no-pictures
same "$d" "$TMPD/whole" "resumed after a kill -9 from outside"

# --- nothing written where the user did not point (issue 31) ---
# snapall DIR: every entry of DIR by its checksum, the lock included
snapall() { (cd "$1" && for f in $(ls -A | sort); do echo "$f $(cksum <"$f")"; done); }
# a refused --out on a run and a refused --resume leave the folder byte for byte, lock included
cp -r "$TMPD/whole" "$TMPD/refused"
before=$(snapall "$TMPD/refused")
expect_fail 2 "holds a run already" W evolve $S --out "$TMPD/refused"
expect_fail 2 "configuration changed: population" W evolve --resume "$TMPD/refused" --population 4 --quiet
if [ "$(snapall "$TMPD/refused")" = "$before" ]; then ok; else ko "a refused command changed the run folder (its lock?)"; fi
# a lock or a table that is a file of several names (a hard link) is refused, never written through
# (wine shows a Unix symbolic link as the file it points to, so only hard links are tried here)
printf 'secret\n' >"$TMPD/victim"
cp -r "$TMPD/whole" "$TMPD/hl" && rm "$TMPD/hl/lock" && ln "$TMPD/victim" "$TMPD/hl/lock"
expect_fail 2 "hl/lock: a file with several names \(a hard link\): refused" W evolve --resume "$TMPD/hl" --evaluations 40 --quiet --no-pictures
if [ "$(cat "$TMPD/victim")" = secret ]; then ok; else ko "a hard-linked lock was written through: '$(cat "$TMPD/victim")'"; fi
rm -rf "$TMPD/hl" && cp -r "$TMPD/whole" "$TMPD/hl" && cp "$TMPD/whole/log.csv" "$TMPD/victim" && rm "$TMPD/hl/log.csv" && ln "$TMPD/victim" "$TMPD/hl/log.csv"
expect_fail 2 "hl/log.csv: a file with several names \(a hard link\): refused" W evolve --resume "$TMPD/hl" --evaluations 40 --quiet --no-pictures
if cmp -s "$TMPD/victim" "$TMPD/whole/log.csv"; then ok; else ko "rows were appended to a hard-linked log.csv"; fi
# --out starts over a folder left before its first checkpoint, removing the dead process's temporaries
mkdir "$TMPD/early" && cp "$TMPD/whole/config.txt" "$TMPD/early/" && echo partial >"$TMPD/early/checkpoint.txt.tmp.999999"
echo partial >"$TMPD/early/log.csv.tmp.999999.00112233aabbccdd"
expect_ok W evolve $S --out "$TMPD/early"
if [ ! -e "$TMPD/early/checkpoint.txt.tmp.999999" ] && [ ! -e "$TMPD/early/log.csv.tmp.999999.00112233aabbccdd" ]; then ok
else ko "--out left a dead process's temporaries: $(ls "$TMPD/early" | tr '\n' ' ')"; fi
same "$TMPD/early" "$TMPD/whole" "a run started over by --out"
# a write into a folder that is not there names the user's file, not its temporary
expect_fail 1 "nodir/out.lattice: cannot create: " W export --scene cube:2 --lattice "$TMPD/nodir/out.lattice"
if ! grep -q '\.tmp\.' "$TMPD/w.err"; then ok; else ko "the message names the temporary: $(cat "$TMPD/w.err")"; fi

# --- checkpoints cross: Linux's resumes on Windows, Windows's on Linux ---
d="$TMPD/fromlin"
expect_ok "$L" evolve $S --evaluations 16 --out "$d"
expect_ok W evolve --resume "$d" --evaluations 32 --quiet --no-pictures
same "$d" "$TMPD/lin" "a Linux checkpoint resumed on Windows"
d="$TMPD/fromwin"
AMORPH_TEST_INTERRUPT=KILL:20 W evolve $S --out "$d" >/dev/null 2>&1
expect_ok "$L" evolve --resume "$d" --quiet --no-pictures
same "$d" "$TMPD/lin" "a Windows checkpoint resumed on Linux"

# --- input files are regular files: a folder and a device are refused at once ---
mkdir "$TMPD/folder.lattice"
expect_fail 2 "folder.lattice: a folder, neither a run folder" W sim "$TMPD/folder.lattice"
expect_fail 2 "NUL: not a regular file" W sim NUL
expect_fail 2 "exists and is not a directory" W evolve $S --out "$TMPD/lin/config.txt"
summary cli_win
