#!/bin/sh
# /init of the test VM (tests/linux/run.sh builds the initramfs around it).
#
# Loads the USB gadget and HID modules in dependency order, starts feel's USB device on
# dummy_hcd, waits for the kernel's hid-pidff to take it, runs the judges (fftest, SDL2's
# testhaptic) against the event device, stops feel (which unbinds its gadget) and prints
# feel's device log between markers on the console, for the host to pick up. Never exits
# without powering off: a hung step is cut by its own timeout.
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
timeout 30 hidraw_probe /dev/hidraw0 > /tmp/hidraw.log 2>&1
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
        FF_SPY_LOG=/tmp/fftest.spy LD_PRELOAD=/usr/lib/ff_spy.so timeout 60 fftest "$event" 2>&1
    mark "fftest end"
    mark "testhaptic begin"
    FF_SPY_LOG=/tmp/testhaptic.spy LD_PRELOAD=/usr/lib/ff_spy.so timeout 90 testhaptic 2>&1 </dev/null
    mark "testhaptic end"
    # The measurements: EVIOCSFF + play -> first motor tick, and the loop under a flood.
    ff_probe "$event" latency 40 > /tmp/probe.log 2>&1
    ff_probe "$event" flood 3 >> /tmp/probe.log 2>&1
    mark "probe end"
fi

kill "$heartbeat" 2>/dev/null
mark "feel stop"
kill -TERM "$feel_pid"
for i in $(seq 1 50); do kill -0 "$feel_pid" 2>/dev/null || break; sleep 0.1; done
wait "$feel_pid"
echo "feel device exit status $?"
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
            FF_SPY_LOG=/tmp/bridge-fftest.spy LD_PRELOAD=/usr/lib/ff_spy.so timeout 60 fftest "$bridge_event" 2>&1
        mark "bridge fftest end"
        wait "$events_reader"
        echo "==== bridge events begin"
        hexdump -v -e '24/1 "%02x" "\n"' /tmp/bridge-events.bin
        echo "==== bridge events end"
        mark "bridge testhaptic begin"
        FF_SPY_LOG=/tmp/bridge-testhaptic.spy LD_PRELOAD=/usr/lib/ff_spy.so timeout 90 testhaptic 2>&1 </dev/null
        mark "bridge testhaptic end"
        # ff_effects the device cannot play: a clean errno each, and the bridge carries on.
        ff_probe "$bridge_event" invalid 0 > /tmp/bridge-invalid.log 2>&1
        echo "==== bridge invalid begin"
        cat /tmp/bridge-invalid.log
        echo "==== bridge invalid end"
    fi
    kill -TERM "$bridge_pid" 2>/dev/null
    for i in $(seq 1 50); do kill -0 "$bridge_pid" 2>/dev/null || break; sleep 0.1; done
    wait "$bridge_pid"
    echo "feel bridge exit status $?"
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
