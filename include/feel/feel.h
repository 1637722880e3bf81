/* feel — the C ABI.
 *
 * A plain C11 interface to the feel host API (feel/host/device.hpp), so that C programs
 * and other languages (through their C FFI) can drive a feel device: open it, read its
 * capabilities, create the I-FORCE 2.0 wrapper effects of the primer's §8 on it, start and
 * stop them, ask their status, set the gain, send device commands, poll the input, stream
 * forces, subscribe to dynamics' reports, and load and play a sensation file in two calls
 * (§9.5).
 *
 *   feel_device* dev = feel_open("sim:iforce2");
 *   if (!dev) { fprintf(stderr, "%s\n", feel_last_error_message()); return 1; }
 *   feel_effect* spring = feel_x_spring(dev, 1000, 1000, 0, 10000, 10000, 0);
 *   if (!spring || feel_effect_start(spring, FEEL_INFINITE_ITERATIONS, false) != FEEL_OK) ...
 *   ...
 *   feel_effect_destroy(spring);
 *   feel_close(dev);
 *
 * Units are the primer's (docs/conventions.md): levels in ±10000 of the device's
 * capability, times in microseconds (FEEL_INFINITE for "INFINITE"), angles in hundredths
 * of a degree 0..35999, compass angles clockwise from north (+y) naming where a force comes
 * FROM.
 *
 * Errors. Every function that can fail returns a feel_error code (FEEL_OK is 0) or, for the
 * functions that make a handle, the handle or NULL. Every call (except feel_last_error,
 * feel_last_error_message, feel_error_name and the version functions) sets the calling
 * thread's last error: the code and a sentence naming what is wrong, e.g.
 *   "feel_set_gain: gain = 12000 is out of range (allowed 0..10000)"
 * and FEEL_OK with an empty message when it succeeds. A NULL handle or out pointer is
 * FEEL_ERROR_INVALID_PARAMETER. No C++ exception ever crosses this interface.
 *
 * Handles. feel_device, feel_effect, feel_library, feel_subscription,
 * feel_input_subscription and feel_queue are opaque. An effect stays valid after its device is closed, but every call on it then
 * returns FEEL_ERROR_INVALID_HANDLE; it must still be destroyed. Destroying a handle twice,
 * or using it after destroying it, is undefined (as free() is).
 *
 * Threads. A device and its effects may be used from one thread at a time. The calls that
 * talk to the device wait for its answer (about 1-2 ms); the feel_queue_* calls never wait
 * (docs/host-api.md, "Which calls may block"). The last error is thread-local. Callbacks
 * run on the device's I/O thread and must not call back into feel for that device (queue
 * the work instead).
 *
 * Structs and growth. Every struct that crosses this interface (except feel_trigger) starts
 * with `uint32_t size`, as DirectInput's dwSize: set it to sizeof the struct before the
 * call, for structs you pass in and structs feel fills alike. A struct zeroed and sized is
 * all defaults:   feel_caps caps;  FEEL_INIT(caps);
 * feel fills or reads only the bytes both sides know, so a program built against older or
 * newer headers keeps working (docs/c-api.md, "ABI evolution").
 *
 * docs/c-api.md has the details; docs/wrappers.md the §8 wrappers' parameters.
 */
#ifndef FEEL_FEEL_H
#define FEEL_FEEL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "feel/version.h"

/* The functions libfeel.so exports; everything else in it is hidden. */
#if defined(__GNUC__) || defined(__clang__)
#define FEEL_API __attribute__((visibility("default")))
#else
#define FEEL_API
#endif

/* Zeroes a struct and sets its size field: the one correct way to prepare any feel struct. */
#define FEEL_INIT(s) (memset(&(s), 0, sizeof(s)), (s).size = (uint32_t)sizeof(s))

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Errors (feel::host::ErrorKind) ------------------------------------------------- */

enum {
    FEEL_OK = 0,
    FEEL_ERROR_INVALID_PARAMETER = 1, /* an argument out of range or inconsistent (named) */
    FEEL_ERROR_DEVICE_FULL = 2,       /* no free effect block, parameter or sample memory */
    FEEL_ERROR_NOT_SUPPORTED = 3,     /* the device cannot play it, the host cannot emulate it */
    FEEL_ERROR_INVALID_HANDLE = 4,    /* the effect was unloaded or its device closed */
    FEEL_ERROR_DISCONNECTED = 5,      /* the device went away */
    FEEL_ERROR_TIMEOUT = 6,           /* the device did not answer in time */
    FEEL_ERROR_PROTOCOL = 7,          /* the device answered something that is not the protocol */
    FEEL_ERROR_INTERNAL = 8           /* an unexpected failure inside feel (e.g. out of memory) */
};

/* The last error of this thread: its code, and its message (never NULL; "" after a
 * success). The message is valid until the thread's next feel call. */
FEEL_API int feel_last_error(void);
FEEL_API const char* feel_last_error_message(void);
/* "ok", "invalid parameter", ... ; "unknown error" for any other value. */
FEEL_API const char* feel_error_name(int code);

/* ---- Version ------------------------------------------------------------------------- */

/* The library's version as FEEL_VERSION numbers it (major * 10000 + minor * 100 + patch),
 * and as text ("0.1.0"). A program can compare feel_version() with the FEEL_VERSION of the
 * headers it was built with. */
FEEL_API uint32_t feel_version(void);
FEEL_API const char* feel_version_string(void);

/* ---- Units and enumerations ---------------------------------------------------------- */

#define FEEL_INFINITE (-1)              /* a duration without end, µs (feel::kInfiniteUs) */
#define FEEL_EFFECT_ITERATIONS 0        /* feel_effect_start: the effect's own iteration count */
#define FEEL_INFINITE_ITERATIONS (-1)   /* feel_effect_start: repeat until stopped */
#define FEEL_MAX_AXES 6

