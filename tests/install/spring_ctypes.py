#!/usr/bin/env python3
"""Python's ctypes against an installed libfeel.so (scripts/test-install.sh).

Loads the shared library by path, opens the in-process simulated I-FORCE 2.0 stick
("sim:iforce2") held by a kinematic hand at x = 5000, plays the primer's x spring
(feel_x_spring, §8.2) and checks the force the device reports against the spring law
F = -k/10000 * (x - offset) (§3.2) at the position it reports. The struct layouts below
are written from feel.h by hand, as a binding's author would; feel_input's size field
must match the C struct's.

usage: spring_ctypes.py PATH/TO/libfeel.so
"""
import ctypes as C
import sys

MAX_AXES = 6


class OpenOptions(C.Structure):
    _fields_ = [("size", C.c_uint32), ("timeout_ms", C.c_int32), ("report_rate_hz", C.c_int32),
                ("sim_hand", C.c_char_p), ("sim_motion", C.c_char_p)]


class Input(C.Structure):
    _fields_ = [("size", C.c_uint32), ("t_us", C.c_int64), ("axis_count", C.c_int32),
                ("position", C.c_float * MAX_AXES), ("velocity", C.c_float * MAX_AXES),
                ("force", C.c_float * MAX_AXES), ("buttons", C.c_uint32), ("hats", C.c_uint32),
                ("handle_held", C.c_bool), ("hands_off", C.c_bool), ("host_lost", C.c_bool),
                ("fade_level", C.c_float), ("paused", C.c_bool), ("actuators_enabled", C.c_bool),
                ("gain", C.c_int32), ("playing_effects", C.c_int32), ("resident_effects", C.c_int32),
                ("loop_rate_hz", C.c_int32), ("measured_loop_hz", C.c_double), ("overruns", C.c_uint64),
                ("dropped_reports", C.c_uint64), ("reports_received", C.c_uint64)]


def main():
    lib = C.CDLL(sys.argv[1])
    lib.feel_version_string.restype = C.c_char_p
    lib.feel_last_error_message.restype = C.c_char_p
    lib.feel_open_ex.restype = C.c_void_p
    lib.feel_open_ex.argtypes = [C.c_char_p, C.POINTER(OpenOptions)]
    lib.feel_x_spring.restype = C.c_void_p
    lib.feel_x_spring.argtypes = [C.c_void_p] + [C.c_int32] * 6
    lib.feel_effect_start.argtypes = [C.c_void_p, C.c_int32, C.c_bool]
    lib.feel_wait_input.argtypes = [C.c_void_p, C.c_int32, C.POINTER(Input)]
    lib.feel_effect_destroy.argtypes = [C.c_void_p]
    lib.feel_close.argtypes = [C.c_void_p]

    def error():
        return lib.feel_last_error_message().decode()

    options = OpenOptions(C.sizeof(OpenOptions), 0, 0, b"kinematic", b"hold:5000")
    dev = lib.feel_open_ex(b"sim:iforce2", C.byref(options))
    if not dev:
        sys.exit("feel_open_ex: " + error())
    k, offset = 6000, 1000
    spring = lib.feel_x_spring(dev, k, k, offset, 10000, 10000, 0)
    if not spring or lib.feel_effect_start(spring, -1, False) != 0:
        sys.exit("spring: " + error())
    state = Input()
    state.size = C.sizeof(Input)
    for i in range(3000):  # until the safety fade-in is complete
        if lib.feel_wait_input(dev, 500, C.byref(state)) != 0:
            sys.exit("feel_wait_input: " + error())
        if state.fade_level >= 1.0 and i > 20:
            break
    x, force = state.position[0], state.force[0]
    expected = -k / 10000.0 * (x - offset)
    print("libfeel %s via ctypes: x = %.0f, force = %.0f, spring law %.0f"
          % (lib.feel_version_string().decode(), x, force, expected))
    lib.feel_effect_destroy(spring)
    lib.feel_close(dev)
    if not (x > 4900 and abs(force - expected) < 30):
        sys.exit("the reported force does not follow the spring law")


if __name__ == "__main__":
    main()
