# tests/cli_vxa.sh: VoxCAD files through the command (docs/vxa.md): amorph export --vxa, amorph sim
# FILE.vxa, warnings for unsupported tags, exit status 2 with one "FILE:LINE: problem" line for
# malformed or oversized files, and no output file left behind by a failed export.
. tests/shlib.sh

D=$TMPD/vxa
mkdir -p "$D"
hash_of() { grep '^hash = ' "$1" | cut -d' ' -f3; }
# the size of the scenes, within every profile
N=$("$AMORPH" --help | sed -n 's/.*workspace up to \([0-9]*\)^3.*/\1/p')
S=6; [ "$N" -ge 8 ] && S=8

# export then import through the command: the same robot simulates to the same state
expect_ok "$AMORPH" export --scene sphere:$S --vxa "$D/sphere.vxa"
if head -n 2 "$D/sphere.vxa" | grep -q '<VXA Version="1.1">' && grep -q '<Structure Compression="ASCII_READABLE">' "$D/sphere.vxa"
then ok; else ko "sphere.vxa does not look like VXA 1.1"; fi
"$AMORPH" sim --scene sphere:$S --cycles 2 >"$D/direct.out" 2>&1
"$AMORPH" sim "$D/sphere.vxa" --cycles 2 >"$D/vxa.out" 2>"$D/vxa.err"
if [ -n "$(hash_of "$D/direct.out")" ] && [ "$(hash_of "$D/direct.out")" = "$(hash_of "$D/vxa.out")" ]; then ok
else ko "sim of the exported VXA differs: $(hash_of "$D/direct.out") vs $(hash_of "$D/vxa.out")"; fi
if [ ! -s "$D/vxa.err" ]; then ok; else ko "our own VXA gave warnings: $(head -c 300 "$D/vxa.err")"; fi

# the lattice read back from the VXA is the lattice written directly, byte for byte
expect_ok "$AMORPH" export --scene sphere:$S --lattice "$D/direct.lattice"
expect_ok "$AMORPH" export "$D/sphere.vxa" --lattice "$D/back.lattice"
if cmp -s "$D/direct.lattice" "$D/back.lattice"; then ok; else ko "lattice -> vxa -> lattice differs"; fi
# and a VXA written from a VXA is the same file
expect_ok "$AMORPH" export "$D/sphere.vxa" --vxa "$D/again.vxa"
if cmp -s "$D/sphere.vxa" "$D/again.vxa"; then ok; else ko "vxa -> vxa differs"; fi

# a genome exports too, and simulates the same as a VXA file
expect_ok "$AMORPH" random --repr gmx --size 5 --seed 1 --out "$D/g.genome"
expect_ok "$AMORPH" export "$D/g.genome" --vxa "$D/g.vxa"
"$AMORPH" sim "$D/g.genome" --cycles 1 --relax-max 50 >"$D/g1.out" 2>&1
"$AMORPH" sim "$D/g.vxa" --cycles 1 --relax-max 50 >"$D/g2.out" 2>&1
if [ -n "$(hash_of "$D/g1.out")" ] && [ "$(hash_of "$D/g1.out")" = "$(hash_of "$D/g2.out")" ]; then ok
else ko "genome and its VXA simulate differently: $(cat "$D/g1.out" "$D/g2.out" | head -c 600)"; fi
# a run folder's evaluation travels with its robot (<Amorph>'s <Evaluation>): sim of the VXA is
# sim of the run, 4 cycles, its release window and direction, to the same state; a flag still wins
expect_ok "$AMORPH" evolve --workspace 5 --population 4 --evaluations 8 --cycles 4 --release_steps 300 --fitness x \
    --quiet --no-pictures --out "$D/run"
expect_ok "$AMORPH" export "$D/run" --vxa "$D/run.vxa"
check "the run's VXA holds its evaluation: $(grep -o '<Evaluation>.*</Evaluation>' "$D/run.vxa")" \
    grep -q '<Evaluation><cycles>4</cycles><fitness>x</fitness>.*<release_steps>300</release_steps></Evaluation>' "$D/run.vxa"
"$AMORPH" sim "$D/run" >"$D/run1.out" 2>&1
"$AMORPH" sim "$D/run.vxa" >"$D/run2.out" 2>&1
check "the run and its VXA simulate alike: $(grep -E '^(hash|steps|move_steps) ' "$D/run1.out" "$D/run2.out" | tr '\n' ' ')" \
    sh -c "[ -n \"\$(grep '^hash = ' '$D/run1.out')\" ] && [ \"\$(grep -E '^(hash|steps|fitness) = ' '$D/run1.out')\" = \"\$(grep -E '^(hash|steps|fitness) = ' '$D/run2.out')\" ] && grep -q '^move_steps = 2000$' '$D/run2.out'"
"$AMORPH" sim "$D/run.vxa" --cycles 1 >"$D/run3.out" 2>&1
check "sim --cycles 1 over the VXA's evaluation: $(grep '^move_steps' "$D/run3.out")" grep -q '^move_steps = 500$' "$D/run3.out"
# the lattice format holds no evaluation: exporting the run to it says which settings it leaves out,
# in one line, and a scene at the defaults exports without a word
"$AMORPH" export "$D/run" --lattice "$D/run.lattice" >"$D/lat.out" 2>"$D/lat.err"
check "export --lattice of the 4-cycle run: one warning naming cycles = 4, fitness = x and release_steps = 300: $(cat "$D/lat.err")" \
    sh -c "[ -s '$D/run.lattice' ] && [ \$(wc -l <'$D/lat.err') -eq 1 ] && grep -q 'warning: the lattice format holds no environment or evaluation: --lattice .* leaves out cycles = 4, fitness = x, .*release_steps = 300' '$D/lat.err'"
"$AMORPH" export --scene cube:2 --lattice "$D/c2.lattice" >"$D/c2.out" 2>"$D/c2.err"
check "export --lattice of a scene at the defaults said something: $(cat "$D/c2.err")" [ ! -s "$D/c2.err" ]
# the run's best.lattice carries none of the run's evaluation: sim says so in one note naming the
# run's settings and the command that replays the run; with those settings as flags, no note and
# the run's own result
"$AMORPH" sim "$D/run/best.lattice" >"$D/bl.out" 2>"$D/bl.err"
check "sim of the run's best.lattice: one note naming cycles = 4, fitness = x, release_steps = 300 and amorph sim DIR: $(cat "$D/bl.err")" \
    sh -c "[ \$(wc -l <'$D/bl.err') -eq 1 ] && grep -q '^amorph: note: $D/run/best.lattice is in the run folder $D/run, whose settings differ from these: the run had cycles = 4, fitness = x, .*release_steps = 300 (amorph sim $D/run evaluates' '$D/bl.err'"
"$AMORPH" sim "$D/run/best.lattice" --cycles 4 --fitness x --release_steps 300 >"$D/bl2.out" 2>"$D/bl2.err"
check "sim of best.lattice in the run's settings: a note, or another result than the run's: $(cat "$D/bl2.err")" \
    sh -c "[ ! -s '$D/bl2.err' ] && [ \"\$(grep -E '^(hash|fitness) = ' '$D/bl2.out')\" = \"\$(grep -E '^(hash|fitness) = ' '$D/run1.out')\" ]"
