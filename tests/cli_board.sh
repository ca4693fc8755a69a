#!/bin/sh
# tests/cli_board.sh: what the board profile does its own way, on a build of it for this machine
# ($BOARD_BUILD/amorph, PROFILE=board on the POSIX port, exported by `make test`; skipped when
# unset). The desktop-only commands answer "not in this build"; files stream through one line
# buffer and a 512-byte output buffer, so a checkpoint many times their size is written and read
# back exactly (a resumed run equals an uninterrupted one), long lines and damaged files are
# refused in one line; the evolver places offspring two at a time. With AMORPH_QEMU_BOARD set to a
# bare-metal build (build/cortex-m4/amorph) the file round trip also runs on QEMU's semihosting.
# Run from the repository root.
. tests/shlib.sh

if [ -z "${BOARD_BUILD:-}" ] || ! [ -x "$BOARD_BUILD/amorph" ]; then
    echo "cli_board: BOARD_BUILD not set or not built: board profile tests skipped"
    summary cli_board
    exit $?
fi
B="$BOARD_BUILD/amorph"
if ! "$B" --help 2>/dev/null | grep -q 'profile=board'; then
    ko "$B is not a board profile build"
    summary cli_board
    exit $?
fi

# --- left out of the board build: one line, exit 2, no file written ---
expect_fail 2 "render: not in this build" "$B" render --scene cube:2 --out "$TMPD/x.png"
expect_fail 2 "plot: not in this build" "$B" plot "$TMPD" --out "$TMPD/x.svg"
expect_fail 2 "view: not in this build" "$B" view --scene cube:2 --out "$TMPD/x.html"
expect_fail 2 "export --vxa: not in this build" "$B" export --scene cube:2 --vxa "$TMPD/x.vxa"
expect_fail 2 "voxcad_quadruped.vxa: a VXA file: not in this build" "$B" sim tests/data/voxcad_quadruped.vxa
expect_fail 2 "bench --kernels: not in this build" "$B" bench --kernels
# the board's palette holds three materials (its RAM, docs/porting.md): the follow-up's four and a
# fourth materialK are refused in one line, the seed's three evolve
expect_fail 2 "palette = unshackled: 4 materials; the board profile's palette holds at most 3" "$B" evolve --palette unshackled --out "$TMPD/p4"
printf 'material4 = x modulus=1e6 density=1000 cte=0 phase=0\n' >"$TMPD/p4.cfg"
expect_fail 2 "p4.cfg:1: material4: a palette holds at most 3 materials \(the board profile\)" "$B" evolve --config "$TMPD/p4.cfg" --out "$TMPD/p4"
expect_fail 2 "sim --scalars: not in this build" "$B" sim --scene cube:2 --trajectory "$TMPD/t.csv" --scalars
check "sim --scalars on the board left a file" [ ! -e "$TMPD/t.csv" ]
expect_fail 2 "eval: not in this build" "$B" eval </dev/null
if [ ! -e "$TMPD/x.png" ] && [ ! -e "$TMPD/x.vxa" ]; then ok; else ko "a refused command wrote a file"; fi
# the lattice export works and reads back
expect_ok "$B" export --scene sphere:6 --lattice "$TMPD/s.lattice"
f1=$("$B" sim --scene sphere:6 --cycles 1 | sed -n 's/^hash = //p'); f2=$("$B" sim "$TMPD/s.lattice" --cycles 1 | sed -n 's/^hash = //p')
if [ -n "$f1" ] && [ "$f1" = "$f2" ]; then ok; else ko "sphere:6 and its exported lattice simulate differently: $f1 $f2"; fi

