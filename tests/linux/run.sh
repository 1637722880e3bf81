#!/usr/bin/env bash
# The Linux kernel as judge: feel's USB device in a virtual machine (docs/usb-device.md).
#
#   tests/linux/run.sh FEEL_BINARY CHECKER_BINARY FF_SPY_LIBRARY FF_PROBE [OUT_DIR]
#
# The bridge's checker (check_bridge_log) is found beside CHECKER_BINARY.
#
# Why a VM. These machines have no USB and their kernel cannot load modules. Debian's own
# kernel package (linux-image-6.1.0-*-amd64) has everything as modules: dummy_hcd (a USB
# device controller wired to a USB host controller in the same kernel), libcomposite and
# usb_f_fs (configfs gadgets with FunctionFS), usbhid with hid-pidff, evdev. So the rig boots
# that kernel under qemu-system-x86_64 with TCG (no KVM needed), serial console, no network,
# with an initramfs made here of busybox-static, the feel binary and the judges (fftest from
# Debian's `joystick`, SDL2's testhaptic from `libsdl2-tests`) with the shared libraries ldd
# says they need. The VM's /init (tests/linux/init.sh) loads the modules, starts
# `feel device --sim --usb`, runs the judges and powers off. This script then pulls the logs
# out of the console and lets the checker (tests/linux/check_device_log.cpp) decide.
#
# The run happens twice: dummy_hcd at high speed (its default) and at full speed
# (is_high_speed=0), since feel's function has both descriptor sets.
#
# Downloaded .debs are kept in build/linux-cache, so reruns fetch nothing.
set -euo pipefail

feel=$(realpath "$1")
checker=$(realpath "$2")
bridge_checker=$(dirname "$checker")/feel_check_bridge_log
spy=$(realpath "$3")
probe=$(realpath "$4")
out=${5:-out/linux}
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
cache=${FEEL_LINUX_CACHE:-$repo/build/linux-cache}
mkdir -p "$cache" "$out"
out=$(realpath "$out")

say() { echo "test-linux: $*"; }
started=$(date +%s%N)
seconds_since() { echo $(( ($(date +%s%N) - $1) / 1000000 )) | sed -E 's/([0-9]{3})$/.\1/; s/^\./0./'; }

# --- the kernel and busybox, from Debian's archive (cached) -----------------------------
kernel_pkg=$(apt-cache depends linux-image-amd64 2>/dev/null | sed -n 's/.*Depends: \(linux-image-6\.1\.0-[0-9]*-amd64\)$/\1/p' | head -1)
if [[ -z $kernel_pkg ]]; then
    # No package lists (apt-get update not run): take the newest kernel already cached.
    kernel_pkg=$(ls "$cache"/linux-image-6.1.0-*-amd64_*.deb 2>/dev/null | sort -V | tail -1 | xargs -r basename | cut -d_ -f1)
fi
[[ -n $kernel_pkg ]] || { say "cannot tell which linux-image-6.1.0-*-amd64 to fetch (run apt-get update)"; exit 1; }
fetch() {  # fetch PACKAGE: its .deb into the cache, unless it is there
    local pkg=$1
    if ! ls "$cache/${pkg}"_*.deb >/dev/null 2>&1; then
        # Messages go to stderr: this function's stdout is the path its caller captures.
        say "downloading $pkg" >&2
        (cd "$cache" && apt-get download -q "$pkg" >/dev/null 2>&1) || { say "apt-get download $pkg failed" >&2; return 1; }
    fi
    ls "$cache/${pkg}"_*.deb | sort -V | tail -1
}
kernel_deb=$(fetch "$kernel_pkg") || exit 1
busybox_deb=$(fetch busybox-static) || exit 1

# Each .deb is extracted once, next to it (the kernel's module tree is large).
extract() {  # extract DEB: prints the directory it is extracted in
    local dir=$cache/extract/$(basename "$1" .deb)
    if [[ ! -d $dir ]]; then
        rm -rf "$dir.tmp" && mkdir -p "$dir.tmp" && dpkg-deb -x "$1" "$dir.tmp" && mv "$dir.tmp" "$dir"
    fi
    echo "$dir"
}
kernel_dir=$(extract "$kernel_deb")
busybox_dir=$(extract "$busybox_deb")
work=$out/vm
rm -rf "$work"
mkdir -p "$work/root"
kver=$(ls "$kernel_dir/lib/modules" | head -1)
vmlinuz=$kernel_dir/boot/vmlinuz-$kver