# --genome FILE: a genome in a run folder's settings, materials and expression. The run's own best
# genome that way is the run's result; named alone it gets the seed's settings and a note naming
# the command that evaluates it as the run did; a folder of config.txt alone takes a genome too
hv() { grep -E '^(hash|fitness|move_steps) = ' "$1"; }
"$AMORPH" sim "$D/run/best.genome" >"$D/bg.out" 2>"$D/bg.err"
check "sim of the run's best.genome: one note naming amorph sim DIR --genome FILE: $(cat "$D/bg.err")" \
    sh -c "[ \$(wc -l <'$D/bg.err') -eq 1 ] && grep -q '^amorph: note: $D/run/best.genome is in the run folder $D/run, whose settings differ .*(amorph sim $D/run --genome $D/run/best.genome evaluates this genome as the run did)$' '$D/bg.err'"
"$AMORPH" sim "$D/run" --genome "$D/run/best.genome" >"$D/g1.out" 2>"$D/g1.err"
g1=$(hv "$D/g1.out") r1=$(hv "$D/run1.out")
check "sim RUN --genome RUN/best.genome is the run's result, without a word: $g1 / $r1 / $(cat "$D/g1.err")" \
    sh -c "[ ! -s '$D/g1.err' ] && [ \"\$1\" = \"\$2\" ] && [ \$(echo \"\$1\" | wc -l) -eq 3 ] && grep -qx 'robot = $D/run/best.genome' '$D/g1.out'" _ "$g1" "$r1"
mkdir -p "$D/cfgonly" && cp "$D/run/config.txt" "$D/cfgonly/" && cp "$D/run/best.genome" "$D/kept.genome"
"$AMORPH" sim "$D/cfgonly" --genome "$D/kept.genome" >"$D/g2.out" 2>&1
check "a folder of config.txt alone with --genome: the run's result: $(hv "$D/g2.out" | tr '\n' ' ')" \
    sh -c '[ -n "$2" ] && [ "$1" = "$2" ]' _ "$(hv "$D/g2.out")" "$r1"
"$AMORPH" random --repr cppn --size 5 --seed 11 --out "$D/other.genome" >/dev/null 2>&1
"$AMORPH" sim "$D/run" --genome "$D/other.genome" >"$D/g3.out" 2>&1
"$AMORPH" sim "$D/other.genome" >"$D/g4.out" 2>/dev/null
check "another genome in the run's settings: the run's 4 cycles, another robot than the run's and than the genome alone: $(hv "$D/g3.out" | tr '\n' ' ')" \
    sh -c "grep -qx 'move_steps = 2000' '$D/g3.out' && grep -qx 'move_steps = 5000' '$D/g4.out' && grep -q '^hash = ' '$D/g3.out' && [ \"\$(grep '^hash' '$D/g3.out')\" != \"\$(grep '^hash' '$D/run1.out')\" ]"
"$AMORPH" render "$D/run" --genome "$D/other.genome" --cycles 1 --out "$D/other.png" >/dev/null 2>&1
"$AMORPH" render "$D/run" --cycles 1 --out "$D/best.png" >/dev/null 2>&1
check "render RUN --genome FILE draws that robot (another picture than the run's best)" sh -c "[ -s '$D/other.png' ] && [ -s '$D/best.png' ] && ! cmp -s '$D/other.png' '$D/best.png'"
expect_fail 2 "^amorph: --genome $D/kept.genome: a genome is evaluated in a run folder's settings \(its config.txt\); cube:2 is a scene$" \
    "$AMORPH" sim --scene cube:2 --genome "$D/kept.genome"
expect_fail 2 "^amorph: --genome $D/kept.genome: a genome is evaluated in a run folder's settings \(its config.txt\); $D/run/best.lattice is not a run folder$" \
    "$AMORPH" sim "$D/run/best.lattice" --genome "$D/kept.genome"
expect_fail 2 "^amorph: $D/run/best.lattice:1: not a genome: " "$AMORPH" sim "$D/run" --genome "$D/run/best.lattice"
expect_fail 2 "^amorph: $D/none.genome: cannot open" "$AMORPH" sim "$D/run" --genome "$D/none.genome"
expect_fail 2 "^amorph: sim: --genome needs a genome file" "$AMORPH" sim "$D/run" --genome
expect_fail 2 "^amorph: view: --genome given twice \('a' and 'b'\)$" "$AMORPH" view "$D/run" --genome a --genome b --out "$D/x.html"
expect_fail 2 "^amorph: export: --checkpoint takes a run folder and no other output or setting$" "$AMORPH" export "$D/run" --genome "$D/kept.genome" --checkpoint -
expect_fail 2 "neither a run folder \(config.txt, best.genome: no best.genome yet\)" "$AMORPH" sim "$D/cfgonly"
# to the standard output with '-'
"$AMORPH" export --scene cube:2 --vxa - >"$D/stdout.vxa" 2>/dev/null
if head -n 1 "$D/stdout.vxa" | grep -q '^<?xml version="1.0"'; then ok; else ko "export --vxa - wrote no XML"; fi

# a file written the way VoxCAD writes it: it runs, with one warning per unsupported tag
F=tests/data/voxcad_quadruped.vxa
"$AMORPH" sim "$F" --cycles 2 --relax-max 400 >"$D/q.out" 2>"$D/q.err"; rc=$?
if [ $rc -eq 0 ] && grep -q '^voxels = 44$' "$D/q.out" && grep -q '^diverged = 0$' "$D/q.out"; then ok
else ko "sim $F -> exit $rc: $(head -c 300 "$D/q.out") $(head -c 300 "$D/q.err")"; fi
for w in "$F:18: warning: unsupported tag <Features> ignored" "$F:86: warning: unsupported tag <IsConductive> ignored"; do
    if grep -qF "$w" "$D/q.err"; then ok; else ko "missing warning '$w' in: $(cat "$D/q.err")"; fi
done
# (the file's warnings; its <DtFrac> 0.9 is amorph's default step, taken without one; its
# <StopCondition> is read: --cycles 2 sets the length instead; amorph sim adds its own line when 400
# relaxation steps do not settle the body)
if [ "$(grep -c "^$F:" "$D/q.err")" -eq 2 ]; then ok; else ko "expected 2 warning lines: $(cat "$D/q.err")"; fi
# its materials and environment arrive: names made safe, linear CTE, amplitude, damping
expect_ok "$AMORPH" export "$F" --lattice "$D/q.lattice"
if grep -q '^material Active__ E=1000000 density=1000 poisson=0.35 cte=0.01 phase=0 mu_s=1 mu_k=0.5 zeta_int=1 zeta_glob=0.01 zeta_col=0.8 color=#ff0000 fixed=0$' "$D/q.lattice"
then ok; else ko "fixture material: $(grep '^material' "$D/q.lattice")"; fi
expect_ok "$AMORPH" export "$F" --vxa "$D/q.vxa"
if grep -q '<CTEMode>linear</CTEMode>' "$D/q.vxa" && grep -q '<TempAmplitude>39</TempAmplitude>' "$D/q.vxa" && \
   grep -q '<SelfColEnabled>0</SelfColEnabled>' "$D/q.vxa" && grep -q '<GravAcc>-9.81</GravAcc>' "$D/q.vxa"
