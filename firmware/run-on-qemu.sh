#!/usr/bin/env bash
# Runs the Cortex-M4F test program on qemu's mps2-an386 board (semihosting for output and
# exit status, -icount shift=0 so SysTick counts instructions) and compares its forces
# with the x86 build's (tests/firmware/firmware_compare.cpp).
#   run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM
set -euo pipefail
elf=${1:?usage: run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM}
compare=${2:?usage: run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM}
if [[ ! -f $elf ]]; then
  echo "no firmware at $elf: run 'make firmware' (make test does it first)" >&2
  exit 1
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none -icount shift=0 \
    -semihosting-config enable=on,target=native -kernel "$elf" > "$out"
"$compare" "$out"
