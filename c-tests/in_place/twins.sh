#!/bin/sh
# Every case of the conformance suite on binary twins of its roads (each sample road
# converted to KRBI and to KDBI by `opencrg convert`), run by the conformance client once
# with the road read into memory and once read in place (OPENCRG_IN_PLACE): the two
# outputs (every answer printed to 17 significant digits) must be the same, byte for
# byte, in both behaviour profiles. The suite's own cases are nearly all text roads, which
# are never read in place; this puts each of their settings on roads that are.
#
# usage: twins.sh INCLUDE_DIR LIBRARY OPENCRG_COMMAND CONFORMANCE_DIR OUT_DIR
set -eu
inc=$1 lib=$(cd "$(dirname "$2")" && pwd)/$(basename "$2") opencrg=$3 conformance=$(cd "$4" && pwd) out=$5
rm -rf "$out"
mkdir -p "$out"
cc -O2 -Wall -I"$inc" "$conformance/oracle.c" "$lib" -lm -Wl,-rpath,"$(dirname "$lib")" -o "$out/oracle"
for format in KRBI KDBI; do
    for dir in crg-txt crg-bin; do
        mkdir -p "$out/$format/$dir"
        for road in "$conformance/$dir"/*.crg; do
            # A road that cannot be read (one names a file that does not exist) stays as it is.
            "$opencrg" convert "$road" "$out/$format/$dir/$(basename "$road")" --format "$format" 2>/dev/null ||
                cp "$road" "$out/$format/$dir/"
        done
    done
done
same=0 differ=0
for profile in current 2.0.1; do
    compat=; [ "$profile" = 2.0.1 ] && compat=2.0.1
    for format in KRBI KDBI; do
        grep -v '^#' "$conformance/cases.txt" | {
            while read -r name file nu nv rest; do
                [ -n "$name" ] || continue
                for mode in never always; do
                    (cd "$out/$format/$(dirname "$file")" &&
                        OPENCRG_COMPAT=$compat OPENCRG_IN_PLACE=$mode "$out/oracle" "$(basename "$file")" "$nu" "$nv" $rest) \
                        >"$out/$name.$mode" 2>/dev/null || true
                done
                if cmp -s "$out/$name.never" "$out/$name.always" && [ -s "$out/$name.never" ]; then
                    same=$((same + 1))
                else
                    differ=$((differ + 1))
                    echo "DIFFER $profile $format $name"
                fi
            done
            echo "$profile $format: $same the same, $differ differ"
        }
    done
done | tee "$out/summary"
# Every line of the summary must report none differing.
! grep -q "^DIFFER" "$out/summary"