then ok; else ko "the fixture's environment did not come through export"; fi
# the same robot saved with ZLIB layers (VoxCAD's default) simulates to the same state
Z=tests/data/voxcad_quadruped_zlib.vxa
"$AMORPH" sim "$F" --cycles 1 --relax-max 100 >"$D/qa.out" 2>/dev/null
"$AMORPH" sim "$Z" --cycles 1 --relax-max 100 >"$D/qz.out" 2>/dev/null
if [ -n "$(hash_of "$D/qa.out")" ] && [ "$(hash_of "$D/qa.out")" = "$(hash_of "$D/qz.out")" ]; then ok
else ko "ZLIB and ASCII layers simulate differently: $(hash_of "$D/qa.out") vs $(hash_of "$D/qz.out")"; fi
# and exports as the exporter writes every file: ASCII_READABLE layers, the same cells
expect_ok "$AMORPH" export "$Z" --lattice "$D/qz.lattice"
expect_ok "$AMORPH" export "$F" --lattice "$D/qa.lattice"
if cmp -s "$D/qa.lattice" "$D/qz.lattice"; then ok; else ko "ZLIB layers read other cells"; fi
expect_ok "$AMORPH" export "$Z" --vxa "$D/qz.vxa"
if grep -q 'Compression="ASCII_READABLE"' "$D/qz.vxa" && grep -q '<Layer><!\[CDATA\[200003000000000000200003\]\]></Layer>' "$D/qz.vxa"
then ok; else ko "export of a ZLIB file: $(grep -A3 '<Structure' "$D/qz.vxa")"; fi
sed 's|eNpjYAQCBgYMEgAA4AAR|eNpjYAQCBgYMEgAA4AAS|' "$Z" >"$D/adler.vxa"
expect_fail 2 "^amorph: $D/adler.vxa:147: layer 2: bad Adler-32" "$AMORPH" sim "$D/adler.vxa"

# command-line flags win over the file's environment
"$AMORPH" sim "$F" --cycles 1 --relax-max 50 --amplitude 0 --json >"$D/flag.out" 2>/dev/null
"$AMORPH" sim "$F" --cycles 1 --relax-max 50 --json >"$D/noflag.out" 2>/dev/null
if grep -q '"fitness"' "$D/flag.out" && ! cmp -s "$D/flag.out" "$D/noflag.out"; then ok; else ko "--amplitude did not override the file"; fi

# an unsupported tag: a warning with its line, never silence, and the run goes on
sed 's|<Simulator>|<Simulator>\n    <Wobble>1</Wobble>|' "$F" >"$D/wobble.vxa"
"$AMORPH" sim "$D/wobble.vxa" --cycles 1 --relax-max 20 >"$D/out" 2>"$D/err"; rc=$?
if [ $rc -eq 0 ] && grep -qxF "$D/wobble.vxa:4: warning: unsupported tag <Wobble> ignored" "$D/err"; then ok
else ko "unsupported tag: exit $rc, stderr $(cat "$D/err")"; fi

# malformed XML and VXA: exit 2, one line FILE:LINE: problem
printf '<VXA>\n<VXC>\n</VXA>\n' >"$D/mismatch.vxa"
expect_fail 2 "^amorph: $D/mismatch.vxa:3: </VXA> does not close <VXC> \(opened on line 2\)$" "$AMORPH" sim "$D/mismatch.vxa"
printf '<?xml version="1.0"?>\n<VXA>\n<VXC>\n' >"$D/eof.vxa"
expect_fail 2 "$D/eof.vxa:3: the file ends inside <VXC> \(opened on line 3\)" "$AMORPH" sim "$D/eof.vxa"
printf '<VXA>\n<VXC Version="0.94">&bogus;</VXC>\n</VXA>\n' >"$D/entity.vxa"
expect_fail 2 "$D/entity.vxa:2: unknown entity" "$AMORPH" sim "$D/entity.vxa"
printf '<Robot/>\n' >"$D/root.vxa"
expect_fail 2 "$D/root.vxa:1: not a VXA file: the root element is <Robot>, expected <VXA>" "$AMORPH" sim "$D/root.vxa"
# ASCII layers under a ZLIB label: their text is not a zlib stream
sed 's|ASCII_READABLE|ZLIB|' "$F" >"$D/zlib.vxa"
expect_fail 2 "$D/zlib.vxa:145: layer 0: bad zlib header" "$AMORPH" sim "$D/zlib.vxa"
sed 's|<!\[CDATA\[011110011110011110011110\]\]>|<![CDATA[0111100111100111100111]]>|' "$F" >"$D/short.vxa"
expect_fail 2 "$D/short.vxa:147: layer 2 has 22 cells, expected 24" "$AMORPH" sim "$D/short.vxa"
sed 's|<Elastic_Mod>1e+006</Elastic_Mod>|<Elastic_Mod>stiff</Elastic_Mod>|' "$F" >"$D/junk.vxa"
expect_fail 2 "$D/junk.vxa:74: <Elastic_Mod>: 'stiff' is not a finite number" "$AMORPH" sim "$D/junk.vxa"
sed 's|<Poissons_Ratio>0.35</Poissons_Ratio>|<Poissons_Ratio>0.75</Poissons_Ratio>|' "$F" >"$D/range.vxa"
expect_fail 2 "$D/range.vxa:81: <Poissons_Ratio> 0.75 must be in \[0, 0.5\]" "$AMORPH" sim "$D/range.vxa"
sed 's|<X_Voxels>6</X_Voxels>|<X_Voxels>999</X_Voxels>|' "$F" >"$D/wide.vxa"
expect_fail 2 "$D/wide.vxa:141: <X_Voxels> 999 exceeds the (desktop|board) profile's" "$AMORPH" sim "$D/wide.vxa"

# a deeply nested file is refused within the fixed memory
awk 'BEGIN { printf "<VXA>"; for (i = 0; i < 10000; i++) printf "<a>"; print "" }' >"$D/deep.vxa"
expect_fail 2 "$D/deep.vxa:1: elements nested deeper than [0-9]+ levels" "$AMORPH" sim "$D/deep.vxa"
# so is one with more elements than the reader holds (the element past the limit is named)
awk 'BEGIN { print "<VXA>"; for (i = 0; i < 20000; i++) print "<a/>"; print "</VXA>" }' >"$D/many.vxa"
expect_fail 2 "$D/many.vxa:[0-9]+: more than [0-9]+ elements \(the XML reader's capacity" "$AMORPH" sim "$D/many.vxa"
# and one larger than any buffer of the build
awk 'BEGIN { print "<VXA>"; s = sprintf("%1000s", ""); for (i = 0; i < 5000; i++) print "<!--" s "-->"; print "</VXA>" }' >"$D/huge.vxa"
expect_fail 2 "huge.vxa.*(larger than|more than)" "$AMORPH" sim "$D/huge.vxa"

