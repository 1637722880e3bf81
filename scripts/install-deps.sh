#!/usr/bin/env bash
# The one list of everything feel needs from Debian. It installs only what is missing,
# so a machine that already has everything runs no apt-get at all.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang libclang-rt-14-dev pkg-config  # toolchain; clang + its runtime for libFuzzer
  nlohmann-json3-dev   # sensation files (JSON)
  libcli11-dev         # the feel command line
  libgtest-dev         # unit tests
  libbenchmark-dev     # benchmarks
  librapidcheck-dev    # property tests
  libcairo2-dev        # plots (SVG and PNG)
  libboost-dev         # Boost.Asio: Unix-socket and TCP transports (header-only)
  libaio-dev           # feel device --usb: FunctionFS endpoints' asynchronous I/O
  qemu-system-x86 cpio kmod  # make test-linux: boot Debian's kernel in a VM (initramfs, depmod)
  joystick libsdl2-tests     # make test-linux: the judges fftest and SDL2's testhaptic, copied into the VM
)

missing=()
for p in "${packages[@]}"; do
  [[ $p == \#* ]] && continue
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps: everything is installed"
fi
