#!/bin/sh
# tools/check_layers.sh: who may include whom (docs/architecture.md). The library's layers, in order:
#   base  sim  geno  evo  io  api
# A source of src/L/ and the header include/amorph/L.h may include the public headers of L's layer
# and of the layers before it, and src/L/'s own private headers (L_internal.h); nothing else of
# amorph (no amorph.h, no port.h: the porting layer is the program's, port/port.h; no path into
# another folder). The ports (port/) may include port.h and, of the library, amorph/base.h only;
# include/amorph/ holds no port.h. The profiles' configuration headers (include/amorph/config_*.h)
# belong to the base layer and include nothing. Inside a layer, the files' calls form no circle.
# Prints one line per breach and exits 1 when there is one.
LAYERS="base sim geno evo io api"
CONFIGS=$(cd include && ls amorph/config_*.h | tr '\n' ' ')
bad=0 n=0
# the public headers a file of layer $1 may include
allowed() {
    a="$CONFIGS"
    for l in $LAYERS; do a="$a amorph/$l.h"; [ "$l" = "$1" ] && break; done
    echo "$a"
}
check_file() { # file, allowed quoted includes
    f=$1; shift
    n=$((n + 1))
    for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
        case " $* " in *" $inc "*) ;; *) echo "check-layers: $f includes \"$inc\" (allowed: $*)"; bad=1 ;; esac
    done
}
for l in $LAYERS; do
    [ -d "src/$l" ] || { echo "check-layers: src/$l is missing"; bad=1; continue; }
    own=$(cd "src/$l" && ls *.h 2>/dev/null | tr '\n' ' ')
    for f in src/$l/*.c src/$l/*.h; do
        [ -f "$f" ] || continue
        case $(basename "$f") in "${l}"_*) ;; *) echo "check-layers: $f is not named ${l}_*"; bad=1 ;; esac
        check_file "$f" $(allowed "$l") $own
    done
    check_file "include/amorph/$l.h" $(allowed "$l" | sed "s| amorph/$l.h||")
done
for f in include/amorph/config_*.h; do check_file "$f"; done
# and inside a layer no circle of calls between its files: a file calls another's functions (a
# function defined at the start of a line, am_NAME(...), mentioned as am_NAME( elsewhere), and
# those calls sort in an order (tsort), so the step never calls back into the model build
for l in $LAYERS; do
    set -- src/$l/*.c
    edges=$(awk 'FNR == 1 { if (!first) first = FILENAME; pass += FILENAME == first; f = FILENAME; sub(/.*\//, "", f) }
        pass == 1 && /^[a-z][a-z0-9_ ]*[ *]am_[a-z0-9_]*\(.*[^;]$/ { s = $0; sub(/\(.*/, "", s); sub(/.*[ *]/, "", s); def[s] = f; next }
        pass == 2 { s = $0; while (match(s, /am_[a-z0-9_]*\(/)) { fn = substr(s, RSTART, RLENGTH - 1); s = substr(s, RSTART + RLENGTH)
            if ((fn in def) && def[fn] != f) print f, def[fn] } }' "$@" "$@" | sort -u)
    [ -n "$edges" ] || continue
    if ! echo "$edges" | tsort >/dev/null 2>&1; then
        echo "check-layers: src/$l: its files call each other in a circle:" $(echo "$edges" | tsort 2>&1 >/dev/null | grep -v 'input contains a loop' | sed 's/^tsort: //'); bad=1
    fi
done
for f in src/*; do
    case " $LAYERS " in *" $(basename "$f") "*) ;; *) echo "check-layers: $f is not a layer's folder"; bad=1 ;; esac
done
for f in $(find port -name '*.c' -o -name '*.h' | sort); do
    n=$((n + 1))
    for inc in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f"); do
        case $inc in amorph/base.h | port.h) ;;
        amorph.h | amorph/* | *src/*) echo "check-layers: $f includes \"$inc\" (a port may include amorph/base.h and port.h)"; bad=1 ;;
        *.c) echo "check-layers: $f includes the source \"$inc\" (a port compiles its sources as objects)"; bad=1 ;; esac
    done
done
for f in include/amorph/port.h include/port.h; do
    [ -e "$f" ] && { echo "check-layers: $f: the porting layer is the program's (port/port.h), not the library's"; bad=1; }
done
if [ $bad -ne 0 ]; then echo "check-layers: 0 passed, 1 failed"; exit 1; fi
echo "check-layers: $n files of src/, include/amorph/ and port/ include only what their layer may, and no layer's files call each other in a circle"