# a failed export leaves no file, and does not touch an existing one
expect_fail 2 "$D/mismatch.vxa:3:" "$AMORPH" export "$D/mismatch.vxa" --vxa "$D/new.vxa"
if [ ! -e "$D/new.vxa" ]; then ok; else ko "a failed export left $D/new.vxa"; fi
cp "$D/sphere.vxa" "$D/keep.vxa"
expect_fail 2 "$D/junk.vxa:74:" "$AMORPH" export "$D/junk.vxa" --vxa "$D/keep.vxa"
if cmp -s "$D/sphere.vxa" "$D/keep.vxa"; then ok; else ko "a failed export changed an existing file"; fi
if [ -z "$(ls -A "$D" | grep "\.tmp\.")" ]; then ok; else ko "temporary files left: $(ls -A "$D")"; fi

# per-voxel phases (evosoro) and boundary conditions (VoxCAD) survive export --vxa: the same state
for R in evosoro_phase voxcad_cantilever; do
    G=tests/data/$R.vxa
    "$AMORPH" sim "$G" --cycles 1 --relax-max 200 >"$D/$R.a" 2>/dev/null
    expect_ok "$AMORPH" export "$G" --vxa "$D/$R.vxa"
    "$AMORPH" sim "$D/$R.vxa" --cycles 1 --relax-max 200 >"$D/$R.b" 2>"$D/$R.err"
    if [ -n "$(hash_of "$D/$R.a")" ] && [ "$(hash_of "$D/$R.a")" = "$(hash_of "$D/$R.b")" ]; then ok
    else ko "$R: the exported file simulates differently: $(hash_of "$D/$R.a") vs $(hash_of "$D/$R.b")"; fi
    if ! grep -q "warning: unsupported" "$D/$R.err"; then ok; else ko "$R: our export gave warnings: $(cat "$D/$R.err")"; fi
done
if grep -q '<PhaseOffset>' "$D/evosoro_phase.vxa" && grep -q '<NumBCs>2</NumBCs>' "$D/voxcad_cantilever.vxa"; then ok
else ko "exported layers missing"; fi
# without its phases the robot moves otherwise; the lattice format says it drops them
"$AMORPH" export tests/data/evosoro_phase.vxa --lattice "$D/ph.lattice" 2>"$D/ph.err"
if grep -q "^tests/data/evosoro_phase.vxa: warning: the lattice format holds no per-voxel phases" "$D/ph.err"; then ok
else ko "no warning for a lattice without phases: $(cat "$D/ph.err")"; fi
"$AMORPH" export tests/data/evosoro_stiffness.vxa --lattice "$D/st.lattice" 2>"$D/st.err"
if grep -q "^tests/data/evosoro_stiffness.vxa: warning: the lattice format holds no .*per-voxel stiffness" "$D/st.err"; then ok
else ko "no warning for a lattice without stiffness: $(cat "$D/st.err")"; fi
"$AMORPH" sim "$D/ph.lattice" --cycles 1 --relax-max 200 >"$D/ph.out" 2>/dev/null
if [ "$(hash_of "$D/ph.out")" != "$(hash_of "$D/evosoro_phase.a")" ]; then ok; else ko "phases made no difference"; fi
# the cantilever moves down under its load (0.5 mm at rest, tests/test_io_vxa.c checks the figure), and
# sits without it: a relaxation cut short (200 steps, before the tip has come down) leaves the rest
# of the deflection to the movement segment, whose displacement sim reports
"$AMORPH" sim tests/data/voxcad_cantilever.vxa --cycles 1 --relax-max 200 --json >"$D/cant.json" 2>/dev/null
sed 's|<NumBCs>2</NumBCs>|<NumBCs>0</NumBCs>|; /<FRegion>/,/<\/FRegion>/d' tests/data/voxcad_cantilever.vxa >"$D/free.vxa"
"$AMORPH" sim "$D/free.vxa" --cycles 1 --relax-max 200 --json >"$D/free.json" 2>/dev/null
cz=$(sed -n 's/.*"dz": \([-0-9.eE+]*\).*/\1/p' "$D/cant.json")
if awk -v z="$cz" 'BEGIN { exit !(z < -1e-5) }' && grep -q '"dz": 0[,}]' "$D/free.json"; then ok
else ko "cantilever: $(head -c 200 "$D/cant.json") / $(head -c 200 "$D/free.json")"; fi
# a bad phase: one line FILE:LINE: problem
sed 's|<Layer><!\[CDATA\[0, 0.25|<Layer><![CDATA[0, zero|' tests/data/evosoro_phase.vxa >"$D/badphase.vxa"
expect_fail 2 "^amorph: $D/badphase.vxa:80: <PhaseOffset> layer 0: value 1 'zero' is not a finite number$" "$AMORPH" sim "$D/badphase.vxa"

# voxcraft's VXD over a base VXA: both files, or their folder; the same as one merged VXA file
V=tests/data/voxcraft
"$AMORPH" sim "$V/base.vxa" "$V/robot.vxd" --cycles 1 --relax-max 200 >"$D/vx1.out" 2>"$D/vx1.err"
"$AMORPH" sim "$V" --cycles 1 --relax-max 200 >"$D/vx2.out" 2>/dev/null
"$AMORPH" sim "$V/robot.vxd" "$V/base.vxa" --cycles 1 --relax-max 200 >"$D/vx3.out" 2>/dev/null
expect_ok "$AMORPH" export "$V/base.vxa" "$V/robot.vxd" --vxa "$D/merged.vxa"
"$AMORPH" sim "$D/merged.vxa" --cycles 1 --relax-max 200 >"$D/vx4.out" 2>/dev/null
h=$(hash_of "$D/vx1.out")
if [ -n "$h" ] && [ "$h" = "$(hash_of "$D/vx2.out")" ] && [ "$h" = "$(hash_of "$D/vx3.out")" ] && [ "$h" = "$(hash_of "$D/vx4.out")" ] && \
   grep -q '^voxels = 18$' "$D/vx1.out"; then ok
else ko "VXD: $h $(hash_of "$D/vx2.out") $(hash_of "$D/vx3.out") $(hash_of "$D/vx4.out")"; fi
if grep -qxF "$V/robot.vxd:31: warning: unsupported tag <RawPrint> ignored (amorph reads the elements of a VXD that replace=\"VXA...\" a part of the base)" "$D/vx1.err" && \
   [ "$(grep -c "^$V/robot.vxd:" "$D/vx1.err")" -eq 3 ] && [ "$(grep -c "^$V/base.vxa:" "$D/vx1.err")" -eq 2 ]; then ok
