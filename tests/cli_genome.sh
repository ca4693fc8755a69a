# tests/cli_genome.sh: amorph random, amorph express and genome files through the command.
. tests/shlib.sh

# random genomes of every representation, reproducible from the seed
for r in dct cppn gmx; do
    expect_ok "$AMORPH" random --repr $r --seed 5 --out "$TMPD/$r.genome"
    expect_ok "$AMORPH" random --repr $r --seed 5 --materials 3 --out "$TMPD/${r}3.genome"
    "$AMORPH" random --repr $r --seed 5 >"$TMPD/$r.again" 2>/dev/null
    if cmp -s "$TMPD/$r.genome" "$TMPD/$r.again"; then ok; else ko "random --repr $r --seed 5 differs between runs"; fi
    if head -n 1 "$TMPD/$r.genome" | grep -q '^amorph-genome 1$'; then ok; else ko "$r.genome: no 'amorph-genome 1' line"; fi
    if grep -q '^materials passive active active90$' "$TMPD/${r}3.genome"; then ok; else ko "${r}3.genome: not three materials"; fi
    # expressed into a lattice file
    expect_ok "$AMORPH" express "$TMPD/$r.genome" --out "$TMPD/$r.lattice"
    if grep -qE '^voxels=[0-9]+$' "$TMPD/out"; then ok; else ko "express $r: no voxels=N line: $(cat "$TMPD/out")"; fi
    if head -n 1 "$TMPD/$r.lattice" | grep -q '^amorph-lattice'; then ok; else ko "$r.lattice is not a lattice"; fi
    # a genome read back and written again is the same text
    expect_ok "$AMORPH" express "$TMPD/${r}3.genome"
done
"$AMORPH" random --repr dct --seed 6 >"$TMPD/other.genome" 2>/dev/null
if cmp -s "$TMPD/dct.genome" "$TMPD/other.genome"; then ko "seeds 5 and 6 give the same genome"; else ok; fi

# amorph sim accepts a genome file (a small workspace and a short run)
expect_ok "$AMORPH" random --repr dct --size 5 --seed 3 --out "$TMPD/small.genome"
expect_ok "$AMORPH" sim "$TMPD/small.genome" --cycles 1 --period-steps 20 --relax-max 20
if grep -qE '^voxels = [1-9]' "$TMPD/out"; then ok; else ko "sim of a genome: $(head -c 200 "$TMPD/out")"; fi

# an empty body is not an error
printf 'amorph-genome 1\nrepr gmx\nmaterials passive active\nworkspace 6 6 6\ngmx 0\nend\n' >"$TMPD/empty.genome"
expect_ok "$AMORPH" express "$TMPD/empty.genome" --out "$TMPD/empty.lattice"
if grep -q '^voxels=0$' "$TMPD/out"; then ok; else ko "empty genome: $(cat "$TMPD/out")"; fi

# bad genome files: file:line: problem, one line, exit status 2
head='amorph-genome 1\nrepr dct\nmaterials passive active\nworkspace 8 8 8\n'
printf "${head}dct 2\namp 0 0 0 0.5 2\n" >"$TMPD/range.genome"
expect_fail 2 'range\.genome:6: amplitude .2. is not a number in \[-1, 1\]' "$AMORPH" express "$TMPD/range.genome"
expect_fail 2 'range\.genome:6: ' "$AMORPH" sim "$TMPD/range.genome"
printf 'amorph-genome 7\n' >"$TMPD/version.genome"
expect_fail 2 'version\.genome:1: genome format version 7' "$AMORPH" express "$TMPD/version.genome"
printf 'amorph-genome 1\n\n# comment\nrepr blob\n' >"$TMPD/repr.genome"
expect_fail 2 'repr\.genome:4: unknown representation .blob.' "$AMORPH" express "$TMPD/repr.genome"
printf "${head}dct 1\namp 0 0 0 0.5\n" >"$TMPD/short.genome"
expect_fail 2 'short\.genome:6: unexpected end of text' "$AMORPH" express "$TMPD/short.genome"
printf "${head}dct 1\namp 0 0 0 0.5\nend\n" >"$TMPD/missing.genome"
expect_fail 2 "missing\.genome:7: missing line 'amp 1 0 0'" "$AMORPH" express "$TMPD/missing.genome"
printf 'amorph-genome 1\nrepr gmx\nmaterials passive active\nworkspace 8 8 8\ngmx 100000\n' >"$TMPD/cap.genome"
expect_fail 2 'cap\.genome:5: 100000 GMX points exceed' "$AMORPH" express "$TMPD/cap.genome"
printf 'amorph-genome 1\nrepr gmx\nmaterials passive active\nworkspace 99 8 8\n' >"$TMPD/big.genome"
expect_fail 2 'big\.genome:4: workspace side 99 exceeds' "$AMORPH" express "$TMPD/big.genome"
printf 'amorph-genome 1\nrepr cppn\nmaterials passive active\nworkspace 8 8 8\ncppn 1 1\nnode 0 0 tanh 0 1 1\n' >"$TMPD/fn.genome"
expect_fail 2 "fn\.genome:6: unknown function 'tanh'" "$AMORPH" express "$TMPD/fn.genome"
printf 'amorph-genome 1\nrepr gmx\nmaterials passive steel\nworkspace 8 8 8\ngmx 0\nend\n' >"$TMPD/steel.genome"
expect_fail 2 "steel\.genome:3: material 'steel' is not in the built-in palette \(a run's genome: give the run's palette, --palette and --materialK" "$AMORPH" express "$TMPD/steel.genome"
# a genome of the follow-up's palette: expressed in it when express is given it, its lattice carrying
# those materials; a setting that is not a palette's refused
expect_ok "$AMORPH" random --palette unshackled --seed 3 --out "$TMPD/four.genome"
expect_fail 2 "four\.genome:4: material 'passive_soft' is not in the built-in palette" "$AMORPH" express "$TMPD/four.genome"
expect_ok "$AMORPH" express "$TMPD/four.genome" --palette unshackled --out "$TMPD/four.lattice"
check "express --palette: the lattice's materials are the follow-up's" [ "$(grep -c '^material passive_soft E=5000000 \|^material active_minus E=5000000 ' "$TMPD/four.lattice")" -eq 2 ]
# --material4 over the preset: the genome names active_minus, gone from the palette
expect_fail 2 "four\.genome:4: material 'active_minus' is not in the palette the settings give" \
    "$AMORPH" express "$TMPD/four.genome" --palette unshackled --material4 "muscle_b modulus=5e6 density=1e6 cte=0.01 phase=90"
