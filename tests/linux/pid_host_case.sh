# The host API over hidraw in the VM (sourced by tests/linux/init.sh; tests/linux/run.sh
# copies it into the initramfs): feel::host::PidDevice, which drives any HID PID device from
# its own descriptor, plays every PID effect type on feel's USB gadget through the kernel's
# hidraw and USB stack (tests/linux/pid_host_probe.cpp). The host checks the device's log
# against what the probe asked for (tests/linux/check_pid_host_log.cpp).

# ff_event_device: the last event device whose capabilities have EV_FF (bit 21), or nothing.
ff_event_device() {
    found=
    for caps in /sys/class/input/event*/device/capabilities/ev; do
        [ -e "$caps" ] || continue
        read -r ev < "$caps"
        if [ $(( 0x$ev & 0x200000 )) -ne 0 ]; then
            dir=${caps%/device/capabilities/ev}
            found=/dev/input/${dir##*/}
        fi
    done
    echo "$found"
}

# pid_host_run NODE: runs the probe on NODE (kernel command line feel.pidhost=1 only: one
# speed is enough, the USB paths are the hidraw probe's and fftest's at both).
pid_host_run() {
    [ "$pidhost" = 1 ] || return 0
    mark "pid host probe"
    bounded 60 pid_host_probe pid_host_probe "$1" > /tmp/pid-host.log 2>&1
    echo "pid_host_probe exit status $?" >> /tmp/pid-host.log
    mark "pid host probe end"
}

# pid_host_print: its output between markers on the console, for run.sh.
pid_host_print() {
    [ "$pidhost" = 1 ] || return 0
    echo "==== pid host log begin"
    cat /tmp/pid-host.log 2>/dev/null
    echo "==== pid host log end"
}

# Host emulation on a plain PID gadget (feel.pidhost=1 too): `feel device --usb
# --standard-pid-only` declares PID's reports alone and sends no vendor report. hid-pidff
# must still bind it (an event device with EV_FF); then feel's host (PidDevice over hidraw,
# tests/linux/pid_emulation_probe.cpp) plays a wall, a texture and a recoil by host
# emulation while the gadget's kinematic hand moves through them, and the gadget logs what
# its motors got (tests/linux/check_pid_emulation.cpp compares it with the device-side
# rendering). Run after the first gadget is gone, before the bridge (whose event node must
# be the only one with EV_FF). The checker's kProfile, kMotion and kLoopHz match this line.
pid_emulation_run() {
    [ "$pidhost" = 1 ] || return 0
    mark "std pid begin"
    before=$(dmesg | grep -c "HID v1.11")
    feel device --sim --usb --standard-pid-only --profile iforce2 --rate 250 --hand kinematic \
        --motion sine:x:2000:0.5 --log /tmp/std-device.log > /tmp/std-device.out 2>&1 &
    std_pid=$!
    for i in $(seq 1 300); do
        [ "$(dmesg | grep -c "HID v1.11")" -gt "$before" ] && break
        sleep 0.1
    done
    std_event=$(ff_event_device)
    if [ -n "$std_event" ]; then mark "std pid event device $std_event"; else mark "std pid no force-feedback event device"; fi
    std_node=$(ls /dev/hidraw* 2>/dev/null | head -n 1)
    bounded 60 pid_emulation_probe pid_emulation_probe "$std_node" > /tmp/std-emu.log 2>&1
    echo "pid_emulation_probe exit status $?" >> /tmp/std-emu.log
    stop_program "std feel device" "$std_pid"
    cat /tmp/std-device.out
    echo "==== std device.log begin"
    cat /tmp/std-device.log 2>/dev/null
    echo "==== std device.log end"
    echo "==== std emu begin"
    cat /tmp/std-emu.log
    echo "==== std emu end"
    mark "std pid end"
}