/* Axes, in device order. */
enum { FEEL_AXIS_X = 0, FEEL_AXIS_Y, FEEL_AXIS_Z, FEEL_AXIS_RX, FEEL_AXIS_RY, FEEL_AXIS_RZ };

/* The effect types (§6.4), in feel::EffectType's order; FEEL_TYPE_BIT(t) is t's bit in
 * feel_caps.supported_types. */
enum {
    FEEL_TYPE_SPRING = 0, FEEL_TYPE_DAMPER, FEEL_TYPE_INERTIA, FEEL_TYPE_FRICTION,
    FEEL_TYPE_ANGLE_SPRING, FEEL_TYPE_AXIS_BARRIER, FEEL_TYPE_ANGLE_BARRIER,
    FEEL_TYPE_AXIS_WALL, FEEL_TYPE_ANGLE_WALL, FEEL_TYPE_TEXTURE,
    FEEL_TYPE_VECTOR_FORCE, FEEL_TYPE_CONSTANT, FEEL_TYPE_SMART_POP,
    FEEL_TYPE_SINE, FEEL_TYPE_SQUARE, FEEL_TYPE_TRIANGLE, FEEL_TYPE_SAW_UP, FEEL_TYPE_SAW_DOWN,
    FEEL_TYPE_SWEEP_SINE, FEEL_TYPE_SWEEP_SQUARE, FEEL_TYPE_SWEEP_TRIANGLE,
    FEEL_TYPE_SWEEP_SAW_UP, FEEL_TYPE_SWEEP_SAW_DOWN,
    FEEL_TYPE_FORCE_PROFILE, FEEL_TYPE_RAMP,
    FEEL_TYPE_DYNAMIC_RECOIL, FEEL_TYPE_DYNAMIC_IMPACT, FEEL_TYPE_DYNAMIC_LIQUID,
    FEEL_TYPE_DYNAMIC_INERTIA, FEEL_TYPE_DYNAMIC_CENTER_DRIFT, FEEL_TYPE_DYNAMIC_CONTROL_LAW,
    FEEL_TYPE_DYNAMIC_SLING, FEEL_TYPE_DYNAMIC_PADDLE,
    FEEL_TYPE_COUNT
};
#define FEEL_TYPE_BIT(type) (UINT64_C(1) << (type))

/* §8.3 WaveForm (feel::Waveform). */
enum { FEEL_WAVEFORM_SINE = 0, FEEL_WAVEFORM_SQUARE, FEEL_WAVEFORM_TRIANGLE, FEEL_WAVEFORM_SAW_UP,
       FEEL_WAVEFORM_SAW_DOWN };
/* §8.2 a wall's Sense (feel::WallSense): positive resists crossing while moving toward +. */
enum { FEEL_WALL_SENSE_POSITIVE = 0, FEEL_WALL_SENSE_NEGATIVE };
/* §8.3 a sweep's Sense (feel::SweepSense). */
enum { FEEL_SWEEP_CLOCKWISE = 0, FEEL_SWEEP_COUNTERCLOCKWISE };

/* §8.3 Trigger: the button or hat switch that plays the effect as a reflex (§1.2.c). */
enum { FEEL_TRIGGER_NONE = 0, FEEL_TRIGGER_BUTTON, FEEL_TRIGGER_HAT };
typedef struct feel_trigger {
    int32_t kind;  /* FEEL_TRIGGER_NONE, _BUTTON or _HAT */
    int32_t index; /* button 1..32 or hat 1..4; 0 for none */
} feel_trigger;
static inline feel_trigger feel_no_trigger(void) { feel_trigger t = {FEEL_TRIGGER_NONE, 0}; return t; }
static inline feel_trigger feel_button_trigger(int32_t button) { feel_trigger t = {FEEL_TRIGGER_BUTTON, button}; return t; }
static inline feel_trigger feel_hat_trigger(int32_t hat) { feel_trigger t = {FEEL_TRIGGER_HAT, hat}; return t; }

/* The generation of a device's local processor (§2.2): the same numbers as the C++
 * feel::sim::DeviceClass and the wire's Device Info report. */
enum { FEEL_DEVICE_CLASS_IFORCE1 = 1, /* Conditions and Waves, no Dynamics, reflexes emulated by the host */
       FEEL_DEVICE_CLASS_IFORCE2 = 2  /* the whole master set of §6.4, local reflexes */ };

/* ---- Devices --------------------------------------------------------------------------- */

typedef struct feel_device feel_device;
typedef struct feel_effect feel_effect;
typedef struct feel_library feel_library;
typedef struct feel_subscription feel_subscription;

/* EnumDevices (§7.3): the devices a host could open, in-process simulated devices first
 * (one per profile), then the devices listening on Unix sockets in the socket directory. */
typedef struct feel_device_info {
    uint32_t size;             /* sizeof(feel_device_info), set by feel */
    char address[256];         /* what feel_open takes: "sim:iforce2", "unix:/run/user/1000/feel/sim.sock" */
    char device[32];           /* the profile name, e.g. "iforce2" */
    char description[256];     /* one line about the hardware */
    char class_name[32];       /* "I-FORCE 1.x", "I-FORCE 2.0" */
    bool in_process;           /* a simulated device this process would run itself */
} feel_device_info;
/* Return true to go on, false to stop the enumeration. */
typedef bool (*feel_device_callback)(const feel_device_info* info, void* user_data);
typedef struct feel_enumerate_options {
    uint32_t size;             /* sizeof(feel_enumerate_options), set by the caller */
    bool skip_in_process;      /* do not list the in-process simulated devices */
    const char* socket_dir;    /* the directory whose sockets are probed; NULL: the default
                                  ($XDG_RUNTIME_DIR/feel or /tmp/feel-UID) */
    int32_t timeout_ms;        /* per socket probed, 1..60000; 0: 300 */
} feel_enumerate_options;
/* Calls callback(info, user_data) for each device, on the calling thread; options may be
 * NULL (defaults). Sockets that do not answer are skipped. */
FEEL_API int feel_enumerate_devices(const feel_enumerate_options* options, feel_device_callback callback,
                           void* user_data);

