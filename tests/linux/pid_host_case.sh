# The host API over hidraw in the VM (sourced by tests/linux/init.sh; tests/linux/run.sh
# copies it into the initramfs): feel::host::PidDevice, which drives any HID PID device from
# its own descriptor, plays every PID effect type on feel's USB gadget through the kernel's
# hidraw and USB stack (tests/linux/pid_host_probe.cpp). The host checks the device's log
# against what the probe asked for (tests/linux/check_pid_host_log.cpp).

# pid_host_run NODE: runs the probe on NODE (kernel command line feel.pidhost=1 only: one
# speed is enough, the USB paths are the hidraw probe's and fftest's at both).
pid_host_run() {
    [ "$pidhost" = 1 ] || return 0
    mark "pid host probe"
    timeout 60 pid_host_probe "$1" > /tmp/pid-host.log 2>&1
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
