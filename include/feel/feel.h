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
 * feel_last_error_message and feel_error_name) sets the calling thread's last error: the
 * code and a sentence naming what is wrong, e.g.
 *   "feel_set_gain: gain = 12000 is out of range (allowed 0..10000)"
 * and FEEL_OK with an empty message when it succeeds. A NULL handle or out pointer is
 * FEEL_ERROR_INVALID_PARAMETER. No C++ exception ever crosses this interface.
 *
 * Handles. feel_device, feel_effect, feel_library and feel_subscription are opaque.
 * An effect stays valid after its device is closed, but every call on it then returns
 * FEEL_ERROR_INVALID_HANDLE; it must still be destroyed. Destroying a handle twice, or
 * using it after destroying it, is undefined (as free() is).
 *
 * Threads. A device and its effects may be used from one thread at a time. The last error
 * is thread-local. Callbacks run on the device's I/O thread and must not call back into
 * feel for that device (queue the work instead).
 *
 * docs/c-api.md has the details; docs/wrappers.md the §8 wrappers' parameters.
 */
#ifndef FEEL_FEEL_H
#define FEEL_FEEL_H

#include <stdbool.h>
#include <stdint.h>

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
int feel_last_error(void);
const char* feel_last_error_message(void);
/* "ok", "invalid parameter", ... ; "unknown error" for any other value. */
const char* feel_error_name(int code);

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

/* ---- Devices --------------------------------------------------------------------------- */

typedef struct feel_device feel_device;
typedef struct feel_effect feel_effect;
typedef struct feel_library feel_library;
typedef struct feel_subscription feel_subscription;

/* Opens "sim:PROFILE" (an in-process simulated device, e.g. "sim:iforce2"),
 * "unix:PATH" or "tcp:HOST:PORT"; NULL or "" means "sim:iforce2". NULL on failure. */
feel_device* feel_open(const char* address);
/* feel_open with options (feel::host::OpenOptions). A zero field takes its default. */
typedef struct feel_open_options {
    int32_t timeout_ms;      /* per command round trip, 1..60000; 0: 2000 */
    int32_t report_rate_hz;  /* state reports per second, 100..1000; 0: the device's */
    /* sim: addresses only: the simulated hand ("none", "loose", "firm", "stiff",
     * "kinematic"; NULL: "firm") and its target motion (as `feel render --motion`, e.g.
     * "hold:0", "sine:x:5000:1", "circle:3000:0.5"; NULL: "hold:0"). */
    const char* sim_hand;
    const char* sim_motion;
} feel_open_options;
feel_device* feel_open_ex(const char* address, const feel_open_options* options);
/* Frees every effect of this host on the device and closes it; NULL is ignored. Effects
 * made from it return FEEL_ERROR_INVALID_HANDLE afterwards. */
void feel_close(feel_device* device);

typedef struct feel_axis_caps {
    int32_t axis;          /* FEEL_AXIS_* */
    bool rotary;           /* linear: m and N; rotary: rad and N·m */
    double half_travel;    /* m or rad at position ±10000 */
    double max_force;      /* N or N·m at force ±10000 */
    int32_t sensor_counts; /* sensor resolution over the whole travel */
} feel_axis_caps;