# --- genomes and lattices through the line buffer ---
for r in dct cppn gmx; do
    expect_ok "$B" random --repr "$r" --materials 3 --seed 4 --out "$TMPD/$r.genome"
    expect_ok "$B" express "$TMPD/$r.genome" --out "$TMPD/$r.lattice"
    "$B" export "$TMPD/$r.genome" --lattice - >"$TMPD/$r.exported" 2>"$TMPD/err"
    if cmp -s "$TMPD/$r.lattice" "$TMPD/$r.exported"; then ok; else ko "$r: express and export --lattice differ"; fi
    a=$("$B" sim "$TMPD/$r.genome" --cycles 1 | grep -v '^robot\|^wall'); b=$("$B" sim "$TMPD/$r.lattice" --cycles 1 | grep -v '^robot\|^wall')
    if [ -n "$a" ] && [ "$a" = "$b" ]; then ok; else ko "$r: the genome and its lattice simulate differently: $a / $b"; fi
done
# --- the board's simulator keeps constants per material, adds each chunk of links to its voxels'
# totals at once and derives velocities from momenta where read; it must compute what the
# desktop's computes (per-link results gathered by each voxel), bit for bit: random robots of the
# board's workspace, with self-contact, on both builds ---
D="${BUILD:-build}/amorph"
if [ -x "$D" ]; then
    contact=0
    for r in dct cppn gmx; do
        for seed in 1 2 5; do
            "$B" random --repr "$r" --materials 3 --seed "$seed" --out "$TMPD/eq.genome" >/dev/null 2>&1
            "$B" express "$TMPD/eq.genome" --out "$TMPD/eq-$r$seed.lattice" >/dev/null 2>&1 || continue
            a=$("$D" sim "$TMPD/eq-$r$seed.lattice" --cycles 3 --collisions on | grep -v '^robot\|^wall')
            b=$("$B" sim "$TMPD/eq-$r$seed.lattice" --cycles 3 --collisions on | grep -v '^robot\|^wall')
            if [ -n "$a" ] && [ "$a" = "$b" ]; then ok; else ko "$r seed $seed: board and desktop simulate differently: $a / $b"; fi
            case "$a" in *"max_pairs = 0"*) ;; *max_pairs*) contact=$((contact + 1)) ;; esac
        done
    done
    if [ "$contact" -ge 6 ]; then ok; else ko "only $contact of the compared robots had self-contact candidates"; fi
else
    echo "cli_board: $D not built: board/desktop comparison skipped"
fi

# a comment of 1023 characters is a line; one of 1024 is too long, said in one line
long=$(awk 'BEGIN { for (i = 0; i < 1021; i++) printf "x" }')
{ echo "amorph-lattice 1"; echo "# $long"; echo "size 1 1 1"; echo "layer 0"; echo "1"; } >"$TMPD/ok.lattice"
expect_ok "$B" sim "$TMPD/ok.lattice" --cycles 0
{ echo "amorph-lattice 1"; echo "# x$long"; echo "size 1 1 1"; echo "layer 0"; echo "1"; } >"$TMPD/long.lattice"
expect_fail 2 "long.lattice:2: line longer than 1023 characters" "$B" sim "$TMPD/long.lattice"
{ head -n 3 "$TMPD/gmx.genome"; echo "# x$long"; tail -n +4 "$TMPD/gmx.genome"; } >"$TMPD/long.genome"
expect_fail 2 "long.genome:4: line longer than 1023 characters" "$B" express "$TMPD/long.genome"
printf 'amorph-lattice 1\nsize 1 1 1\n\000layer 0\n1\n' >"$TMPD/nul.lattice"
expect_fail 2 "nul.lattice:1: binary data" "$B" sim "$TMPD/nul.lattice"

# --- evolution: a checkpoint of about 60 KB through the small buffers, resumed exactly ---
cat >"$TMPD/big.cfg" <<'CFG'
representation = dct
materials = 3
workspace = 8
population = 20
cycles = 1
period_steps = 100
relax_max_steps = 400
relax_min_steps = 50
release_steps = 100
seed = 5
CFG
E="$B evolve --config $TMPD/big.cfg --quiet"
expect_ok $E --out "$TMPD/full" --evaluations 60
expect_ok $E --out "$TMPD/part" --evaluations 40
size=$(wc -c <"$TMPD/part/checkpoint.txt")
if [ "$size" -gt 20000 ]; then ok; else ko "the checkpoint is only $size bytes: not a stress of the buffers"; fi
cp -r "$TMPD/part" "$TMPD/bad"
expect_ok "$B" evolve --resume "$TMPD/part" --evaluations 60 --quiet
if [ "$(sumval "$TMPD/part" run_hash)" = "$(sumval "$TMPD/full" run_hash)" ] && [ "$(nowall "$TMPD/part/log.csv")" = "$(nowall "$TMPD/full/log.csv")" ] &&
   cmp -s "$TMPD/part/best.genome" "$TMPD/full/best.genome" && cmp -s "$TMPD/part/best.lattice" "$TMPD/full/best.lattice"; then ok