/* Opens "sim:PROFILE" (an in-process simulated device, e.g. "sim:iforce2"),
 * "unix:PATH" or "tcp:HOST:PORT"; NULL or "" means "sim:iforce2". NULL on failure. */
FEEL_API feel_device* feel_open(const char* address);
/* feel_open with options (feel::host::OpenOptions). A zero field takes its default. */
typedef struct feel_open_options {
    uint32_t size;      /* sizeof(feel_open_options), set by the caller */
    int32_t timeout_ms;      /* per command round trip, 1..60000; 0: 2000 */
    int32_t report_rate_hz;  /* state reports per second, 100..1000; 0: the device's */
    /* sim: addresses only: the simulated hand ("none", "loose", "firm", "stiff",
     * "kinematic"; NULL: "firm") and its target motion (as `feel render --motion`, e.g.
     * "hold:0", "sine:x:5000:1", "circle:3000:0.5"; NULL: "hold:0"). */
    const char* sim_hand;
    const char* sim_motion;
} feel_open_options;
FEEL_API feel_device* feel_open_ex(const char* address, const feel_open_options* options);
/* Frees every effect of this host on the device and closes it; NULL is ignored. Effects
 * made from it return FEEL_ERROR_INVALID_HANDLE afterwards. */
FEEL_API void feel_close(feel_device* device);

typedef struct feel_axis_caps {
    int32_t axis;          /* FEEL_AXIS_* */
    bool rotary;           /* linear: m and N; rotary: rad and N·m */
    double half_travel;    /* m or rad at position ±10000 */
    double max_force;      /* N or N·m at force ±10000 */
    int32_t sensor_counts; /* sensor resolution over the whole travel */
} feel_axis_caps;

/* GetCapabilities (§7.4). Strings are NUL-terminated, truncated to fit. */
typedef struct feel_caps {
    uint32_t size;   /* sizeof(feel_caps), set by the caller */
    char device[32];            /* profile name, e.g. "iforce2" */
    char description[256];
    char class_name[32];        /* "I-FORCE 1.x", "I-FORCE 2.0" */
    char firmware_version[32];
    char protocol_version[32];
    int32_t device_class;       /* FEEL_DEVICE_CLASS_IFORCE1 or _IFORCE2 */
    int32_t axis_count;         /* 1..6: axes[0..axis_count) are x, y, z, rx, ry, rz */
    feel_axis_caps axes[FEEL_MAX_AXES];
    int32_t button_count;       /* 0..32 */
    int32_t hat_count;          /* 0..4 */
    bool dead_man_switch;
    int32_t max_force;          /* normalized force at each axis's max_force */
    uint64_t supported_types;   /* FEEL_TYPE_BIT(t) for each type the device plays itself */
    int32_t effect_slots;
    int32_t pool_bytes;
    int32_t sample_memory;      /* force-profile samples */
    bool local_reflexes;        /* false: the host emulates trigger reflexes (§1.2.c) */
    bool interim_reports;
    int32_t loop_rate_hz;
    int32_t max_loop_rate_hz;
    double interim_report_hz;
    int32_t report_rate_hz;     /* state reports per second now */
} feel_caps;
FEEL_API int feel_device_caps(const feel_device* device, feel_caps* out);

/* EnumEffects (§6.2): FEEL_TYPE_BIT(t) for each type that can be created on this device,
 * played by the device itself or emulated by the host (a superset of caps.supported_types). */
FEEL_API int feel_device_effect_types(const feel_device* device, uint64_t* types);

/* The device's parameter and sample memory (§2.2). */
typedef struct feel_pool_info {
    uint32_t size;             /* sizeof(feel_pool_info), set by the caller */
    int32_t total_bytes;       /* parameter memory, bytes */
    int32_t free_bytes;
    int32_t max_effects;       /* effect slots */
    int32_t free_effects;
    int32_t total_samples;     /* force-profile sample memory, samples */
    int32_t free_samples;
} feel_pool_info;
FEEL_API int feel_device_pool(feel_device* device, feel_pool_info* out);

/* The device's address as opened ("sim:iforce2"), NUL-terminated, truncated to capacity. */
FEEL_API int feel_device_address(const feel_device* device, char* out, int32_t capacity);
/* false once the device went away or was closed. */
FEEL_API bool feel_device_connected(const feel_device* device);
/* Input disturbance filtering (IDF, §1.2.d) of the reported position, per class of effect:
 * periodic (vibrations) and impulse (jolts). */
FEEL_API int feel_set_idf(feel_device* device, bool periodic, bool impulse);
/* State reports per second: 100..min(1000, the device's loop rate). */
FEEL_API int feel_set_report_rate(feel_device* device, int32_t hz);

/* DIPROP_FFGAIN: the device's overall gain, 0..10000. */
FEEL_API int feel_set_gain(feel_device* device, int32_t gain);

/* SendForceFeedbackCommand (DISFFC_*). */
enum {
    FEEL_COMMAND_ACTUATORS_ON = 0, /* forces pass again, faded in */
    FEEL_COMMAND_ACTUATORS_OFF,    /* no force; effects play on */
    FEEL_COMMAND_STOP_ALL,         /* stop every effect; they stay resident */
    FEEL_COMMAND_RESET,            /* free every effect and reflex, gain 10000 */
    FEEL_COMMAND_PAUSE,            /* every effect clock stands still, no force */
    FEEL_COMMAND_RESUME
};
FEEL_API int feel_device_command(feel_device* device, int32_t command);

