#!/bin/sh
# /init of the test VM (tests/linux/run.sh builds the initramfs around it).
#
# Loads the USB gadget and HID modules in dependency order, starts feel's USB device on
# dummy_hcd, waits for the kernel's hid-pidff to take it, runs the judges (fftest, SDL2's
# testhaptic) against the event device, stops feel (which unbinds its gadget) and prints
# feel's device log between markers on the console, for the host to pick up. Never exits
# without powering off: a hung step is cut by its own time limit in seconds, and named on
# the console by a line "FAIL: ... did not ..." (the checkers fail on it), instead of
# running into qemu's 600 s timeout.
export PATH=/usr/bin:/bin:/sbin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
mount -t tmpfs tmpfs /tmp
mount -t tmpfs tmpfs /run

hs=1
bridge=0
pidhost=0
for word in $(cat /proc/cmdline); do
    case $word in
        feel.hs=*) hs=${word#feel.hs=} ;;
        feel.bridge=*) bridge=${word#feel.bridge=} ;;
        feel.pidhost=*) pidhost=${word#feel.pidhost=} ;;
    esac
done

mark() { echo "==== $* t=$(cut -d' ' -f1 /proc/uptime)"; }
exec 3>&1  # the console, for FAIL lines from commands whose output goes to a file

# bounded SECONDS NAME COMMAND...: runs COMMAND, sent SIGTERM after SECONDS and SIGKILL 3 s
# later; cut short, it gets a FAIL line naming it. Returns COMMAND's exit status.
bounded() {
    limit=$1 name=$2
    shift 2
    timeout -k 3 "$limit" "$@"
    status=$?
    if [ "$status" -eq 143 ] || [ "$status" -eq 137 ]; then
        echo "FAIL: $name did not end within its $limit s (exit status $status)" >&3
    fi
    return "$status"
}

# await_exit NAME PID SECONDS: waits for the background program PID to end, at most
# SECONDS; past that it gets a FAIL line naming it and SIGKILL. Returns its exit status.
await_exit() {
    ticks=0
    while kill -0 "$2" 2>/dev/null; do
        if [ "$ticks" -ge $(($3 * 10)) ]; then
            echo "FAIL: $1 did not exit within $3 s; killed" >&3
            kill -KILL "$2" 2>/dev/null
            break
        fi
        ticks=$((ticks + 1))
        sleep 0.1
    done
    wait "$2"
}

# stop_program NAME PID: SIGTERM, then await_exit with 5 s; prints "NAME exit status N"
# (the checkers read it) and "NAME stopped in S s" (from SIGTERM to its exit, 0.1 s steps).
stop_program() {
    read -r stop_t0 rest < /proc/uptime
    kill -TERM "$2" 2>/dev/null
    await_exit "$1" "$2" 5
    status=$?
    read -r stop_t1 rest < /proc/uptime
    echo "$1 exit status $status"
    echo "$1 stopped in $(awk -v a="$stop_t0" -v b="$stop_t1" 'BEGIN { printf "%.2f", b - a }') s"
}
. /etc/feel/pid_host_case.sh
finish() {
    mark "end"
    sync
    poweroff -f
}

mark "modules"
for m in $(cat /etc/modules.order); do
    case $m in
        */dummy_hcd.ko) insmod "$m" is_high_speed="$hs" || { echo "insmod $m failed"; finish; } ;;
        *) insmod "$m" || { echo "insmod $m failed"; finish; } ;;
    esac
done
mount -t configfs none /sys/kernel/config
mount -t debugfs none /sys/kernel/debug 2>/dev/null
# hid-pidff's reasons (it lives in usbhid) at debug level, in dmesg.
echo "module usbhid +p" > /sys/kernel/debug/dynamic_debug/control 2>/dev/null
mark "modules loaded"

# --- feel's device, bound to dummy_hcd's UDC --------------------------------------------
feel device --sim --usb --profile iforce2 --log /tmp/device.log &
feel_pid=$!
mark "feel started"

# A heartbeat on the console every 5 s: how far the kernel and feel got.
( while :; do sleep 5; mark "heartbeat"; dmesg | tail -n 3; tail -n 2 /tmp/device.log; done ) &
heartbeat=$!

# Wait (up to 90 s of VM time) until hid_connect() is done: it prints "HID v1.11" after the
# force-feedback init (hid-pidff's). Then find the event device whose capabilities have
# EV_FF (bit 21).
read -r up rest < /proc/uptime
deadline=$(( ${up%.*} + 90 ))
until dmesg | grep -q "HID v1.11"; do
    read -r up rest < /proc/uptime
    [ "${up%.*}" -ge "$deadline" ] && break
    sleep 1
done
mark "hid connected"
event=$(ff_event_device)
# feel's own protocol through hidraw: every USB path of the backend, whatever hid-pidff
# decided (tests/linux/hidraw_probe.cpp).
mark "hidraw probe"
bounded 30 hidraw_probe hidraw_probe /dev/hidraw0 > /tmp/hidraw.log 2>&1
cat /tmp/hidraw.log
cat /tmp/hidraw.log >> /tmp/probe.log
pid_host_run /dev/hidraw0
if [ -z "$event" ]; then
    mark "no force-feedback event device"