else ko "resumed run differs from the uninterrupted one: $(sumval "$TMPD/part" run_hash) vs $(sumval "$TMPD/full" run_hash)"; fi
# an interrupted log (rows past the checkpoint) is cut back on resume
cp -r "$TMPD/bad" "$TMPD/extra"
tail -n 1 "$TMPD/extra/log.csv" >>"$TMPD/extra/log.csv"
expect_ok "$B" evolve --resume "$TMPD/extra" --evaluations 60 --quiet
if [ "$(nowall "$TMPD/extra/log.csv")" = "$(nowall "$TMPD/full/log.csv")" ]; then ok; else ko "the extra log row was not cut"; fi
# damaged checkpoints: refused in one line, the run folder untouched
snap() { (cd "$1" && cat config.txt log.csv best.genome checkpoint.txt | cksum); }
before=$(snap "$TMPD/bad")
sed -i 's/^evaluations 40$/evaluations 41/' "$TMPD/bad/checkpoint.txt"
expect_fail 2 "checkpoint.txt:[0-9]+: checksum mismatch" "$B" evolve --resume "$TMPD/bad" --quiet
cp "$TMPD/full/checkpoint.txt" "$TMPD/bad/checkpoint.txt"
head -c 30000 "$TMPD/part/checkpoint.txt" >"$TMPD/bad/checkpoint.txt"
expect_fail 2 "missing checksum" "$B" evolve --resume "$TMPD/bad" --quiet
printf 'amorph-checkpoint 1\n\000\n' >"$TMPD/bad/checkpoint.txt"
expect_fail 2 "binary data in a checkpoint" "$B" evolve --resume "$TMPD/bad" --quiet
# the reference evolution (offspring two at a time) prints make repro's pinned hash
h1=$("$B" repro | sed -n 's/^repro_hash=//p')
pin_float=$(sed -n 's/^float) REPRO_EXPECT=${REPRO_EXPECT:-\([0-9a-f]*\)}.*/\1/p' tools/repro.sh)
pin_fixed=$(sed -n 's/^fixed) REPRO_EXPECT=${REPRO_EXPECT_FIXED:-\([0-9a-f]*\)}.*/\1/p' tools/repro.sh)
if [ -n "$pin_float" ] && [ -n "$pin_fixed" ] && { [ "$h1" = "$pin_float" ] || [ "$h1" = "$pin_fixed" ]; }; then ok
else ko "repro hash $h1 differs from make repro's pins (tools/repro.sh: float '$pin_float', fixed '$pin_fixed')"; fi

# --- an experiment's table ---
# the board's small run (tests/data/board_small.cfg; tools/stack_peak.sh measures the stack with it)
cp tests/data/board_small.cfg "$TMPD/small.cfg"
expect_ok "$B" experiment three-materials --evals 12 --runs 2 --config "$TMPD/small.cfg" --out "$TMPD/exp" --quiet
if [ "$(head -n 1 "$TMPD/exp/results.csv")" = "variant,evaluations,mean_best,stderr_best,runs" ] &&
   [ "$(wc -l <"$TMPD/exp/results.csv")" -eq 5 ]; then ok
else ko "results.csv: $(head -c 300 "$TMPD/exp/results.csv")"; fi