/* The device's latest input state, from its input reports (no round trip). */
typedef struct feel_input {
    uint32_t size;  /* sizeof(feel_input), set by the caller */
    int64_t t_us;                     /* device time of the newest report, µs */
    int32_t axis_count;
    float position[FEEL_MAX_AXES];    /* reported position, ±10000 of the travel */
    float velocity[FEEL_MAX_AXES];    /* handle velocity, position units/s */
    float force[FEEL_MAX_AXES];       /* what the motors got, ±10000 */
    uint32_t buttons;                 /* bit i = button i+1 pressed */
    uint32_t hats;                    /* bit h-1 = hat h off center */
    bool handle_held;                 /* the dead-man switch */
    bool hands_off;                   /* the device detected a free handle and faded out */
    bool host_lost;                   /* the device's host watchdog tripped */
    float fade_level;                 /* safety fade, 0..1 */
    bool paused;
    bool actuators_enabled;
    int32_t gain;                     /* 0..10000 */
    int32_t playing_effects;
    int32_t resident_effects;
    int32_t loop_rate_hz;
    double measured_loop_hz;
    uint64_t overruns;
    uint64_t dropped_reports;
    uint64_t reports_received;        /* input reports this host has read */
} feel_input;
FEEL_API int feel_poll_input(feel_device* device, feel_input* out);
/* Waits up to timeout_ms (1..60000) for a state report newer than the current one. */
FEEL_API int feel_wait_input(feel_device* device, int32_t timeout_ms, feel_input* out);

/* Every state report the device sends, in order (Device::subscribe_input): the device's I/O
 * thread appends each to this subscription's queue, `capacity` reports (1..1000000) allocated
 * here; when the queue is full the oldest go and are counted, and the I/O thread never waits
 * for the reader. Where feel_wait_input gives the newest state and skips the reports a slow
 * reader missed, this gives all of them (a plot, a recorder). NULL on failure. */
typedef struct feel_input_subscription feel_input_subscription;
FEEL_API feel_input_subscription* feel_subscribe_input(feel_device* device, uint32_t capacity);
/* Waits up to timeout_ms (0..60000; 0 never blocks) until at least one report is queued, then
 * copies up to max_reports of them, oldest first, into reports[0..max_reports) (an array of
 * feel_input; set reports[0].size to sizeof(feel_input): it is the array's stride, and every
 * element is filled as feel_poll_input fills one). *count says how many were copied; the
 * rest stay queued for the next call. *dropped (may be NULL) says how many reports were lost
 * to a full queue since the previous call. FEEL_ERROR_TIMEOUT when none came in time,
 * FEEL_ERROR_DISCONNECTED when none is queued and the device is gone. */
FEEL_API int feel_input_subscription_wait(feel_input_subscription* subscription, int32_t timeout_ms,
                                          feel_input* reports, int32_t max_reports, int32_t* count,
                                          uint64_t* dropped);
/* Ends the subscription and frees the handle; NULL ignored. */
FEEL_API void feel_unsubscribe_input(feel_input_subscription* subscription);

/* Force streaming (§2.4): one sample of the host's force per device axis, ±10000,
 * physical sign (+ pushes toward +axis), up to 1 kHz. axis_count must equal the device's. */
FEEL_API int feel_stream_force(feel_device* device, const int32_t* force, int32_t axis_count);

/* ---- Effects ----------------------------------------------------------------------------- */

/* Unloads the effect from its device (if still there) and frees the handle; NULL ignored. */
FEEL_API void feel_effect_destroy(feel_effect* effect);
/* Start (iterations: FEEL_EFFECT_ITERATIONS, 1..255 or FEEL_INFINITE_ITERATIONS; solo:
 * stop every other effect first, DIES_SOLO) and Stop. */
FEEL_API int feel_effect_start(feel_effect* effect, int32_t iterations, bool solo);
FEEL_API int feel_effect_stop(feel_effect* effect);

enum { FEEL_STATE_STOPPED = 0, FEEL_STATE_PLAYING, FEEL_STATE_DELAYED, FEEL_STATE_EMULATED };
enum { FEEL_END_NONE = 0, FEEL_END_STOPPED, FEEL_END_FINISHED };
typedef struct feel_effect_status_info {
    uint32_t size;  /* sizeof(feel_effect_status_info), set by the caller */
    int32_t state;                /* FEEL_STATE_* */
    bool emulated;                /* the host plays (part of) it for the device (§1.2.c) */
    int32_t iterations;           /* of the current or last play; FEEL_INFINITE_ITERATIONS */
    int32_t completed_iterations;
    int64_t elapsed_us;
    int32_t last_end;             /* FEEL_END_*: how the last play ended */
} feel_effect_status_info;
FEEL_API int feel_effect_status(feel_effect* effect, feel_effect_status_info* out);

/* ---- Effects from a parameter struct (CreateEffect with a DIEFFECT, §6.3, §6.6) --------- *
 * feel_effect_params is the C form of feel::EffectParams (include/feel/effect.hpp, whose
 * comments give every field's unit and range): the Effect Structure and its type-specific
 * blocks; only the blocks of `type` are read. Fill it with feel_effect_params_init (the
 * C++ defaults: infinite duration, gain 10000, one iteration, full saturations, ...), then
 * set what the effect needs. Enumerations are int32_t: FEEL_TYPE_*, FEEL_DIRECTION_*,
 * FEEL_OFFSET_*, FEEL_WALL_SENSE_*, FEEL_SWEEP_*, FEEL_AXIS_*, FEEL_TRIGGER_*. */

/* §6.5: where a directional force comes FROM. value[]: polar {compass angle 0..35999};
 * cartesian and moments {a vector, ±10000 per axis}; spherical {angle in XY from +x,
 * angle away from +z}, hundredths of a degree; none: the single axis's own sign. */
enum { FEEL_DIRECTION_NONE = 0, FEEL_DIRECTION_POLAR, FEEL_DIRECTION_CARTESIAN,
       FEEL_DIRECTION_SPHERICAL, FEEL_DIRECTION_MOMENTS };
/* Where an offset is measured from: the axis origin or the handle at the effect's start. */
enum { FEEL_OFFSET_ABSOLUTE = 0, FEEL_OFFSET_RELATIVE };