else ko "VXD warnings: $(cat "$D/vx1.err")"; fi
expect_fail 2 "^amorph: $V/robot.vxd:1: a VXD file \(voxcraft-sim's robot: elements that replace parts of a base VXA file\) is not read alone: give its base VXA file first, then the VXD \(amorph sim BASE.vxa ROBOT.vxd, or a folder holding base.vxa and one .vxd\)$" "$AMORPH" sim "$V/robot.vxd"
# the robot reported is the VXD (voxcraft-sim's robot), not the base it goes over, as a pair or a folder
check "the pair's robot: $(grep '^robot' "$D/vx1.out")" grep -qxF "robot = $V/robot.vxd" "$D/vx1.out"
check "the folder's robot: $(grep '^robot' "$D/vx2.out")" grep -qxF "robot = $V/robot.vxd" "$D/vx2.out"
"$AMORPH" sim "$V" --cycles 1 --relax-max 200 --json >"$D/vx2.json" 2>/dev/null
check "the folder's robot in JSON: $(head -c 80 "$D/vx2.json")" grep -qF "\"robot\": \"$V/robot.vxd\"" "$D/vx2.json"
# volvox's <ForceField> (a field amorph does not simulate): a warning, and named in the summary line
sed 's|<Environment>|<Environment>\n    <ForceField><x_forcefield><mtConst>0.001</mtConst></x_forcefield></ForceField>|' "$V/base.vxa" >"$D/ff.vxa"
"$AMORPH" sim "$D/ff.vxa" "$V/robot.vxd" --cycles 1 --relax-max 50 >/dev/null 2>"$D/ff.err"
check "ForceField: $(cat "$D/ff.err")" sh -c "grep -q '^$D/ff.vxa:[0-9]*: warning: unsupported tag <ForceField> ignored$' '$D/ff.err' && \
    grep -q '^$V/robot.vxd: warning: results will differ from the reference simulator: amorph does not simulate .*ForceField' '$D/ff.err'"
mkdir -p "$D/onlybase" && cp "$V/base.vxa" "$D/onlybase/"
expect_fail 2 "$D/onlybase: a voxcraft folder holds a base VXA and a robot's VXD; no .vxd in it" "$AMORPH" sim "$D/onlybase"
# the folder's VXD under any name (voxcraft-sim names them freely), and its VXA under any name
# when it is the only one; two VXD files are refused with both names
mkdir -p "$D/anyname" && cp "$V/base.vxa" "$D/anyname/body.vxa" && cp "$V/robot.vxd" "$D/anyname/walker7.vxd"
"$AMORPH" sim "$D/anyname" --cycles 1 --relax-max 200 >"$D/vx5.out" 2>/dev/null
check "a voxcraft folder with other names: hash '$(hash_of "$D/vx5.out")' (want $h)" [ "$(hash_of "$D/vx5.out")" = "$h" ]
cp "$V/robot.vxd" "$D/anyname/a2.vxd"
expect_fail 2 "$D/anyname: 2 VXD files \\(a2.vxd, walker7.vxd\\): name one" "$AMORPH" sim "$D/anyname"
cp "$V/base.vxa" "$D/anyname/other.vxa"
expect_fail 2 "$D/anyname: a voxcraft folder holds base.vxa and VXD files; this one has 2 VXA files and no base.vxa" "$AMORPH" sim "$D/anyname"
printf '<VXD>\n<Structure replace="VXA.VXC.Structure"><X_Voxels>x</X_Voxels></Structure>\n</VXD>\n' >"$D/bad.vxd"
expect_fail 2 "^amorph: $D/bad.vxd:2: <X_Voxels>: 'x' is not a whole number$" "$AMORPH" sim "$V/base.vxa" "$D/bad.vxd"
expect_fail 2 "one robot at a time" "$AMORPH" sim "$V/base.vxa" "$V/robot.vxd" "$F"

# usage errors
expect_fail 2 "export: say what to write" "$AMORPH" export --scene cube:2
expect_fail 2 "export: name a robot" "$AMORPH" export --vxa "$D/x.vxa"
expect_fail 2 "export: unknown option '--png'" "$AMORPH" export --scene cube:2 --png x.png
# a VXD is read up to 4 MiB, as a VXA file (issue 31: 1 MiB): one padded past 2 MiB with a comment
# simulates as the unpadded one
{ echo '<VXD><!--'; head -c 2200000 /dev/zero | tr '\0' 'x'; echo '-->'; tail -n +2 "$V/robot.vxd"; } >"$D/big.vxd"
"$AMORPH" sim "$V/base.vxa" "$D/big.vxd" --cycles 1 --relax-max 200 >"$D/vx5.out" 2>"$D/vx5.err"
if [ "$(wc -c <"$D/big.vxd")" -gt 2200000 ] && [ -n "$h" ] && [ "$(hash_of "$D/vx5.out")" = "$h" ]; then ok
else ko "a 2 MiB VXD: $(head -c 300 "$D/vx5.err")"; fi

# one range per setting wherever it comes from (issue 31): a VXA period of 10^9 steps, a period in
# seconds past 10^4, a subnormal cell edge (in a VXA or a lattice file) and a 64-character phase
# are refused with the file and line, never simulated (timeout: an old build ran such a period for days)
expect_ok "$AMORPH" export --scene cube:2 --vxa "$D/c.vxa"
sed 's#<PeriodSteps>[^<]*</PeriodSteps>#<PeriodSteps>1000000000</PeriodSteps>#' "$D/c.vxa" >"$D/p9.vxa"
expect_fail 2 "^amorph: $D/p9.vxa:[0-9]+: <PeriodSteps> 1000000000 is outside 2..10000000$" timeout -k 5 60 "$AMORPH" sim "$D/p9.vxa" --cycles 1
sed 's#<TempPeriod>[^<]*</TempPeriod>#<TempPeriod>1e30</TempPeriod>#' tests/data/evosoro_phase.vxa >"$D/t30.vxa"
expect_fail 2 "^amorph: $D/t30.vxa:43: <TempPeriod> 1e\+30 is too large \(at most 10000 s\)$" timeout -k 5 60 "$AMORPH" sim "$D/t30.vxa" --cycles 1
sed 's#<Lattice_Dim>[^<]*</Lattice_Dim>#<Lattice_Dim>1e-45</Lattice_Dim>#' "$D/c.vxa" >"$D/sub.vxa"
expect_fail 2 "^amorph: $D/sub.vxa:[0-9]+: <Lattice_Dim> .* is too small \(at least 1e-05 m\)$" timeout -k 5 60 "$AMORPH" sim "$D/sub.vxa" --cycles 1
expect_ok "$AMORPH" export --scene cube:2 --lattice "$D/c.lattice"
sed 's/^voxel_size .*/voxel_size 1e-45/' "$D/c.lattice" >"$D/sub.lattice"
expect_fail 2 "^amorph: $D/sub.lattice:[0-9]+: voxel_size 1e-45 m is outside 1e-05..10$" timeout -k 5 60 "$AMORPH" sim "$D/sub.lattice" --cycles 1
sed 's#CDATA\[0, 0.25, #CDATA[0, 0.25000000000000000000000000000000000000000000000000000000000001, #' tests/data/evosoro_phase.vxa >"$D/long.vxa"
if grep -q '0.25000000000000000000000000000000000000000000000000000000000001' "$D/long.vxa"; then ok; else ko "the long phase was not planted"; fi
expect_fail 2 "^amorph: $D/long.vxa:80: <PhaseOffset> layer 0: value 1 is longer than 63 characters$" "$AMORPH" sim "$D/long.vxa" --cycles 1

