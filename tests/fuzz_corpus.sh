#!/bin/sh
# tests/fuzz_corpus.sh DIR: the fuzz target's seed corpus (tests/fuzz_parsers.c): each file of
# tests/data of a kind the target reads, prefixed with the byte that picks its reader.
set -eu
out=$1
k=0
add() { # add KIND FILE
    k=$((k + 1))
    { printf "\\$(printf '%03o' "$1")"; cat "$2"; } >"$out/seed-$k"
}
# tests/data/hostile: the hostile cases of issue 31 (a period of 10^9 steps, a subnormal cell
# edge, a 64-character phase, an odd population, the all-zero rng of a resealed checkpoint, a
# VXD replace path past its buffer), each refused with one line; and those of issue 46, each
# refused before any step: <DtFrac> 1e-20 with <TempPeriod> 1e-18 (ran for ever), <DtFrac> 1e-6 (a
# period of 5e8 steps), <TempPeriod> 1e-9 (a period under 2 steps), <DtFrac> 1e-5 and 100,000
# cycles of 10^7 steps (VXA and config.txt: over the budget of 10^9 steps an evaluation)
for f in tests/data/*.lattice tests/data/*/*.lattice; do [ -f "$f" ] && add 0 "$f"; done
for f in tests/data/*.genome; do [ -f "$f" ] && add 1 "$f"; done
for f in tests/data/*.cfg tests/data/*.conf tests/data/*/*.cfg; do [ -f "$f" ] && add 2 "$f"; done
for f in tests/data/*checkpoint* tests/data/*/*.checkpoint; do [ -f "$f" ] && add 3 "$f"; done
for f in tests/data/*.vxa tests/data/*/*.vxa; do [ -f "$f" ] && add 4 "$f"; done
for d in tests/data/voxcraft tests/data/hostile/vxd_*; do
    [ -f "$d/base.vxa" ] && [ -f "$d/robot.vxd" ] && { k=$((k + 1)); { printf '\005'; cat "$d/base.vxa"; printf '\001'; cat "$d/robot.vxd"; } >"$out/seed-$k"; }
done
for f in tests/data/*/log.csv tests/data/*.csv; do [ -f "$f" ] && add 7 "$f"; done
# genomes, a configuration, a checkpoint and a log made by the command, when it is built
A=${AMORPH:-build/amorph}
if [ -x "$A" ]; then
    tmp=$(mktemp -d)
    for r in dct cppn gmx; do "$A" random --repr $r --seed 3 --workspace 6 >"$tmp/$r.genome" && add 1 "$tmp/$r.genome"; done
    "$A" evolve --print-config >"$tmp/c.cfg" && add 2 "$tmp/c.cfg"
    "$A" export --scene cube:2 --cycles 3 --vxa "$tmp/c.vxa" 2>/dev/null && add 4 "$tmp/c.vxa"
    "$A" evolve --workspace 6 --population 4 --evaluations 8 --quiet --no-pictures --out "$tmp/run" >/dev/null 2>&1 &&
        add 3 "$tmp/run/checkpoint.txt" && add 7 "$tmp/run/log.csv"
    rm -rf "$tmp"
fi
# a zlib stream: the one in a compressed VXA layer is base64; a tiny stored-block stream instead
k=$((k + 1)); printf '\006\170\001\001\005\000\372\377hello\006\054\002\025' >"$out/seed-$k"
echo "fuzz_corpus: $k seeds" >&2
