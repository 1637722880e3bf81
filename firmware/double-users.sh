#!/usr/bin/env bash
# Where the engine still computes in double precision on the Cortex-M4F (issue 14): every
# function of the engine that calls a soft-float double routine of libgcc (__aeabi_dmul,
# __aeabi_f2d, ...) or one of libm's double functions (exp, sin, fmod, ...), by source file.
# On a Cortex-M4F each such call costs 54 to 845 instructions where a float operation costs
# 1 to 5 (docs/firmware.md). Reads the plain code of the engine's archive (its objects are
# fat LTO objects: firmware/CMakeLists.txt), whose call relocations name the routines: each
# function as its file compiles it, before the link inlines across files.
# Prints a summary, one line per source file; the full list goes to BUILD_DIR/double-users.txt
# (file, calls, function).
set -euo pipefail
dir=${1:?usage: double-users.sh BUILD_DIR}
list=$dir/double-users.txt
arm-none-eabi-objdump -dr "$dir/libfeel_engine_m4.a" | awk '
/file format/ { file = $1; sub(/\.obj:$/, "", file); next }
/^[0-9a-f]+ <.*>:$/ { fn = $2; gsub(/^<|>:$/, "", fn); next }
/R_ARM_THM_(CALL|JUMP24)/ {
    callee = $NF
    if (callee ~ /^__aeabi_(d[a-z0-9]+|[filu]+2d|cd[a-z]+)$|^__[a-z]+df[0-9]$/ ||
        callee ~ /^(exp|expm1|sin|cos|tan|fmod|sqrt|pow|log|log1p|floor|ceil|round|lround|llround|trunc|atan|atan2|hypot|cbrt|asin|acos|ldexp|frexp|modf|nextafter)$/)
        calls[file "\t" fn] += 1
}
END { for (k in calls) print k "\t" calls[k] }
' | sort >"$list.raw"
# Demangled names without the engine's namespaces.
cut -f2 "$list.raw" | arm-none-eabi-c++filt | sed -E 's/(feel::)?(detail::)?(\(anonymous namespace\)::)?//g' >"$list.names"
paste <(cut -f1,3 "$list.raw") "$list.names" >"$list"
rm -f "$list.raw" "$list.names"
total=$(awk -F'\t' '{ n += $2 } END { print n + 0 }' "$list")
if [[ $total -eq 0 ]]; then
    echo "double precision in the engine: none (no function calls a soft-float double or libm double routine)"
    exit 0
fi
echo "double precision in the engine: $(wc -l <"$list") functions call soft-float double or libm double routines $total times, by source file (the functions: $list):"
awk -F'\t' '{ n[$1] += 1; c[$1] += $2 }
    END { for (f in n) printf "  %-26s %4d calls in %d function%s\n", f, c[f], n[f], n[f] == 1 ? "" : "s" }' "$list" | sort -k2,2nr