# --- the initramfs ---------------------------------------------------------------------
root=$work/root
mkdir -p "$root"/{bin,sbin,etc,proc,sys,dev,tmp,run,mnt,usr/bin,lib/modules/$kver}
cp "$busybox_dir/bin/busybox" "$root/bin/busybox"
for applet in $("$root/bin/busybox" --list); do
    [[ -e $root/bin/$applet ]] || ln -s busybox "$root/bin/$applet"
done
modules=(drivers/usb/common/usb-common drivers/usb/core/usbcore drivers/usb/gadget/udc/udc-core
         fs/configfs/configfs drivers/usb/gadget/libcomposite drivers/usb/gadget/udc/dummy_hcd
         drivers/usb/gadget/function/usb_f_fs drivers/hid/hid drivers/hid/usbhid/usbhid
         drivers/hid/hid-generic drivers/input/evdev drivers/input/misc/uinput)
: > "$root/etc/modules.order"
for m in "${modules[@]}"; do
    src=$kernel_dir/lib/modules/$kver/kernel/$m.ko
    mkdir -p "$root/lib/modules/$kver/kernel/$(dirname "$m")"
    cp "$src" "$root/lib/modules/$kver/kernel/$m.ko"
    echo "/lib/modules/$kver/kernel/$m.ko" >> "$root/etc/modules.order"
done
cp "$kernel_dir/lib/modules/$kver/modules.builtin"* "$root/lib/modules/$kver/" 2>/dev/null || true
sed "s|^/lib/modules/$kver/||" "$root/etc/modules.order" > "$root/lib/modules/$kver/modules.order"
depmod -b "$root" "$kver"