typedef struct feel_direction { int32_t kind; int32_t value[3]; } feel_direction;
typedef struct feel_envelope {  /* §4.2.a */
    int32_t impulse_level;    /* 0..10000 */
    int64_t settle_time_us;   /* 0..65e6 */
    int32_t fade_level;       /* 0..10000 */
    int64_t fade_time_us;     /* 0..65e6 */
} feel_envelope;
typedef struct feel_condition_block {  /* §6.6.a, one per axis */
    int32_t pos_coefficient, neg_coefficient;  /* -10000..10000 */
    int32_t offset;                            /* -10000..10000 */
    int32_t pos_saturation, neg_saturation;    /* 0..10000 */
    int32_t deadband;                          /* 0..10000 */
    int32_t offset_mode;                       /* FEEL_OFFSET_* */
} feel_condition_block;
typedef struct feel_periodic_block {  /* §6.6.b, §6.6.i */
    int32_t magnitude;          /* 0..10000 (sweeps ±10000) */
    int32_t offset;             /* -10000..10000 */
    int64_t period_us;          /* 1..65e6 */
    int32_t phase;              /* 0..35999 */
    int32_t sweep_start_angle, sweep_end_angle;  /* 0..35999, sweeps only */
    int32_t sweep_sense;        /* FEEL_SWEEP_*, sweeps only */
} feel_periodic_block;
typedef struct feel_custom_block {    /* §6.6.d; the samples are passed beside the params */
    int32_t channels;           /* 1..6 */
    int64_t sample_period_us;   /* 1..65e6 */
    int32_t sample_count;       /* 1..65535, a multiple of channels */
} feel_custom_block;
typedef struct feel_texture_block { int32_t pos_roughness, neg_roughness, spacing, density; } feel_texture_block;  /* §6.6.j, 1..10000 each */
typedef struct feel_wall_block {      /* §6.6.h */
    int32_t hardness;           /* -10000..10000 */
    int32_t sense;              /* FEEL_WALL_SENSE_* */
    int32_t offset;             /* -10000..10000 */
    int32_t offset_mode;        /* FEEL_OFFSET_* */
    int32_t angle;              /* 0..35999, angle_wall only */
    int32_t surface_friction, surface_texture;  /* 0..10000 */
    bool clipping;
} feel_wall_block;
typedef struct feel_barrier_block {   /* §6.6.g */
    int32_t pos_hardness, neg_hardness;  /* -10000..10000 */
    int32_t thickness;          /* 1..10000 */
    int32_t offset;             /* -10000..10000 */
    int32_t angle;              /* 0..35999, angle_barrier only */
    int32_t surface_friction, surface_texture;  /* 0..10000 */
} feel_barrier_block;
typedef struct feel_control_law_block {  /* §8.4 DynamicControlLaw, one per axis */
    int32_t mass, k_pos, k_neg;    /* 1..10000 */
    int32_t b;                     /* 0..10000 */
    int32_t vel_init, pos_init;    /* -10000..10000 */
    int32_t half_cycles, length, drag;  /* 0..10000 */
    int32_t gravity;               /* -10000..10000 */
} feel_control_law_block;
typedef struct feel_dynamic_block {   /* §8.4: only the fields of the effect's type are read */
    int32_t blast_direction, blast_intensity, blast_resonance, blast_decay;  /* recoil */
    int32_t dynamic_mass;                                                     /* recoil, impact */
    int32_t impact_direction, impact_intensity, elasticity, collision_absorption;  /* impact */
    int32_t density, settle, viscosity;                                       /* liquid */
    int32_t inertia, play;                                                    /* inertia */
    int32_t stiffness, drift_resistance;                                      /* center drift */
    int32_t ball_mass;                                                        /* sling, paddle */
    int32_t string_length, string_compliance, ball_damping;                   /* sling */
    int32_t initial_velocity, initial_velocity_direction, paddle_compliance,
            paddle_damping, gravity;                                          /* paddle */
    feel_control_law_block control_law[FEEL_MAX_AXES];                              /* control law */
    bool interim_reporting;                                                   /* all dynamics */
} feel_dynamic_block;

typedef struct feel_effect_params {
    uint32_t size;                 /* sizeof(feel_effect_params), set by the caller */
    int32_t type;                  /* FEEL_TYPE_* */
    int64_t duration_us;           /* 1..65e6 or FEEL_INFINITE */
    int64_t start_delay_us;        /* 0..65e6 */
    int32_t gain;                  /* 0..10000 */
    int32_t iterations;            /* 1..255 or FEEL_INFINITE_ITERATIONS */
    int32_t axis_count;            /* 1..6 */
    int32_t axes[FEEL_MAX_AXES];   /* FEEL_AXIS_*, the effect's axes in its order */
    feel_direction direction;
    feel_trigger trigger;
    int64_t trigger_repeat_interval_us;  /* 0 = no repeat, else 1..65e6 */
    bool has_envelope;
    feel_envelope envelope;
    feel_condition_block conditions[FEEL_MAX_AXES];  /* spring, damper, inertia, friction, angle_spring */
    feel_periodic_block periodic;        /* sine .. saw_down, sweeps */
    int32_t constant_magnitude;    /* constant, vector_force, smart_pop: -10000..10000 */
    int32_t ramp_start, ramp_end;  /* ramp: -10000..10000 */
    feel_custom_block custom;            /* force_profile */
    feel_texture_block texture;
    feel_wall_block wall;                /* axis_wall, angle_wall */
    feel_barrier_block barrier;          /* axis_barrier, angle_barrier */
    feel_dynamic_block dynamic;          /* dynamic_* */
    /* Grown at the end (docs/c-api.md, "ABI evolution"; it sits in what was the struct's tail
     * padding, so sizeof is unchanged and a zeroed struct means "absolute", as before). */
    int32_t barrier_offset_mode;   /* FEEL_OFFSET_*, axis_barrier and angle_barrier (§3.8) */
} feel_effect_params;