/* GetCapabilities (§7.4). Strings are NUL-terminated, truncated to fit. */
typedef struct feel_caps {
    char device[32];            /* profile name, e.g. "iforce2" */
    char description[256];
    char class_name[32];        /* "I-FORCE 1.x", "I-FORCE 2.0" */
    char firmware_version[32];
    char protocol_version[32];
    int32_t device_class;       /* 1: I-FORCE 1.x class, 2: I-FORCE 2.0 class */
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
int feel_device_caps(const feel_device* device, feel_caps* out);

/* DIPROP_FFGAIN: the device's overall gain, 0..10000. */
int feel_set_gain(feel_device* device, int32_t gain);

/* SendForceFeedbackCommand (DISFFC_*). */
enum {
    FEEL_COMMAND_ACTUATORS_ON = 0, /* forces pass again, faded in */
    FEEL_COMMAND_ACTUATORS_OFF,    /* no force; effects play on */
    FEEL_COMMAND_STOP_ALL,         /* stop every effect; they stay resident */
    FEEL_COMMAND_RESET,            /* free every effect and reflex, gain 10000 */
    FEEL_COMMAND_PAUSE,            /* every effect clock stands still, no force */
    FEEL_COMMAND_RESUME
};
int feel_device_command(feel_device* device, int32_t command);

/* The device's latest input state, from its input reports (no round trip). */
typedef struct feel_input {
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
int feel_poll_input(feel_device* device, feel_input* out);
/* Waits up to timeout_ms (1..60000) for a state report newer than the current one. */
int feel_wait_input(feel_device* device, int32_t timeout_ms, feel_input* out);

/* Force streaming (§2.4): one sample of the host's force per device axis, ±10000,
 * physical sign (+ pushes toward +axis), up to 1 kHz. axis_count must equal the device's. */
int feel_stream_force(feel_device* device, const int32_t* force, int32_t axis_count);

/* ---- Effects ----------------------------------------------------------------------------- */

/* Unloads the effect from its device (if still there) and frees the handle; NULL ignored. */
void feel_effect_destroy(feel_effect* effect);
/* Start (iterations: FEEL_EFFECT_ITERATIONS, 1..255 or FEEL_INFINITE_ITERATIONS; solo:
 * stop every other effect first, DIES_SOLO) and Stop. */
int feel_effect_start(feel_effect* effect, int32_t iterations, bool solo);
int feel_effect_stop(feel_effect* effect);

enum { FEEL_STATE_STOPPED = 0, FEEL_STATE_PLAYING, FEEL_STATE_DELAYED, FEEL_STATE_EMULATED };
enum { FEEL_END_NONE = 0, FEEL_END_STOPPED, FEEL_END_FINISHED };
typedef struct feel_effect_status_info {
    int32_t state;                /* FEEL_STATE_* */
    bool emulated;                /* the host plays (part of) it for the device (§1.2.c) */
    int32_t iterations;           /* of the current or last play; FEEL_INFINITE_ITERATIONS */
    int32_t completed_iterations;
    int64_t elapsed_us;
    int32_t last_end;             /* FEEL_END_*: how the last play ended */
} feel_effect_status_info;
int feel_effect_status(feel_effect* effect, feel_effect_status_info* out);

/* ---- Dynamic reports (§5.2) ---------------------------------------------------------- */

enum { FEEL_REPORT_INTERIM = 0, FEEL_REPORT_FINAL };
typedef struct feel_dynamic_event {
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
feel_subscription* feel_effect_subscribe(feel_effect* effect, feel_dynamic_callback callback, void* user_data);
feel_subscription* feel_device_subscribe(feel_device* device, feel_dynamic_callback callback, void* user_data);
/* Stops the calls (none is in progress when it returns) and frees the handle; NULL ignored. */
void feel_unsubscribe(feel_subscription* subscription);

/* ---- Load and play in two calls (§9.5) ----------------------------------------------- */

/* Call 1: opens the device at `address` (NULL or "": "sim:iforce2"), creates and downloads
 * every effect of every sensation in the file, and arms its button assignments as
 * reflexes. NULL on failure (the message names the file, sensation, field and range). */
feel_library* feel_library_load(const char* path, const char* address);
/* Call 2: starts every effect of the named sensation. */
int feel_library_play(feel_library* library, const char* name);
int feel_library_stop(feel_library* library, const char* name);
/* The library's device, owned by the library (do not feel_close it): to poll its input,
 * set its gain, ... NULL if library is NULL. */
feel_device* feel_library_device(feel_library* library);
/* Frees every effect of the library and closes its device; NULL is ignored. */
void feel_library_free(feel_library* library);

/* ---- The I-FORCE 2.0 wrapper functions (§8) ------------------------------------------- *
 * Each builds the effect of feel::iforce::<name> (docs/wrappers.md), creates it on the
 * device and downloads it, and returns it stopped (start it with feel_effect_start); NULL
 * on failure: FEEL_ERROR_INVALID_PARAMETER names the wrapper, the parameter and its range
 * ("x_spring: deadband = 12000 is out of range (allowed 0..10000)"); the device's refusals
 * (not supported, full) as their codes. */

/* §8.2 conditions */
feel_effect* feel_x_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
feel_effect* feel_y_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
feel_effect* feel_spring(feel_device* device, int32_t x_k_pos, int32_t x_k_neg, int32_t x_offset,
                         int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                         int32_t y_k_pos, int32_t y_k_neg, int32_t y_offset, int32_t y_pos_saturation,
                         int32_t y_neg_saturation, int32_t y_deadband);
feel_effect* feel_angle_spring(feel_device* device, int32_t k_pos, int32_t k_neg, int32_t offset,
                               int32_t pos_saturation, int32_t neg_saturation, int32_t deadband,
                               int32_t angle);
feel_effect* feel_center_spring(feel_device* device, int32_t k, int32_t saturation, int32_t deadband);
feel_effect* feel_spring_at_current_location(feel_device* device, int32_t k, int32_t saturation,
                                             int32_t deadband);
feel_effect* feel_x_damper(feel_device* device, int32_t b_pos, int32_t b_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
feel_effect* feel_y_damper(feel_device* device, int32_t b_pos, int32_t b_neg, int32_t offset,
                           int32_t pos_saturation, int32_t neg_saturation, int32_t deadband);
feel_effect* feel_damper(feel_device* device, int32_t x_b_pos, int32_t x_b_neg, int32_t x_offset,
                         int32_t x_pos_saturation, int32_t x_neg_saturation, int32_t x_deadband,
                         int32_t y_b_pos, int32_t y_b_neg, int32_t y_offset, int32_t y_pos_saturation,
                         int32_t y_neg_saturation, int32_t y_deadband);
feel_effect* feel_x_inertia(feel_device* device, int32_t mass, int32_t saturation);
feel_effect* feel_y_inertia(feel_device* device, int32_t mass, int32_t saturation);
feel_effect* feel_inertia(feel_device* device, int32_t mass, int32_t saturation);
feel_effect* feel_friction(feel_device* device, int32_t f);
feel_effect* feel_x_friction(feel_device* device, int32_t f_pos, int32_t f_neg);
feel_effect* feel_y_friction(feel_device* device, int32_t f_pos, int32_t f_neg);
feel_effect* feel_texture(feel_device* device, int32_t roughness, int32_t spacing, int32_t density,
                          int32_t angle);
/* XTexture(Roughness, Spacing, Density) and XTexture(PosRoughness, NegRoughness, Spacing,
 * Density): C has no overloads, so the second is feel_x_texture_pos_neg. */
feel_effect* feel_x_texture(feel_device* device, int32_t roughness, int32_t spacing, int32_t density);
feel_effect* feel_x_texture_pos_neg(feel_device* device, int32_t pos_roughness, int32_t neg_roughness,
                                    int32_t spacing, int32_t density);
feel_effect* feel_y_texture(feel_device* device, int32_t pos_roughness, int32_t neg_roughness,
                            int32_t spacing, int32_t density);
feel_effect* feel_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset, int32_t angle);
/* Horizontal: the line y = offset, felt along y; vertical: x = offset, felt along x. */
feel_effect* feel_horizontal_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset,
                                  int32_t surface_friction, int32_t surface_texture, bool clipping);
feel_effect* feel_vertical_wall(feel_device* device, int32_t hardness, int32_t sense, int32_t offset,
                                int32_t surface_friction, int32_t surface_texture, bool clipping);
feel_effect* feel_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                          int32_t thickness, int32_t offset, int32_t angle);
feel_effect* feel_horizontal_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                                     int32_t thickness, int32_t offset, int32_t surface_friction,
                                     int32_t surface_texture);
