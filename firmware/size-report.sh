#!/usr/bin/env bash
# The Cortex-M4F build's size report (make firmware): flash of the linked size program and
# the engine's share of it, then the engine's RAM for 32 slots on 2 axes, itemised, as the
# program measures it on the emulated board. Goal (issue 14): <= 48 KB flash, <= 16 KB RAM.
set -euo pipefail
# awk without gawk's strtonum: a hexadecimal size field to a number.
hexfn='function hex(h,  i, n) { n = 0; h = tolower(h); for (i = 1; i <= length(h); ++i) n = n * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1; return n }'
dir=${1:?usage: size-report.sh BUILD_DIR}
elf=$dir/feel_m4_size.elf
read -r text data bss _ < <(arm-none-eabi-size "$elf" | tail -1)
# The engine's own code and constants: every symbol of namespace feel in the image.
engine=$(arm-none-eabi-nm -S -C --size-sort "$elf" | awk "$hexfn"'$4 ~ /^feel::/ || $5 ~ /^feel::/ {s += hex($2)} END {print s + 0}')
# Soft-float double routines and libm, which the engine's double math pulls in.
soft=$(arm-none-eabi-nm -S "$elf" | awk "$hexfn"'$4 ~ /^__aeabi_d|^__(add|sub|mul|div)df3|^__(eq|ne|lt|le|gt|ge|un)df2|^__float.*df|^__fix.*df|^__extendsfdf2|^__truncdfsf2/ {s += hex($2)} END {print s + 0}')
libm=$(arm-none-eabi-nm -S "$elf" | awk "$hexfn"'$3 ~ /^[tT]$/ && $4 ~ /^(__ieee754_|__kernel_|sin$|cos$|exp$|log$|pow$|sqrt$|atan2$|floor$|round$|fmod$|expm1$|log1p$|atan$|asin$|acos$|tan$|sinh$|cosh$|hypot$)/ {s += hex($2)} END {print s + 0}')
echo "feel on a Cortex-M4F (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os):"
echo "flash (bytes): image $((text + data)) = engine $engine + soft-float double $soft + libm $libm + newlib/start-up/harness $((text + data - engine - soft - libm))"
echo "static RAM of the image: $((data + bss)) bytes (.data + .bss; the engine has none)"
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "$elf" | tail -n +2
echo "goal: flash <= 49152, RAM <= 16384"