/* Fills *params (params->size must be set) with the defaults of an effect of `type`. */
FEEL_API int feel_effect_params_init(feel_effect_params* params, int32_t type);
/* CreateEffect + Download. A force profile passes its samples (sample_count =
 * params->custom.sample_count, interleaved by channel, ±10000); other types NULL, 0. The
 * host checks everything first: FEEL_ERROR_INVALID_PARAMETER names the field and range
 * ("conditions[0].deadband = 12000 is out of range (allowed 0..10000)"). NULL on failure. */
FEEL_API feel_effect* feel_create_effect(feel_device* device, const feel_effect_params* params,
                                const int16_t* samples, int32_t sample_count);
/* The effect's current parameters. */
FEEL_API int feel_effect_get_parameters(const feel_effect* effect, feel_effect_params* out);

/* SetParameters (§7.6): field_mask names the fields to change (FEEL_FIELD_*; the rest of
 * params is ignored); with restart the effect (re)starts from its beginning (DIEP_START),
 * without it a playing effect plays on with the new values, a stopped one stays stopped.
 * On any error nothing changes. A force profile's new samples come with
 * FEEL_FIELD_TYPE_SPECIFIC (else NULL, 0). The type cannot change. */
enum {
    FEEL_FIELD_DURATION = 1 << 0,       /* duration_us */
    FEEL_FIELD_START_DELAY = 1 << 1,    /* start_delay_us */
    FEEL_FIELD_GAIN = 1 << 2,           /* gain */
    FEEL_FIELD_ITERATIONS = 1 << 3,     /* iterations */
    FEEL_FIELD_AXES = 1 << 4,           /* axis_count and axes */
    FEEL_FIELD_DIRECTION = 1 << 5,      /* direction */
    FEEL_FIELD_TRIGGER = 1 << 6,        /* trigger */
    FEEL_FIELD_TRIGGER_REPEAT = 1 << 7, /* trigger_repeat_interval_us */
    FEEL_FIELD_ENVELOPE = 1 << 8,       /* has_envelope and envelope */
    FEEL_FIELD_TYPE_SPECIFIC = 1 << 9,  /* the blocks of the effect's type */
    FEEL_FIELD_ALL = (1 << 10) - 1
};
FEEL_API int feel_effect_set_parameters(feel_effect* effect, const feel_effect_params* params, uint32_t field_mask,
                               bool restart, const int16_t* samples, int32_t sample_count);
/* Download again after feel_effect_unload; Unload frees the device's block but keeps the
 * parameters (the handle stays valid). */
FEEL_API int feel_effect_download(feel_effect* effect);
FEEL_API int feel_effect_unload(feel_effect* effect);

/* ---- Calls that never stall a frame (feel::host::CommandQueue) ------------------------ *
 * Every call above waits for the device's answer (about 1 ms for a start, 2 ms for
 * set_parameters; docs/host-api.md, "Which calls may block"). A queue's calls check what
 * needs no device, queue the command and return at once with a ticket (1, 2, 3, ...), or 0
 * when refused at once (the last error says why: NULL or empty handles, a value out of
 * range, FEEL_ERROR_DEVICE_FULL when max_pending commands already wait). One worker thread
 * runs the commands in order; each one's outcome comes back on the caller's thread at its
 * next feel_queue_poll. A burst of set_parameters to one effect coalesces to the newest
 * (the masks merged), as do set_gain and stream_force; each coalesced call still gets an
 * outcome, with `coalesced` set and `into` naming the ticket that carried it. Use one queue
 * per device, from one thread at a time. */
typedef struct feel_queue feel_queue;
typedef struct feel_outcome {
    uint32_t size;             /* sizeof(feel_outcome), set by feel */
    uint64_t ticket;
    const char* what;          /* "start", "stop", "set_parameters", "set_gain", "command", "stream_force" */
    int32_t code;              /* FEEL_OK or FEEL_ERROR_* */
    const char* message;       /* "" on success; valid during the callback only */
    bool coalesced;            /* carried by a later call of the same kind */
    uint64_t into;             /* the ticket that carried it; == ticket when not coalesced */
} feel_outcome;
typedef void (*feel_outcome_callback)(const feel_outcome* outcome, void* user_data);
/* max_pending 1..65536 commands waiting (0: 1024), max_outcomes 1..1048576 outcomes
 * waiting for a poll (0: 4096; older ones are dropped). NULL on failure. */
FEEL_API feel_queue* feel_queue_create(feel_device* device, int32_t max_pending, int32_t max_outcomes);
/* Runs the commands already queued (each bounded by the device's timeout), then frees the
 * queue; outcomes not polled are dropped. NULL is ignored. */
FEEL_API void feel_queue_destroy(feel_queue* queue);
FEEL_API uint64_t feel_queue_start(feel_queue* queue, feel_effect* effect, int32_t iterations, bool solo);
FEEL_API uint64_t feel_queue_stop(feel_queue* queue, feel_effect* effect);
FEEL_API uint64_t feel_queue_set_parameters(feel_queue* queue, feel_effect* effect, const feel_effect_params* params,
                                   uint32_t field_mask, bool restart, const int16_t* samples, int32_t sample_count);
FEEL_API uint64_t feel_queue_set_gain(feel_queue* queue, int32_t gain);
FEEL_API uint64_t feel_queue_command(feel_queue* queue, int32_t command);
FEEL_API uint64_t feel_queue_stream_force(feel_queue* queue, const int32_t* force, int32_t axis_count);
/* Calls callback(outcome, user_data) on this thread for each command finished since the
 * last poll, in the order they finished; returns how many (never waits). */
FEEL_API int32_t feel_queue_poll(feel_queue* queue, feel_outcome_callback callback, void* user_data);
/* Waits until nothing is queued or running, up to timeout_ms (1..60000): FEEL_ERROR_TIMEOUT
 * if commands remain. */
FEEL_API int feel_queue_flush(feel_queue* queue, int32_t timeout_ms);
/* Commands queued or running. */
FEEL_API int32_t feel_queue_pending(const feel_queue* queue);

/* ---- Dynamic reports (§5.2) ---------------------------------------------------------- */

