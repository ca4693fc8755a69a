# tests/cli_arch.sh: the default build's vector gathers (Makefile GATHER=, tools/gather_flags.sh,
# docs/benchmarks.md, Build flags). tools/gather_flags.sh leaves gathers out exactly where the
# kernel says the microcode slows them (or cannot say, on Intel), with the switch the compiler
# knows; and a build with gathers gives the same results as one without ($GATHER_BUILD, the other
# choice, exported by `make test`). Run from the repository root: sh tests/cli_arch.sh
. tests/shlib.sh

# a stand-in compiler that accepts the switch $1 and refuses every other -m switch
fakecc() {
    cat >"$TMPD/cc-$2" <<EOF
#!/bin/sh
for a in "\$@"; do
    case \$a in -march=*) ;; $1) ;; -m*) exit 1 ;; esac
done
exit 0
EOF
    chmod +x "$TMPD/cc-$2"
}
fakecc "-mno-gather" new
fakecc "-mtune-ctrl=*" old
fakecc "-mnothing" none
echo 'vendor_id	: GenuineIntel' >"$TMPD/intel"
echo 'vendor_id	: AuthenticAMD' >"$TMPD/amd"
TUNE='-mtune-ctrl=^use_gather_2parts,^use_gather_4parts,^use_gather'

# flags CC MODE STATE CPUINFO: what gather_flags.sh prints with that kernel state ("" = no file)
flags() {
    if [ -n "$3" ]; then printf '%s\n' "$3" >"$TMPD/state"; else rm -f "$TMPD/state"; fi
    GDS_STATE_FILE=$TMPD/state GDS_CPUINFO=$4 sh tools/gather_flags.sh "$1" "$2"
}
# want DESC GOT WANT
want() { if [ "$2" = "$3" ]; then ok; else ko "$1: got '$2', want '$3'"; fi; }

want "mitigated microcode, new compiler" "$(flags "$TMPD/cc-new" auto 'Mitigation: Microcode' "$TMPD/intel")" -mno-gather
want "mitigated microcode, gcc 12" "$(flags "$TMPD/cc-old" auto 'Mitigation: Microcode' "$TMPD/intel")" "$TUNE"
want "mitigated, compiler without a switch" "$(flags "$TMPD/cc-none" auto 'Mitigation: Microcode' "$TMPD/intel")" ""
want "a guest of an affected host (the kernel's word)" "$(flags "$TMPD/cc-new" auto 'Unknown: Dependent on hypervisor status' "$TMPD/intel")" -mno-gather
want "not affected" "$(flags "$TMPD/cc-new" auto 'Not affected' "$TMPD/intel")" ""
want "vulnerable, no microcode (fast gathers)" "$(flags "$TMPD/cc-new" auto 'Vulnerable: No microcode' "$TMPD/intel")" ""
want "mitigation turned off (fast gathers)" "$(flags "$TMPD/cc-new" auto 'Vulnerable' "$TMPD/intel")" ""
want "no kernel word, Intel" "$(flags "$TMPD/cc-new" auto '' "$TMPD/intel")" -mno-gather
want "no kernel word, AMD (microcoded gathers)" "$(flags "$TMPD/cc-new" auto '' "$TMPD/amd")" -mno-gather
want "AMD, not affected by GDS (microcoded all the same)" "$(flags "$TMPD/cc-old" auto 'Not affected' "$TMPD/amd")" "$TUNE"
want "AMD, a guest" "$(flags "$TMPD/cc-new" auto 'Unknown: Dependent on hypervisor status' "$TMPD/amd")" -mno-gather
echo 'vendor_id	: SomeOtherVendor' >"$TMPD/other"
want "no kernel word, another vendor" "$(flags "$TMPD/cc-new" auto '' "$TMPD/other")" ""
want "GATHER=off where gathers are fast" "$(flags "$TMPD/cc-old" off 'Not affected' "$TMPD/intel")" "$TUNE"
expect_fail 2 "gather_flags: mode must be auto, off or why, not 'sometimes'" sh tools/gather_flags.sh gcc sometimes
why=$(flags "$TMPD/cc-new" why 'Mitigation: Microcode' "$TMPD/intel")
case $why in *"gathers are slow here: yes (the microcode's GDS mitigation"*"leaves gathers out"*) ok ;; *) ko "why: $why" ;; esac
why=$(flags "$TMPD/cc-new" why 'Not affected' "$TMPD/amd")
case $why in *"gathers are slow here: yes (AMD"*"leaves gathers out"*) ok ;; *) ko "why (AMD): $why" ;; esac
expect_fail 2 "GATHER must be auto, on or off, not 'maybe'" make --no-print-directory -n GATHER=maybe all

# the other choice computes the same results, bit for bit (with self-collision: its grid gathers too)
hash_of() { b=$1; shift; "$b" sim "$@" --json 2>/dev/null | sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p'; }
if [ -n "${GATHER_BUILD:-}" ]; then
    if [ -x "$GATHER_BUILD/amorph" ]; then ok; else ko "GATHER_BUILD=$GATHER_BUILD has no amorph"; fi
    for scene in "--scene sphere:8" "--scene cube:5 --collisions on --cycles 2"; do
        # shellcheck disable=SC2086
        a=$(hash_of "$AMORPH" $scene) b=$(hash_of "$GATHER_BUILD/amorph" $scene)
        if [ -n "$a" ] && [ "$a" = "$b" ]; then ok; else ko "$scene: $AMORPH gives '$a', $GATHER_BUILD/amorph '$b'"; fi
    done
    # the build that leaves gathers out has none in the step's objects (where the compiler can be told)
    off=$AMORPH
    "$GATHER_BUILD/amorph" bench --scene cube:2 --steps 2 | grep -q 'gathers=off' && off=$GATHER_BUILD/amorph
    if "$off" bench --scene cube:2 --steps 2 | grep -q 'gathers=off'; then
        n=$(objdump -d --no-show-raw-insn "$off" 2>/dev/null | grep -cE '\s(v?p?gather|vscatter)')
        want "gather instructions in $off" "$n" 0
    fi
fi
summary cli_arch