# --- tools/board.sh, the QEMU command line of every board run: what it refuses (without QEMU) ---
expect_fail 2 "usage: tools/board.sh" sh tools/board.sh mps2-an386
expect_fail 2 "board.sh: 'lm3s6965evb': not a board machine" sh tools/board.sh lm3s6965evb "$B"
expect_fail 2 "board.sh: $TMPD/none: no such file" sh tools/board.sh mps2-an386 "$TMPD/none"
expect_fail 2 "board.sh: argument 'a b': semihosting splits the command line at spaces" sh tools/board.sh riscv32-virt "$B" sim "a b"
expect_fail 2 "board.sh: BOARD_TIMEOUT='0': a whole number" env BOARD_TIMEOUT=0 sh tools/board.sh mps2-an385 "$B"
# the command line it hands QEMU, seen by a stand-in qemu on PATH that prints its arguments one a
# line and ends with status 3: commas doubled, the machine's options, -icount on request, the
# program's status passed on
mkdir -p "$TMPD/fakeqemu"
printf '#!/bin/sh\nfor a in "$@"; do echo "$a"; done\nexit 3\n' >"$TMPD/fakeqemu/qemu-system-riscv32"
cp "$TMPD/fakeqemu/qemu-system-riscv32" "$TMPD/fakeqemu/qemu-system-arm"
chmod +x "$TMPD/fakeqemu/qemu-system-riscv32" "$TMPD/fakeqemu/qemu-system-arm"
PATH="$TMPD/fakeqemu:$PATH" sh tools/board.sh riscv32-virt "$B" sim --materials a,b >"$TMPD/q.out" 2>&1
rc=$?
if [ $rc -eq 3 ] && grep -qx "virt" "$TMPD/q.out" && grep -qx -- "-bios" "$TMPD/q.out" && ! grep -q -- "-icount" "$TMPD/q.out" &&
   grep -qx "enable=on,target=native,arg=amorph,arg=sim,arg=--materials,arg=a,,b" "$TMPD/q.out"; then ok
else ko "board.sh riscv32-virt: status $rc (want 3), arguments: $(tr '\n' ' ' <"$TMPD/q.out")"; fi
PATH="$TMPD/fakeqemu:$PATH" BOARD_ICOUNT=1 sh tools/board.sh mps2-an385 "$B" repro >"$TMPD/q.out" 2>&1
if grep -qx "mps2-an385" "$TMPD/q.out" && grep -qx "shift=0" "$TMPD/q.out" && ! grep -q -- "-bios" "$TMPD/q.out" &&
   grep -qx "enable=on,target=native,arg=amorph,arg=repro" "$TMPD/q.out"; then ok
else ko "board.sh mps2-an385 with BOARD_ICOUNT=1, arguments: $(tr '\n' ' ' <"$TMPD/q.out")"; fi

# --- on the bare-metal port (QEMU, semihosting), when a build is named ---
if [ -n "${AMORPH_QEMU_BOARD:-}" ] && command -v qemu-system-arm >/dev/null 2>&1; then
    q() { sh tools/board.sh mps2-an386 "$AMORPH_QEMU_BOARD" "$@"; }
    mkdir -p "$TMPD/qfull" "$TMPD/qpart"
    q evolve --config "$TMPD/small.cfg" --evaluations 24 --out "$TMPD/qfull" --quiet >/dev/null 2>&1
    q evolve --config "$TMPD/small.cfg" --evaluations 12 --out "$TMPD/qpart" --quiet >/dev/null 2>&1
    q evolve --resume "$TMPD/qpart" --evaluations 24 --quiet >/dev/null 2>&1
    if [ -n "$(sumval "$TMPD/qfull" run_hash)" ] && [ "$(sumval "$TMPD/qpart" run_hash)" = "$(sumval "$TMPD/qfull" run_hash)" ] &&
       [ "$(nowall "$TMPD/qpart/log.csv")" = "$(nowall "$TMPD/qfull/log.csv")" ] && cmp -s "$TMPD/qpart/best.genome" "$TMPD/qfull/best.genome"; then ok
    else ko "QEMU: resumed run differs: $(sumval "$TMPD/qpart" run_hash) vs $(sumval "$TMPD/qfull" run_hash)"; fi
    echo "cli_board: bare-metal round trip on QEMU with $AMORPH_QEMU_BOARD"
fi
summary cli_board