enum { FEEL_REPORT_INTERIM = 0, FEEL_REPORT_FINAL };
typedef struct feel_dynamic_event {
    uint32_t size;  /* sizeof(feel_dynamic_event), set by feel */
    int32_t kind;                           /* FEEL_REPORT_INTERIM or FEEL_REPORT_FINAL */
    int64_t t_us;                           /* device time */
    int32_t axis_count;                     /* the effect's axes, in its order */
    float position[FEEL_MAX_AXES];          /* mass minus handle, position units */
    float velocity[FEEL_MAX_AXES];          /* mass minus handle, position units/s */
    float handle_velocity[FEEL_MAX_AXES];   /* the handle's, position units/s */
} feel_dynamic_event;
typedef void (*feel_dynamic_callback)(const feel_dynamic_event* event, void* user_data);

/* Calls callback(event, user_data) for this effect's interim and final reports (or every
 * effect's, for a device), on the device's I/O thread, until feel_unsubscribe. NULL on
 * failure. */
FEEL_API feel_subscription* feel_effect_subscribe(feel_effect* effect, feel_dynamic_callback callback, void* user_data);
FEEL_API feel_subscription* feel_device_subscribe(feel_device* device, feel_dynamic_callback callback, void* user_data);
/* Stops the calls (none is in progress when it returns) and frees the handle; NULL ignored. */
FEEL_API void feel_unsubscribe(feel_subscription* subscription);

/* ---- Load and play in two calls (§9.5) ----------------------------------------------- */

/* Call 1: opens the device at `address` (NULL or "": "sim:iforce2"), creates and downloads
 * every effect of every sensation in the file, and arms its button assignments as
 * reflexes. NULL on failure (the message names the file, sensation, field and range). */
FEEL_API feel_library* feel_library_load(const char* path, const char* address);
/* Call 2: starts every effect of the named sensation. */
FEEL_API int feel_library_play(feel_library* library, const char* name);
FEEL_API int feel_library_stop(feel_library* library, const char* name);
/* The library's device, owned by the library (do not feel_close it): to poll its input,
 * set its gain, ... NULL if library is NULL. */
FEEL_API feel_device* feel_library_device(feel_library* library);
/* Call 1 on a device already open (which the library then shares; feel_close it after
 * feel_library_free): loads only the sensations named in names[0..count) (count 0: all),
 * e.g. to fit a device too small for the whole file. */
FEEL_API feel_library* feel_library_load_on(const char* path, feel_device* device, const char* const* names,
                                   int32_t count);
/* Call 2 with an iteration count (as feel_effect_start), and stop every sensation. */
FEEL_API int feel_library_play_ex(feel_library* library, const char* name, int32_t iterations);
FEEL_API int feel_library_stop_all(feel_library* library);
/* The file's sensations: how many, and the name of the index-th (0..count-1), owned by the
 * library; NULL for an index out of range. */
FEEL_API int32_t feel_library_sensation_count(const feel_library* library);
FEEL_API const char* feel_library_sensation_name(const feel_library* library, int32_t index);
/* The effects of a sensation, in file order, so that a game can alter a designed sensation
 * before playing it (§9.5): how many (0 with an error for an unknown name) and the
 * index-th, owned by the library (do not feel_effect_destroy it). */
FEEL_API int32_t feel_library_effect_count(feel_library* library, const char* name);
FEEL_API feel_effect* feel_library_effect(feel_library* library, const char* name, int32_t index);
/* Frees every effect of the library and closes its device; NULL is ignored. */
FEEL_API void feel_library_free(feel_library* library);

/* ---- The I-FORCE 2.0 wrapper functions (§8) ------------------------------------------- *
 * Each builds the effect of feel::iforce::<name> (docs/wrappers.md), creates it on the
 * device and downloads it, and returns it stopped (start it with feel_effect_start); NULL
 * on failure: FEEL_ERROR_INVALID_PARAMETER names the wrapper, the parameter and its range
 * ("x_spring: deadband = 12000 is out of range (allowed 0..10000)"); the device's refusals
 * (not supported, full) as their codes. */

/* §8.2 conditions */
FEEL_API feel_effect* feel_x_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
FEEL_API feel_effect* feel_y_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
FEEL_API feel_effect* feel_spring(feel_device* device, int32_t x_k_pos, int32_t x_k_neg, int32_t x_offset,
                         int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                         int32_t y_k_pos, int32_t y_k_neg, int32_t y_offset, int32_t y_pos_saturation,
                         int32_t y_neg_saturation, int32_t y_deadband);
FEEL_API feel_effect* feel_angle_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                               int32_t pos_saturation, int32_t neg_saturation, int32_t deadband,
                               int32_t angle);
FEEL_API feel_effect* feel_center_spring(feel_device* device, int32_t k, int32_t saturation, int32_t deadband);
FEEL_API feel_effect* feel_spring_at_current_location(feel_device* device, int32_t k, int32_t saturation,
                                             int32_t deadband);