# issue 32: peers' robots as their authors meant them
# regions take every voxel whose cell touches the box (VoxCAD's and Voxelyze's rule): evosoro's sticky
# floor, a box 0.01 of the workspace high, clamps the whole bottom layer though no centre lies in it
R=tests/data/region_touch.vxa
"$AMORPH" sim "$R" --cycles 1 --relax-max 300 >"$D/rt.out" 2>"$D/rt.err"
sed '/<FRegion>/,/<\/FRegion>/d; s|<NumBCs>1</NumBCs>|<NumBCs>0</NumBCs>|' "$R" >"$D/rt_free.vxa"
"$AMORPH" sim "$D/rt_free.vxa" --cycles 1 --relax-max 300 >"$D/rtf.out" 2>/dev/null
check "region_touch: a warning: $(cat "$D/rt.err")" [ -z "$(grep "$R:" "$D/rt.err")" ]
if [ -n "$(hash_of "$D/rt.out")" ] && [ "$(hash_of "$D/rt.out")" != "$(hash_of "$D/rtf.out")" ]; then ok
else ko "region_touch: the clamp changed nothing ($(hash_of "$D/rt.out"))"; fi
expect_ok "$AMORPH" export "$R" --vxa "$D/rt.vxa"
check "region_touch: the bottom layer's 6 voxels are not clamped: $(grep -c '<DofFixed>63' "$D/rt.vxa")" \
    [ "$(grep -c '<DofFixed>63</DofFixed>' "$D/rt.vxa")" -eq 6 ]