# Programs and the shared libraries they load (ldd), at the same paths as here.
add_program() {  # add_program PATH [NAME_IN_VM]
    local src=$1 dst=$root/usr/bin/${2:-$(basename "$1")}
    strip --strip-debug -o "$dst" "$src"
    ldd "$src" | grep -o '/[^ ]*' | while read -r lib; do
        [[ -e $root$lib ]] && continue
        mkdir -p "$root$(dirname "$lib")"
        strip --strip-debug -o "$root$lib" "$(readlink -f "$lib")"
    done
}
add_program "$feel" feel
add_program "$probe" ff_probe
add_program "$(dirname "$probe")/hidraw_probe" hidraw_probe
add_program "$(dirname "$probe")/pid_host_probe" pid_host_probe
add_program "$(dirname "$probe")/pid_emulation_probe" pid_emulation_probe
mkdir -p "$root/etc/feel"
cp "$here/pid_host_case.sh" "$root/etc/feel/pid_host_case.sh"
fftest=$(command -v fftest || true)
testhaptic=/usr/libexec/installed-tests/SDL2/testhaptic
[[ -x $fftest ]] || { say "fftest is missing (Debian package joystick: scripts/install-deps.sh)"; exit 1; }
[[ -x $testhaptic ]] || { say "$testhaptic is missing (Debian package libsdl2-tests: scripts/install-deps.sh)"; exit 1; }
add_program "$fftest" fftest
add_program "$testhaptic" testhaptic
mkdir -p "$root/usr/lib"
cp "$spy" "$root/usr/lib/ff_spy.so"
cp "$here/init.sh" "$root/init"
chmod +x "$root/init"
(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$work/initramfs.gz"
say "initramfs $(du -h "$work/initramfs.gz" | cut -f1), kernel $kver"

# --- boot, once per speed ---------------------------------------------------------------
boot() {  # boot SPEED: high or full
    local speed=$1 hs=1 bridge=0 pidhost=0
    [[ $speed == full ]] && hs=0
    [[ $speed == "$first" ]] && bridge=1  # feel bridge needs no USB: one run is enough
    [[ $speed == "$first" ]] && pidhost=1  # the host API over hidraw: one speed is enough
    local console=$out/console-$speed.log
    local t0
    t0=$(date +%s%N)
    timeout 600 qemu-system-x86_64 -accel tcg -m 512M -smp 2 -nographic -no-reboot -nic none \
        -kernel "$vmlinuz" -initrd "$work/initramfs.gz" \
        -append "console=ttyS0 panic=-1 quiet loglevel=4 feel.hs=$hs feel.bridge=$bridge feel.pidhost=$pidhost usbhid.dyndbg=+p" \
        > "$console" 2>&1 </dev/null || { say "qemu failed ($speed speed), see $console"; return 1; }
    say "$speed speed: the VM ran $(seconds_since "$t0") s"
    # The VM writes its device log between markers on the console.
    sed -n '/^==== feel device.log begin/,/^==== feel device.log end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/device-$speed.log"
    sed -n '/^==== probe begin/,/^==== probe end/p' "$console" | sed '1d;$d' | tr -d '\r' > "$out/probe-$speed.log"
    for judge in fftest testhaptic bridge-fftest bridge-testhaptic; do
        sed -n "/^==== $judge spy begin/,/^==== $judge spy end/p" "$console" | sed '1d;$d' | tr -d '\r' \
            > "$out/$judge-$speed.spy"
    done
    sed -n '/^==== feel bridge.log begin/,/^==== feel bridge.log end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/bridge-$speed.log"
    sed -n '/^==== bridge events begin/,/^==== bridge events end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/bridge-events-$speed.txt"
    sed -n '/^==== bridge invalid begin/,/^==== bridge invalid end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/bridge-invalid-$speed.txt"
    sed -n '/^==== pid host log begin/,/^==== pid host log end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/pid-host-$speed.txt"
    sed -n '/^==== std device.log begin/,/^==== std device.log end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/std-device-$speed.log"
    sed -n '/^==== std emu begin/,/^==== std emu end/p' "$console" | sed '1d;$d' | tr -d '\r' \
        > "$out/std-emu-$speed.txt"
}
speeds=${FEEL_LINUX_SPEEDS:-high full}
first=${speeds%% *}
for speed in $speeds; do boot "$speed"; done
cp "$out/console-$first.log" "$out/console.log"
cp "$out/device-$first.log" "$out/device.log"

status=0
passed=0 failed=0
for speed in $speeds; do
    "$checker" --speed $speed --console "$out/console-$speed.log" --device-log "$out/device-$speed.log" \
        --fftest "$out/fftest-$speed.spy" --testhaptic "$out/testhaptic-$speed.spy" \
        --probe "$out/probe-$speed.log" | tee "$out/check-$speed.txt" || status=1
    read -r p f < <(sed -n 's/.* \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p' "$out/check-$speed.txt" | tail -1) || true
    passed=$((passed + ${p:-0})) failed=$((failed + ${f:-1}))
done
# feel bridge (docs/real-devices.md), run in the first speed's VM: what fftest and
# testhaptic asked the bridge's event node for against what the feel device received.
"$bridge_checker" --console "$out/console-$first.log" --wire-log "$out/bridge-$first.log" \
    --fftest "$out/bridge-fftest-$first.spy" --testhaptic "$out/bridge-testhaptic-$first.spy" \
    --events "$out/bridge-events-$first.txt" --invalid "$out/bridge-invalid-$first.txt" \
    | tee "$out/check-bridge.txt" || status=1
read -r p f < <(sed -n 's/.* \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p' "$out/check-bridge.txt" | tail -1) || true
passed=$((passed + ${p:-0})) failed=$((failed + ${f:-1}))
# The host API over hidraw (tests/linux/pid_host_case.sh), in the first speed's VM: what
# feel::host::PidDevice asked for against what the device received.
"$(dirname "$checker")/feel_check_pid_host_log" --probe "$out/pid-host-$first.txt" --device-log "$out/device-$first.log" \
    | tee "$out/check-pid-host.txt" || status=1
read -r p f < <(sed -n 's/.* \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p' "$out/check-pid-host.txt" | tail -1) || true
passed=$((passed + ${p:-0})) failed=$((failed + ${f:-1}))
# Host emulation on a plain PID gadget (tests/linux/pid_host_case.sh), in the first speed's
# VM: the gadget's motor force against the device-side rendering of the same sensations.
"$(dirname "$checker")/feel_check_pid_emulation" --probe "$out/std-emu-$first.txt" \
    --device-log "$out/std-device-$first.log" --console "$out/console-$first.log" \
    | tee "$out/check-pid-emulation.txt" || status=1
read -r p f < <(sed -n 's/.* \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p' "$out/check-pid-emulation.txt" | tail -1) || true
passed=$((passed + ${p:-0})) failed=$((failed + ${f:-1}))
say "done in $(seconds_since "$started") s (console: $out/console.log, device log: $out/device.log)"
echo "linux: $passed passed, $failed failed"
exit $status