feel_effect* feel_vertical_barrier(feel_device* device, int32_t pos_hardness, int32_t neg_hardness,
                                   int32_t thickness, int32_t offset, int32_t surface_friction,
                                   int32_t surface_texture);

/* §8.3 waves */
feel_effect* feel_vector_force(feel_device* device, int32_t magnitude, int64_t duration_us,
                               int32_t direction);
feel_effect* feel_constant_force(feel_device* device, int32_t magnitude, int64_t duration_us,
                                 int32_t direction);
feel_effect* feel_constant_force_trigger(feel_device* device, int32_t magnitude, int64_t duration_us,
                                         int32_t direction, feel_trigger trigger,
                                         int64_t trigger_repeat_interval_us);
feel_effect* feel_envelope_constant(feel_device* device, int32_t magnitude, int64_t duration_us,
                                    int32_t direction, int32_t impulse_level, int64_t settle_time_us,
                                    int32_t fade_level, int64_t fade_time_us, feel_trigger trigger,
                                    int64_t trigger_repeat_interval_us);
feel_effect* feel_ramp(feel_device* device, int32_t start, int32_t end, int64_t duration_us,
                       int32_t direction, feel_trigger trigger, int64_t trigger_repeat_interval_us);
feel_effect* feel_ramp_envelope(feel_device* device, int32_t start, int32_t end, int64_t duration_us,
                                int32_t direction, int32_t impulse_level, int64_t settle_time_us,
                                int32_t fade_level, int64_t fade_time_us, feel_trigger trigger,
                                int64_t trigger_repeat_interval_us);