"$AMORPH" sim "$D/rt.vxa" --cycles 1 --relax-max 300 >"$D/rt2.out" 2>/dev/null
check "region_touch: its export simulates otherwise" [ "$(hash_of "$D/rt2.out")" = "$(hash_of "$D/rt.out")" ]
# Poisson's ratio 0.5 (volvox's files, for voxcraft-sim, which clamps it): the largest ratio below, one warning
sed 's|<Poissons_Ratio>0.35</Poissons_Ratio>|<Poissons_Ratio>0.5</Poissons_Ratio>|' "$F" >"$D/half.vxa"
"$AMORPH" export "$D/half.vxa" --lattice "$D/half.lattice" 2>"$D/half.err"; rc=$?
if [ $rc -eq 0 ] && \
   [ "$(grep -c "^$D/half.vxa:81: warning: <Poissons_Ratio> 0.5 (incompressible) is beyond amorph's model: the largest ratio below 0.5 used for material 1$" "$D/half.err")" -eq 1 ]
then ok; else ko "Poisson 0.5: exit $rc, $(cat "$D/half.err")"; fi
check "Poisson 0.5: $(grep '^material Active' "$D/half.lattice")" grep -q '^material Active__ .* poisson=0\.4999999' "$D/half.lattice"
# voxcraft-sim's fixed material: its voxels are clamped
sed '0,/<uDynamic>0.5<\/uDynamic>/s||<uDynamic>0.5</uDynamic><Fixed>1</Fixed>|' "$F" >"$D/fixmat.vxa"
expect_ok "$AMORPH" export "$D/fixmat.vxa" --lattice "$D/fixmat.lattice"
if [ "$(grep -c '^material Passive_Soft .* fixed=1$' "$D/fixmat.lattice")" -eq 1 ] && [ "$(grep -c 'fixed=1$' "$D/fixmat.lattice")" -eq 1 ]
then ok; else ko "a fixed material: $(grep '^material' "$D/fixmat.lattice")"; fi
# evosoro's per-voxel stiffness, beside its phases: read, simulated, written back
S2=tests/data/evosoro_stiffness.vxa
"$AMORPH" sim "$S2" --cycles 1 --relax-max 200 >"$D/st.out" 2>"$D/st.err"
sed '/^<Stiffness>$/,/^<\/Stiffness>$/d' "$S2" >"$D/st_none.vxa"
"$AMORPH" sim "$D/st_none.vxa" --cycles 1 --relax-max 200 >"$D/stn.out" 2>/dev/null
if [ -z "$(grep -e '<Stiffness>' -e '<Layer>' -e 'ElasticMod' "$D/st.err")" ] && [ -z "$(grep '^<Stiffness>' "$D/st_none.vxa")" ] && \
   [ -n "$(hash_of "$D/stn.out")" ]; then ok; else ko "stiffness: warned about: $(cat "$D/st.err")"; fi
if [ -n "$(hash_of "$D/st.out")" ] && [ "$(hash_of "$D/st.out")" != "$(hash_of "$D/stn.out")" ]; then ok
else ko "stiffness: changed nothing ($(hash_of "$D/st.out"))"; fi
# the step follows the stiffest voxel (10 times the material's modulus: a step sqrt(10) shorter)
dts=$(sed -n 's/^dt = //p' "$D/st.out"); dtn=$(sed -n 's/^dt = //p' "$D/stn.out")
check "stiffness: dt $dts vs $dtn without the layer" awk -v a="$dts" -v b="$dtn" 'BEGIN { r = b / a; exit !(r > 3.15 && r < 3.17) }'
expect_ok "$AMORPH" export "$S2" --vxa "$D/st.vxa"
"$AMORPH" sim "$D/st.vxa" --cycles 1 --relax-max 200 >"$D/st2.out" 2>/dev/null
if grep -q '<Stiffness>' "$D/st.vxa" && [ "$(hash_of "$D/st2.out")" = "$(hash_of "$D/st.out")" ]; then ok
else ko "stiffness: the export simulates otherwise"; fi
sed 's|<Layer><!\[CDATA\[10000000, 1000000,|<Layer><![CDATA[10000000, -5,|' "$S2" >"$D/badstiff.vxa"
expect_fail 2 "^amorph: $D/badstiff.vxa:87: <Stiffness> layer 0: value 1 \(x = 1, y = 0, a voxel\) is -5 Pa: it must be greater than 0 and at most 1e\+30$" "$AMORPH" sim "$D/badstiff.vxa"
# ignored items that change the motion: one summary line naming them (evosoro's water robots)
sed 's|<Environment>|<Environment>\n<FluidEnvironment>1</FluidEnvironment>|' tests/data/evosoro_phase.vxa >"$D/water.vxa"
"$AMORPH" sim "$D/water.vxa" --cycles 1 --relax-max 20 >/dev/null 2>"$D/water.err"
check "water: $(cat "$D/water.err")" grep -qxF "$D/water.vxa: warning: results will differ from the reference simulator: amorph does not simulate FluidEnvironment (warnings above)" "$D/water.err"
check "a summary for a file whose warnings do not matter: $(cat "$D/q.err")" [ -z "$(grep 'results will differ' "$D/q.err")" ]

# VoxCAD's run length (<StopCondition>) and evosoro's transient (<InitCmTime>) as the evaluation's
# cycles and least relaxation: 0.4 s less 0.1 s is 12 periods of 0.025 s, named in one note line
E=tests/data/evosoro_stop.vxa
"$AMORPH" sim "$E" >"$D/stop.out" 2>"$D/stop.err"
ps=$(sed -n 's/^period_steps = //p' "$D/stop.out")
check "StopCondition 0.4 s less InitCmTime 0.1 s: 12 cycles of $ps steps: $(grep -E '^(move_steps|relax_steps|dt) ' "$D/stop.out" | tr '\n' ' ') $(cat "$D/stop.err")" \
    sh -c "[ -n '$ps' ] && grep -q '^move_steps = $((12 * ${ps:-0}))$' '$D/stop.out'"
check "the note on the run length: $(cat "$D/stop.err")" \
    grep -q "^$E: note: the file's run length as amorph's evaluation: cycles = 12 (<StopCondition> 0.4 s less <InitCmTime> 0.1 s: 11.99[0-9]* periods of 0.025 s), relax_min_steps = [0-9]* and relax_max_steps = [0-9]* (<InitCmTime> 0.1 s: the relaxation lasts at least that long before the centre of mass is recorded)$" "$D/stop.err"
check "the relaxation lasts InitCmTime 0.1 s or more: $(grep -E '^(relax_steps|dt) ' "$D/stop.out" | tr '\n' ' ')" \
    awk -v r="$(sed -n 's/^relax_steps = //p' "$D/stop.out")" -v dt="$(sed -n 's/^dt = //p' "$D/stop.out")" 'BEGIN { exit !(r * dt >= 0.1) }'
check "the file's warnings: $(cat "$D/stop.err")" [ "$(grep -c "^$E:" "$D/stop.err")" -eq 1 ]
"$AMORPH" sim "$E" --cycles 3 >"$D/stop3.out" 2>"$D/stop3.err"
check "--cycles 3 over the file's StopCondition: $(grep '^move_steps' "$D/stop3.out") $(cat "$D/stop3.err")" \
    sh -c "grep -q '^move_steps = $((3 * ${ps:-0}))$' '$D/stop3.out' && ! grep -q 'cycles = 12' '$D/stop3.err'"
# a stop amorph has no counterpart for: a warning, the summary line with the setting, amorph's cycles
sed 's|<StopConditionType>2<|<StopConditionType>5<|' "$E" >"$D/stop5.vxa"
"$AMORPH" sim "$D/stop5.vxa" --relax-max 300 >"$D/stop5.out" 2>"$D/stop5.err"
check "StopConditionType 5: $(cat "$D/stop5.err")" sh -c "grep -q '^$D/stop5.vxa:20: warning: <StopConditionType> 5 (until the kinetic energy is below a threshold) is not simulated' '$D/stop5.err' && \
    grep -qF '$D/stop5.vxa: warning: results will differ from the reference simulator: amorph does not simulate StopConditionType 5 (cycles = 10 run: --cycles N) (warnings above)' '$D/stop5.err' && \
    grep -q '^move_steps = $((10 * ${ps:-0}))$' '$D/stop5.out'"
# a run length past the configuration's range: refused before any step, with the file's line
expect_fail 2 "^amorph: tests/data/hostile/stop_time_1e9.vxa:19: <StopCondition> 1e\+09 seconds less <InitCmTime> is [0-9.e+]* actuation periods of 0.025 s: cycles = '[0-9]*': expected an integer in \[0, 100000\]$" "$AMORPH" sim tests/data/hostile/stop_time_1e9.vxa
expect_fail 2 "^amorph: tests/data/hostile/init_cm_time_1e5.vxa:19: <InitCmTime> 100000 s is .*: relax_min_steps = '[0-9]*': expected an integer in \[0, 100000000\]$" "$AMORPH" sim tests/data/hostile/init_cm_time_1e5.vxa
# exported, the run length travels as <Amorph>'s <Evaluation>: the same run
expect_ok "$AMORPH" export "$E" --vxa "$D/stop_exp.vxa"
"$AMORPH" sim "$D/stop_exp.vxa" >"$D/stop_exp.out" 2>/dev/null
check "the export of the StopCondition file runs the same: $(hash_of "$D/stop.out") vs $(hash_of "$D/stop_exp.out")" \
    sh -c "[ -n '$(hash_of "$D/stop.out")' ] && [ '$(hash_of "$D/stop.out")' = '$(hash_of "$D/stop_exp.out")' ]"

# a body starts where the file puts it (VoxCAD's placement): a beam clamped two layers above the
# floor hangs there and droops, where amorph's own lattices are lowered onto the floor; without the
# empty layers below it, the file runs otherwise
H=tests/data/voxcad_hanging.vxa
"$AMORPH" sim "$H" --cycles 1 --trajectory "$D/hang.csv" >"$D/hang.out" 2>"$D/hang.err"
sed 's|<Z_Voxels>3</Z_Voxels>|<Z_Voxels>1</Z_Voxels>|; 0,/<Layer><!\[CDATA\[0000\]\]><\/Layer>/{//d}; 0,/<Layer><!\[CDATA\[0000\]\]><\/Layer>/{//d}' "$H" >"$D/hang_low.vxa"
"$AMORPH" sim "$D/hang_low.vxa" --cycles 1 >"$D/hang_low.out" 2>/dev/null
z0=$(sed -n 2p "$D/hang.csv" | cut -d, -f6); z1=$(tail -n 1 "$D/hang.csv" | cut -d, -f6)
check "the clamped beam starts 2.5 layers up (com z $z0) and droops (to $z1), warnings: $(cat "$D/hang.err")" \
    awk -v a="$z0" -v b="$z1" 'BEGIN { exit !(a > 0.0249 && a < 0.0251 && b < a - 1e-4 && b > 0.005) }'
check "the raised beam and the beam on the floor simulate alike: $(hash_of "$D/hang.out")" \
    sh -c "[ -n '$(hash_of "$D/hang_low.out")' ] && [ '$(hash_of "$D/hang.out")' != '$(hash_of "$D/hang_low.out")' ]"
# unclamped, the same beam falls onto the floor from there
sed '/<FRegion>/,/<\/FRegion>/d; s|<NumBCs>1</NumBCs>|<NumBCs>0</NumBCs>|' "$H" >"$D/fall.vxa"
"$AMORPH" sim "$D/fall.vxa" --cycles 1 --trajectory "$D/fall.csv" >"$D/fall.out" 2>"$D/fall.err"
z0=$(sed -n 2p "$D/fall.csv" | cut -d, -f6); z1=$(tail -n 1 "$D/fall.csv" | cut -d, -f6)
check "the free beam starts 2.5 layers up (com z $z0) and falls to the floor ($z1): $(cat "$D/fall.err")" \
    awk -v a="$z0" -v b="$z1" 'BEGIN { exit !(a > 0.0249 && a < 0.0251 && b > 0.004 && b < 0.0055) }'
# the lattice format has no place for the height: export --lattice says so
"$AMORPH" export "$H" --lattice "$D/hang.lattice" 2>"$D/hangl.err"
check "export --lattice of the raised beam: $(cat "$D/hangl.err")" \
    grep -qxF "$H: warning: the lattice format holds no starting height: --lattice $D/hang.lattice lowers the body onto the floor, not 0.02 m above it (--vxa keeps it)" "$D/hangl.err"
# amorph's own files keep amorph's placement (their <Amorph> element's <Lift>): a run's robot and its export alike
check "an exported lattice keeps amorph's placement: $(grep -c '<Lift>' "$D/run.vxa")" grep -q '<Lift>0</Lift>' "$D/run.vxa"

# prescribed displacements (VoxCAD's sample simulation: a bar clamped at x = 0, its far face clamped
# and pulled 0.1 mm along x): the face is there from the first step, as VoxCAD puts it, and the
# settled bar stretches evenly, voxel column i by i/5 of it
T=tests/data/voxcad_tensile.vxa
"$AMORPH" sim "$T" --cycles 0 --trajectory "$D/tens.csv" >"$D/tens.out" 2>"$D/tens.err"
check "the tensile bar: no warning: $(cat "$D/tens.err")" [ ! -s "$D/tens.err" ]
check "the far face moved 0.1 mm at the first step: $(sed -n 3p "$D/tens.csv" | cut -d, -f1-2,42-44)" \
    awk -F, 'NR == 3 { d = $(7 + 7 * 5) - 0.055; exit !(d > 0.99e-4 && d < 1.01e-4) }' "$D/tens.csv"
check "the settled bar stretches evenly: $(tail -n 1 "$D/tens.csv" | cut -d, -f7,14,21,28,35,42)" \
    awk -F, 'END { for (i = 0; i < 6; i++) { d = $(7 + 7 * i) - (0.005 + 0.01 * i); if (!(d > i * 2e-5 - 1e-6 && d < i * 2e-5 + 1e-6)) exit 1 } }' "$D/tens.csv"
# it exports with its displacement (<DisplaceX> of the far face's voxels) and runs the same
expect_ok "$AMORPH" export "$T" --vxa "$D/tens.vxa"
"$AMORPH" sim "$D/tens.vxa" --cycles 0 >"$D/tens2.out" 2>/dev/null
check "the exported tensile bar: $(grep -c '<DisplaceX>0.0001</DisplaceX>' "$D/tens.vxa") displaced voxels, hash $(hash_of "$D/tens2.out")" \
    sh -c "[ \$(grep -c '<DisplaceX>0.0001</DisplaceX>' '$D/tens.vxa') -eq 4 ] && [ -n '$(hash_of "$D/tens.out")' ] && [ '$(hash_of "$D/tens.out")' = '$(hash_of "$D/tens2.out")' ]"
# a displacement past 50 voxel edges: refused with its line
expect_fail 2 "^amorph: tests/data/hostile/displace_60_edges.vxa:39: <DisplaceX> 0.6 m is more than 50 voxel edges \(Lattice_Dim 0.01 m\)$" \
    "$AMORPH" sim tests/data/hostile/displace_60_edges.vxa
# issue 46: a VXA file alone cannot make an evaluation unbounded. <DtFrac> takes the key dt_frac's
# range, a period is 2 to 10^7 steps, and an evaluation is at most 10^9 steps (docs/physics.md),
# each refused before any step in one line naming the file and the line of the element to blame
# (the file's warnings aside; timeout: the builds before ran the first and the last for ever)
expect_refused() {
    code=$1; pat=$2; shift 2
    "$@" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    grep -v ': warning: ' "$TMPD/err" >"$TMPD/err1"
    if [ $rc -eq "$code" ] && [ "$(wc -l <"$TMPD/err1")" -eq 1 ] && grep -qE -- "$pat" "$TMPD/err1"; then ok
    else ko "$* -> exit $rc (want $code), stderr: $(head -c 300 "$TMPD/err1") (want /$pat/, one line)"; fi
}
H=tests/data/hostile
expect_refused 2 "^amorph: $H/dt_frac_1e-20.vxa:6: <DtFrac> (9.99999968e-21|1e-20) must be in \[1e-06, 10\] \(the key dt_frac's range\)$" \
    timeout -k 5 60 "$AMORPH" sim "$H/dt_frac_1e-20.vxa"
expect_refused 2 "^amorph: $H/dt_frac_1e-6.vxa:6: period_s = 0.025 s is 4.97e\+08 steps of .* s \(a period takes 2 to 10\^7 steps\)$" \
    timeout -k 5 60 "$AMORPH" sim "$H/dt_frac_1e-6.vxa"
expect_refused 2 "^amorph: $H/temp_period_1e-9.vxa:42: period_s = 1e-09 s is 2.21e-05 steps of .* s \(a period takes 2 to 10\^7 steps\)$" \
    timeout -k 5 60 "$AMORPH" sim "$H/temp_period_1e-9.vxa"
expect_refused 2 "^amorph: $H/dt_frac_1e-5_budget.vxa:6: dt_frac = 1e-05: up to 7.2e\+09 steps an evaluation \(2 relaxations of 3.6e\+09: relax_max_steps 40000 at 1e-05 dt_rec; 10 cycles of 500\), over the budget of 1e\+09" \
    timeout -k 5 60 "$AMORPH" sim "$H/dt_frac_1e-5_budget.vxa"
expect_refused 2 "^amorph: $H/cycles_period_budget.vxa:152: period_steps = 10000000: up to 1e\+12 steps an evaluation" \
    timeout -k 5 60 "$AMORPH" sim "$H/cycles_period_budget.vxa"
# a flag that puts it back in bounds is taken; one that pushes it over is named
"$AMORPH" sim "$H/cycles_period_budget.vxa" --period_steps 100 --cycles 1 --relax-max 300 >"$TMPD/out" 2>/dev/null
check "the file with --period_steps 100: $(head -c 200 "$TMPD/out")" grep -q '^fitness = ' "$TMPD/out"
expect_refused 2 "^amorph: --relax_max_steps = 100000000: up to .* over the budget" \
    timeout -k 5 60 "$AMORPH" sim tests/data/voxcad_quadruped_zlib.vxa --dt_frac 0.05 --relax_max_steps 100000000
# every command that loads a robot: render, export, bench --convergence
expect_refused 2 "^amorph: render: $H/dt_frac_1e-5_budget.vxa:6: dt_frac = 1e-05: up to" \
    timeout -k 5 60 "$AMORPH" render "$H/dt_frac_1e-5_budget.vxa" --out "$TMPD/long.png"
expect_refused 2 "^amorph: bench: $H/dt_frac_1e-5_budget.vxa:6: dt_frac = 1e-05: up to" \
    timeout -k 5 60 "$AMORPH" bench --convergence --random 0 "$H/dt_frac_1e-5_budget.vxa"

summary cli_vxa.sh
