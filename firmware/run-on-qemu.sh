#!/usr/bin/env bash
# Runs the Cortex-M4F test program on qemu's mps2-an386 board (semihosting for output and
# exit status, -icount shift=0 so SysTick counts instructions) and compares its forces
# with the x86 build's (tests/firmware/firmware_compare.cpp). An image older than the
# sources it was built from fails first, naming `make firmware` (docs/firmware.md).
#   run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM
set -euo pipefail
elf=${1:?usage: run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM}
compare=${2:?usage: run-on-qemu.sh FIRMWARE_ELF COMPARE_PROGRAM}
if [[ ! -f $elf ]]; then
  echo "no firmware at $elf: run 'make firmware' (make test does it first)" >&2
  exit 1
fi
# A stale image would pass with the figures of the engine it was built from, so the image
# must be newer than every file of this tree it was compiled from: the sources and headers
# of its objects in the build's ninja deps log (what ninja itself rebuilds it on), and every
# engine source the firmware's glob takes (a new file is in no deps log yet). Milliseconds.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(dirname "$elf")
stale() {
  echo "stale firmware: $elf $1: run 'make firmware' (make test does it first)" >&2
  exit 1
}
[[ -f $build/.ninja_deps ]] || stale "has no ninja deps log in $build to check it against the sources"
mapfile -t objects < <(ninja -C "$build" -t inputs "$(basename "$elf")" | grep '\.obj$')
((${#objects[@]} > 0)) || stale "is not a target of the ninja build in $build"
declare -A built_from=()
# The deps log names files relative to the build directory when they are below its parent
# (a build directory inside the tree), absolute otherwise: both are made absolute here.
while IFS= read -r f; do
  [[ $f == /* ]] || f=$(realpath -m "$build/$f")
  [[ $f == "$root"/* ]] && built_from[$f]=1
done < <(ninja -C "$build" -t deps "${objects[@]}" | sed -n 's|^    \(.*\)|\1|p')
for f in "${!built_from[@]}"; do
  [[ -e $f ]] || stale "was built from $f, which is gone"
done
while IFS= read -r f; do
  [[ -n ${built_from[$f]:-} ]] || stale "was built without $f (or from another tree)"
done < <(find "$root/src/engine" -name '*.cpp')
newer=$(find "${!built_from[@]}" -newer "$elf" -print -quit)
[[ -z $newer ]] || stale "is older than $newer"
# The x86 half: the comparison program renders the same scenario with this tree's engine,
# so it must be newer than the engine's sources and public headers too (an old one reports
# the engine's change as a difference between the boards, not as a stale build).
newer=$(find "$root/src/engine" "$root/include/feel" "$root/tests/firmware" -type f -newer "$compare" -print -quit)
if [[ -n $newer ]]; then
  echo "stale comparison program: $compare is older than $newer: rebuild the x86 tree (cmake --build on its build directory; make test does it first)" >&2
  exit 1
fi
out=$(mktemp)
trap 'rm -f "$out"' EXIT
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none -icount shift=0 \
    -semihosting-config enable=on,target=native -kernel "$elf" > "$out"
"$compare" "$out"