feel_effect* feel_periodic(feel_device* device, int32_t waveform, int32_t magnitude, int32_t offset,
                           int32_t phase, int64_t period_us, int64_t duration_us, int32_t angle,
                           feel_trigger trigger, int64_t trigger_repeat_interval_us);
feel_effect* feel_envelope_periodic(feel_device* device, int32_t waveform, int32_t magnitude,
                                    int32_t offset, int32_t phase, int64_t period_us,
                                    int64_t duration_us, int32_t angle, int32_t impulse_level,
                                    int64_t settle_time_us, int32_t fade_level, int64_t fade_time_us,
                                    feel_trigger trigger, int64_t trigger_repeat_interval_us);
feel_effect* feel_delayed_periodic(feel_device* device, int64_t pause_us, int32_t waveform,
                                   int32_t magnitude, int32_t offset, int32_t phase, int64_t period_us,
                                   int64_t duration_us, int32_t angle, feel_trigger trigger,
                                   int64_t trigger_repeat_interval_us);
feel_effect* feel_sweep_periodic(feel_device* device, int32_t start_angle, int32_t stop_angle,
                                 int32_t sense, int32_t waveform, int32_t magnitude, int32_t offset,
                                 int64_t period_us, int32_t phase, int64_t duration_us);

/* §8.4 dynamics */
feel_effect* feel_dynamic_recoil(feel_device* device, int32_t blast_direction, int32_t blast_intensity,
                                 int32_t dynamic_mass, int32_t blast_resonance, int32_t blast_decay);
feel_effect* feel_dynamic_impact(feel_device* device, int32_t impact_direction, int32_t impact_intensity,
                                 int32_t dynamic_mass, int32_t elasticity, int32_t collision_absorption);
feel_effect* feel_dynamic_liquid(feel_device* device, int32_t density, int32_t settle, int32_t viscosity);
feel_effect* feel_dynamic_inertia(feel_device* device, int32_t inertia, int32_t play);
feel_effect* feel_dynamic_center_drift(feel_device* device, int32_t stiffness, int32_t drift_resistance);
feel_effect* feel_dynamic_sling(feel_device* device, int32_t ball_mass, int32_t string_length,
                                int32_t string_compliance, int32_t ball_damping, bool interim_reporting);
feel_effect* feel_dynamic_paddle(feel_device* device, int32_t ball_mass, int32_t initial_velocity,
                                 int32_t initial_velocity_direction, int32_t paddle_compliance,
                                 int32_t paddle_damping, int32_t gravity, bool interim_reporting);
/* axis: FEEL_AXIS_* the law plays on (§8.4: "a single axis"). */
feel_effect* feel_dynamic_control_law(feel_device* device, int32_t mass, int32_t k_pos, int32_t k_neg,
                                      int32_t b, int32_t vel_init, int32_t pos_init, int32_t half_cycles,
                                      int32_t length, int32_t drag, int32_t gravity,
                                      bool interim_reporting, int32_t axis);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* FEEL_FEEL_H */
