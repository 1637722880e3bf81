#!/usr/bin/env bash
# The one list of everything feel needs from Debian. It installs only what is missing,
# so a machine that already has everything runs no apt-get at all.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang libclang-rt-14-dev pkg-config  # toolchain; clang + its runtime for libFuzzer
  lld                  # the sanitizer trees' linker: half the CPU of ld.bfd per test executable
  nlohmann-json3-dev   # sensation files (JSON)
  libcli11-dev         # the feel command line
  libgtest-dev         # unit tests
  libbenchmark-dev     # benchmarks
  librapidcheck-dev    # property tests
  libcairo2-dev        # plots (SVG and PNG)
  libboost-dev         # Boost.Asio: Unix-socket and TCP transports; Boost.Beast: the Studio's server (header-only)
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib  # make firmware: the engine on a Cortex-M4F
  qemu-system-arm      # make test runs the Cortex-M4F build on the emulated mps2-an386 board
  python3              # make test-install: the ctypes consumer of libfeel.so
  chromium             # the Studio's end-to-end tests (headless, driven by playwright-core)
  libaio-dev           # feel device --usb: FunctionFS endpoints' asynchronous I/O
  qemu-system-x86 cpio kmod  # make test-linux: boot Debian's kernel in a VM (initramfs, depmod)
  joystick libsdl2-tests     # make test-linux: the judges fftest and SDL2's testhaptic, copied into the VM
  libsndfile1-dev      # feel import: decoding WAV files (src/import/wav_import.cpp)
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

# The Studio's front end (studio/) is built with Node 20 or newer and the npm packages of
# its package-lock.json; Debian bookworm's own nodejs is 18, so Node comes with the machine.
node_major=$(node --version 2>/dev/null | sed -E 's/^v([0-9]+).*/\1/' || true)
if [[ -z $node_major || $node_major -lt 20 ]]; then
  echo "install-deps: the Studio needs Node.js 20 or newer to build its front end; found: $(node --version 2>/dev/null || echo none)" >&2
  exit 1
fi
if [[ ! -d studio/node_modules ]] || [[ studio/package-lock.json -nt studio/node_modules/.package-lock.json ]]; then
  echo "install-deps: npm ci (studio/)"
  (cd studio && npm ci --no-audit --no-fund --loglevel=error)
fi