else
    mark "event device $event"
    sleep 0.5
    # fftest: one of each of its effects, in its order, each played for a few seconds.
    # It reads the effect number from stdin; -1 ends it.
    mark "fftest begin"
    ( for n in 0 1 2 3 4 5; do echo $n; sleep 1.2; done; echo -1 ) |
        bounded 60 fftest env FF_SPY_LOG=/tmp/fftest.spy LD_PRELOAD=/usr/lib/ff_spy.so fftest "$event" 2>&1
    mark "fftest end"
    mark "testhaptic begin"
    bounded 90 testhaptic env FF_SPY_LOG=/tmp/testhaptic.spy LD_PRELOAD=/usr/lib/ff_spy.so testhaptic 2>&1 </dev/null
    mark "testhaptic end"
    # The measurements: EVIOCSFF + play -> first motor tick, and the loop under a flood.
    bounded 60 "ff_probe latency" ff_probe "$event" latency 40 > /tmp/probe.log 2>&1
    bounded 30 "ff_probe flood" ff_probe "$event" flood 3 >> /tmp/probe.log 2>&1
    mark "probe end"
fi

kill "$heartbeat" 2>/dev/null
mark "feel stop"
stop_program "feel device" "$feel_pid"
ls /sys/kernel/config/usb_gadget/ 2>/dev/null | sed 's/^/gadget left: /'
echo "==== feel device.log begin"
cat /tmp/device.log 2>/dev/null
echo "==== feel device.log end"
echo "==== probe begin"
cat /tmp/probe.log 2>/dev/null
echo "==== probe end"
pid_host_print
pid_emulation_run
for judge in fftest testhaptic; do
    echo "==== $judge spy begin"
    cat /tmp/$judge.spy 2>/dev/null
    echo "==== $judge spy end"
done

# --- feel bridge: the simulated device as a uinput joystick (docs/real-devices.md) -------
# The USB device is gone by now, so the bridge's event node is the only one with EV_FF.
if [ "$bridge" = 1 ]; then
    mark "bridge begin"
    feel bridge --device sim:iforce2 --log /tmp/bridge.log --verbose > /tmp/bridge.out 2>&1 &
    bridge_pid=$!
    bridge_event=
    for i in $(seq 1 300); do
        bridge_event=$(sed -n 's|.* as \(/dev/input/event[0-9]*\) .*|\1|p' /tmp/bridge.out)
        [ -n "$bridge_event" ] && break
        kill -0 "$bridge_pid" 2>/dev/null || break
        sleep 0.1
    done
    cat /tmp/bridge.out
    if [ -z "$bridge_event" ]; then
        mark "no bridge event device"
    else
        mark "bridge event device $bridge_event"
        mark "bridge fftest begin"
        # The handle's motion under fftest's forces, as input events: the first 1000
        # (struct input_event, 24 bytes each on x86-64) read from the node meanwhile.
        ( timeout 6 cat "$bridge_event" | head -c 24000 > /tmp/bridge-events.bin ) &
        events_reader=$!
        ( for n in 0 1 2 3 4 5; do echo $n; sleep 1.2; done; echo -1 ) |
            bounded 60 "bridge fftest" env FF_SPY_LOG=/tmp/bridge-fftest.spy LD_PRELOAD=/usr/lib/ff_spy.so fftest "$bridge_event" 2>&1
        mark "bridge fftest end"
        await_exit "the bridge's event reader" "$events_reader" 10
        echo "==== bridge events begin"
        hexdump -v -e '24/1 "%02x" "\n"' /tmp/bridge-events.bin
        echo "==== bridge events end"
        mark "bridge testhaptic begin"
        bounded 90 "bridge testhaptic" env FF_SPY_LOG=/tmp/bridge-testhaptic.spy LD_PRELOAD=/usr/lib/ff_spy.so testhaptic 2>&1 </dev/null
        mark "bridge testhaptic end"
        # ff_effects the device cannot play: a clean errno each, and the bridge carries on.
        bounded 30 "ff_probe invalid" ff_probe "$bridge_event" invalid 0 > /tmp/bridge-invalid.log 2>&1
        echo "==== bridge invalid begin"
        cat /tmp/bridge-invalid.log
        echo "==== bridge invalid end"
    fi
    stop_program "feel bridge" "$bridge_pid"
    cat /tmp/bridge.out
    echo "==== feel bridge.log begin"
    cat /tmp/bridge.log 2>/dev/null
    echo "==== feel bridge.log end"
    for judge in bridge-fftest bridge-testhaptic; do
        echo "==== $judge spy begin"
        cat /tmp/$judge.spy 2>/dev/null
        echo "==== $judge spy end"
    done
fi
dmesg | grep -iE 'pidff|force|hid|usb' | sed 's/^/dmesg: /'
finish