expect_fail 2 "express: --cycles is not a setting express takes" "$AMORPH" express "$TMPD/four.genome" --cycles 3
printf 'size 2 2 2\n' >"$TMPD/notgenome.txt"
expect_fail 2 'notgenome\.txt:1: not a genome' "$AMORPH" express "$TMPD/notgenome.txt"
expect_fail 2 'nothere\.genome' "$AMORPH" express "$TMPD/nothere.genome"

# flags
expect_fail 2 "random: --representation = 'fourier': expected dct, cppn or gmx" "$AMORPH" random --repr fourier
expect_fail 2 "random: --materials = '99': expected an integer in \[1, [0-9]+\]" "$AMORPH" random --repr dct --materials 99
expect_fail 2 "random: materials = 4: the palette has 3 \(seed\)" "$AMORPH" random --repr dct --materials 4
# the follow-up's palette names the genome's four fields; a palette of keys names its own
expect_ok "$AMORPH" random --repr cppn --palette unshackled --out "$TMPD/u.genome"
if grep -qx 'materials passive_soft passive_hard active_plus active_minus' "$TMPD/u.genome"; then ok; else ko "random --palette unshackled: $(grep '^materials' "$TMPD/u.genome")"; fi
expect_ok "$AMORPH" random --repr dct --palette unshackled --material5 "gel modulus=1e5 density=1000 cte=0 phase=0" --out "$TMPD/u5.genome"
if grep -qx 'materials passive_soft passive_hard active_plus active_minus gel' "$TMPD/u5.genome"; then ok; else ko "random --material5: $(grep '^materials' "$TMPD/u5.genome")"; fi
expect_fail 2 "random: --seed = '-3': expected an integer" "$AMORPH" random --repr dct --seed -3
expect_fail 2 "random: --workspace = '999': each side must be in \[1, " "$AMORPH" random --repr dct --size 999
expect_fail 2 "random: --population is not a setting of a genome" "$AMORPH" random --population 4
# the defaults are the configuration's (gmx), and the old spellings are aliases of its keys
expect_ok "$AMORPH" random --seed 1
cp "$TMPD/out" "$TMPD/default.genome"
expect_ok "$AMORPH" random --representation gmx --seed 1
check "random without --repr is the configuration's default, gmx" cmp -s "$TMPD/out" "$TMPD/default.genome"
expect_ok "$AMORPH" random --repr dct --size 5 --seed 3
cp "$TMPD/out" "$TMPD/alias.genome"
expect_ok "$AMORPH" random --representation=dct --workspace 5 --seed=3
check "--repr/--size are aliases of --representation/--workspace" cmp -s "$TMPD/out" "$TMPD/alias.genome"
expect_fail 2 "random: unknown option '--bogus'" "$AMORPH" random --repr dct --bogus
expect_fail 2 'express: name a genome file' "$AMORPH" express
expect_fail 2 "express: unknown option '--bogus'" "$AMORPH" express "$TMPD/dct.genome" --bogus
expect_ok "$AMORPH" random --help
expect_ok "$AMORPH" express --help

summary cli_genome.sh