FEEL_API feel_effect* feel_x_damper(feel_device* device, int32_t b_pos, int32_t b_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
FEEL_API feel_effect* feel_y_damper(feel_device* device, int32_t b_pos, int32_t b_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
FEEL_API feel_effect* feel_damper(feel_device* device, int32_t x_b_pos, int32_t x_b_neg, int32_t x_offset,
                         int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                         int32_t y_b_pos, int32_t y_b_neg, int32_t y_offset, int32_t y_pos_saturation,
                         int32_t y_neg_saturation, int32_t y_deadband);
FEEL_API feel_effect* feel_x_inertia(feel_device* device, int32_t mass, int32_t saturation);
FEEL_API feel_effect* feel_y_inertia(feel_device* device, int32_t mass, int32_t saturation);
FEEL_API feel_effect* feel_inertia(feel_device* device, int32_t mass, int32_t saturation);
FEEL_API feel_effect* feel_friction(feel_device* device, int32_t f);
FEEL_API feel_effect* feel_x_friction(feel_device* device, int32_t f_pos, int32_t f_neg);
FEEL_API feel_effect* feel_y_friction(feel_device* device, int32_t f_pos, int32_t f_neg);
FEEL_API feel_effect* feel_texture(feel_device* device, int32_t roughness, int32_t spacing, int32_t density,
                          int32_t angle);
/* XTexture(Roughness, Spacing, Density) and XTexture(PosRoughness, NegRoughness, Spacing,
 * Density): C has no overloads, so the second is feel_x_texture_pos_neg. */
FEEL_API feel_effect* feel_x_texture(feel_device* device, int32_t roughness, int32_t spacing, int32_t density);
FEEL_API feel_effect* feel_x_texture_pos_neg(feel_device* device, int32_t pos_roughness, int32_t neg_roughness,
                                    int32_t spacing, int32_t density);
FEEL_API feel_effect* feel_y_texture(feel_device* device, int32_t pos_roughness, int32_t neg_roughness,
                            int32_t spacing, int32_t density);
FEEL_API feel_effect* feel_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset, int32_t angle);
/* Horizontal: the line y = offset, felt along y; vertical: x = offset, felt along x. */
FEEL_API feel_effect* feel_horizontal_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset,
                                  int32_t surface_friction, int32_t surface_texture, bool clipping);
FEEL_API feel_effect* feel_vertical_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset,
                                int32_t surface_friction, int32_t surface_texture, bool clipping);
FEEL_API feel_effect* feel_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                          int32_t thickness, int32_t offset, int32_t angle);
FEEL_API feel_effect* feel_horizontal_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                                     int32_t thickness, int32_t offset, int32_t surface_friction,
                                     int32_t surface_texture);
FEEL_API feel_effect* feel_vertical_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                                   int32_t thickness, int32_t offset, int32_t surface_friction,
                                   int32_t surface_texture);

/* §8.3 waves */
FEEL_API feel_effect* feel_vector_force(feel_device* device, int32_t magnitude, int64_t duration_us,
                               int32_t direction);
FEEL_API feel_effect* feel_constant_force(feel_device* device, int32_t magnitude, int64_t duration_us,
                                 int32_t direction);
FEEL_API feel_effect* feel_constant_force_trigger(feel_device* device, int32_t magnitude, int64_t duration_us,
                                         int32_t direction, feel_trigger trigger,
                                         int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_envelope_constant(feel_device* device, int32_t magnitude, int64_t duration_us,
                                    int32_t direction, int32_t impulse_level, int64_t settle_time_us,
                                    int32_t fade_level, int64_t fade_time_us, feel_trigger trigger,
                                    int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_ramp(feel_device* device, int32_t start, int32_t end, int64_t duration_us,
                       int32_t direction, feel_trigger trigger, int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_ramp_envelope(feel_device* device, int32_t start, int32_t end, int64_t duration_us,
                                int32_t direction, int32_t impulse_level, int64_t settle_time_us,
                                int32_t fade_level, int64_t fade_time_us, feel_trigger trigger,
                                int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_periodic(feel_device* device, int32_t waveform, int32_t magnitude, int32_t offset,
                           int32_t phase, int64_t period_us, int64_t duration_us, int32_t angle,
                           feel_trigger trigger, int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_envelope_periodic(feel_device* device, int32_t waveform, int32_t magnitude,
                                    int32_t offset, int32_t phase, int64_t period_us,
                                    int64_t duration_us, int32_t angle, int32_t impulse_level,
                                    int64_t settle_time_us, int32_t fade_level, int64_t fade_time_us,
                                    feel_trigger trigger, int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_delayed_periodic(feel_device* device, int64_t pause_us, int32_t waveform,
                                   int32_t magnitude, int32_t offset, int32_t phase, int64_t period_us,
                                   int64_t duration_us, int32_t angle, feel_trigger trigger,
                                   int64_t trigger_repeat_interval_us);
FEEL_API feel_effect* feel_sweep_periodic(feel_device* device, int32_t start_angle, int32_t stop_angle,
                                 int32_t sense, int32_t waveform, int32_t magnitude, int32_t offset,
                                 int64_t period_us, int32_t phase, int64_t duration_us);

/* §8.4 dynamics */
FEEL_API feel_effect* feel_dynamic_recoil(feel_device* device, int32_t blast_direction, int32_t blast_intensity,
                                 int32_t dynamic_mass, int32_t blast_resonance, int32_t blast_decay);
FEEL_API feel_effect* feel_dynamic_impact(feel_device* device, int32_t impact_direction, int32_t impact_intensity,
                                 int32_t dynamic_mass, int32_t elasticity, int32_t collision_absorption);
FEEL_API feel_effect* feel_dynamic_liquid(feel_device* device, int32_t density, int32_t settle, int32_t viscosity);
FEEL_API feel_effect* feel_dynamic_inertia(feel_device* device, int32_t inertia, int32_t play);
FEEL_API feel_effect* feel_dynamic_center_drift(feel_device* device, int32_t stiffness, int32_t drift_resistance);
FEEL_API feel_effect* feel_dynamic_sling(feel_device* device, int32_t ball_mass, int32_t string_length,
                                int32_t string_compliance, int32_t ball_damping, bool interim_reporting);
FEEL_API feel_effect* feel_dynamic_paddle(feel_device* device, int32_t ball_mass, int32_t initial_velocity,
                                 int32_t initial_velocity_direction, int32_t paddle_compliance,
                                 int32_t paddle_damping, int32_t gravity, bool interim_reporting);
/* axis: FEEL_AXIS_* the law plays on (§8.4: "a single axis"). */
FEEL_API feel_effect* feel_dynamic_control_law(feel_device* device, int32_t mass, int32_t k_pos, int32_t k_neg,
                                      int32_t b, int32_t vel_init, int32_t pos_init, int32_t half_cycles,
                                      int32_t length, int32_t drag, int32_t gravity,
                                      bool interim_reporting, int32_t axis);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* FEEL_FEEL_H */
