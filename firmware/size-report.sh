#!/usr/bin/env bash
# The Cortex-M4F build's size report (make firmware): the flash of the linked size program
# by origin (the engine, the library routines it calls, the C runtime and the program
# around it; flash-by-origin.awk reads the map file), then the engine's RAM for 32 slots on
# 2 axes, itemised, as the program measures it on the emulated board, and the engine's
# functions that still compute in double (double-users.sh). Goal (issue 14): <= 48 KB
# flash, <= 16 KB RAM.
set -euo pipefail
dir=${1:?usage: size-report.sh BUILD_DIR}
here=$(dirname "$0")
elf=$dir/feel_m4_size.elf
read -r text data bss _ < <(arm-none-eabi-size "$elf" | tail -1)
read -r engine libgcc libm runtime program < <(awk -f "$here/flash-by-origin.awk" "$dir/feel_m4_size.map")
image=$((text + data))
echo "feel on a Cortex-M4F (-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -Os, the engine link-time optimised, FEEL_MAX_AXES=2):"
echo "flash (bytes; goal 49152 for the engine with what it calls):"
printf '  engine            %6d  (its code and constants)\n' "$engine"
if [ "$libgcc" -eq 0 ]; then
    libgcc_what='none called: the engine divides times and converts int64 to float in 32 bits itself'
else
    libgcc_what='called by the engine: 64-bit division or int64 -> float conversion, most likely'
fi
printf '  libgcc            %6d  (%s)\n' "$libgcc" "$libgcc_what"
if [ "$libm" -eq 0 ]; then
    libm_what="none called: the engine's own float exp, expm1 and tanh (float_exp.hpp), round and nextafter (float_round.hpp), sqrt an FPU instruction"
else
    libm_what='called by the engine: a float or double libm function, see the map file'
fi
printf '  libm              %6d  (%s)\n' "$libm" "$libm_what"
printf '  engine + callees  %6d  goal 49152\n' $((engine + libgcc + libm))
printf '  C runtime         %6d  (newlib: printf, exit, semihosting for the harness; malloc for the engine at start-up)\n' "$runtime"
printf '  program           %6d  (size program, start-up, heap guard)\n' "$program"
printf '  image             %6d  (text + data; the parts count strings merged across files once each)\n' "$image"
echo "static RAM of the image: $((data + bss)) bytes (.data + .bss; the engine has none)"
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "$elf" | tail -n +2
bash "$here/double-users.sh" "$dir"
