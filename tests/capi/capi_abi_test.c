/* The rest of the C ABI from C (C11), each checked against an independent truth:
 *
 *  1. the version: feel_version() is the headers' FEEL_VERSION;
 *  2. EnumDevices: one in-process device per profile, the early stop of the callback;
 *     device classes numbered 1 (I-FORCE 1.x) and 2 (I-FORCE 2.0) as on the wire;
 *  3. an x spring created from a feel_effect_params struct: the force the device reports
 *     follows the spring law F = -k/10000 * (x - offset) (§3.2, docs/conditions.md) at the
 *     position it reports; set_parameters with a mask changes only the masked fields
 *     (a new coefficient: the law with the new k; the gain: the force scales by it);
 *     with restart a stopped effect plays again;
 *  4. sized structs: too small is refused naming the size, a larger struct from newer
 *     headers is accepted while its unknown tail is zero and refused once it is not;
 *  5. EnumEffects and the pool: an I-FORCE 1.x-class device cannot create dynamics; one
 *     more effect takes one more slot;
 *  6. a sensation file loaded onto an open device, its effects altered before playing
 *     (§9.5), and the device still open after the library is freed;
 *  7. a command queue: a burst of updates coalesces, every call gets its outcome on the
 *     caller's poll, and the spring plays the newest coefficient.
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "c_check.h"
#include "feel/feel.h"

static void sleep_ms(long ms) {
    struct timespec t;
    t.tv_sec = ms / 1000;
    t.tv_nsec = (ms % 1000) * 1000000L;
    nanosleep(&t, NULL);
}

/* ---- 1. version --------------------------------------------------------------------- */

static void test_version(void) {
    CHECK(feel_version() == FEEL_VERSION, "feel_version() = %u is the headers' FEEL_VERSION %d", feel_version(),
          FEEL_VERSION);
    char expected[32];
    snprintf(expected, sizeof expected, "%d.%d.%d", FEEL_VERSION_MAJOR, FEEL_VERSION_MINOR, FEEL_VERSION_PATCH);
    CHECK(strcmp(feel_version_string(), expected) == 0, "feel_version_string() = %s", feel_version_string());
}

/* ---- 2. enumeration and device classes ------------------------------------------------ */

typedef struct seen_devices {
    int count;
    int stop_after;          /* 0: never stop */
    bool saw_iforce1, saw_iforce2, sizes_ok;
} seen_devices;

static bool on_device(const feel_device_info* info, void* user_data) {
    seen_devices* seen = (seen_devices*)user_data;
    ++seen->count;
    if (info->size != sizeof(feel_device_info)) seen->sizes_ok = false;
    if (strcmp(info->address, "sim:iforce1") == 0 && strcmp(info->class_name, "I-FORCE 1.x") == 0 && info->in_process)
        seen->saw_iforce1 = true;
    if (strcmp(info->address, "sim:iforce2") == 0 && strcmp(info->class_name, "I-FORCE 2.0") == 0 && info->in_process)
        seen->saw_iforce2 = true;
    return seen->stop_after == 0 || seen->count < seen->stop_after;
}

static void test_enumerate(void) {
    feel_enumerate_options options;
    FEEL_INIT(options);
    options.socket_dir = "/nonexistent/feel-capi-abi-test"; /* no socket devices: in-process only */
    seen_devices all = {0, 0, false, false, true};
    CHECK(feel_enumerate_devices(&options, on_device, &all) == FEEL_OK, "feel_enumerate_devices: %s",
          feel_last_error_message());
    CHECK(all.count >= 2 && all.saw_iforce1 && all.saw_iforce2 && all.sizes_ok,
          "%d devices, sim:iforce1 and sim:iforce2 among them with their class names, every info sized", all.count);
    seen_devices first = {0, 1, false, false, true};
    CHECK(feel_enumerate_devices(&options, on_device, &first) == FEEL_OK && first.count == 1,
          "a callback returning false stops the enumeration (%d call)", first.count);
    CHECK(feel_enumerate_devices(&options, NULL, NULL) == FEEL_ERROR_INVALID_PARAMETER,
          "a NULL callback is refused: %s", feel_last_error_message());

    const char* addresses[2] = {"sim:iforce1", "sim:iforce2"};
    const int32_t classes[2] = {FEEL_DEVICE_CLASS_IFORCE1, FEEL_DEVICE_CLASS_IFORCE2};
    CHECK(FEEL_DEVICE_CLASS_IFORCE1 == 1 && FEEL_DEVICE_CLASS_IFORCE2 == 2,
          "device classes are numbered by generation: 1 and 2");
    for (int i = 0; i < 2; ++i) {
        feel_device* dev = feel_open(addresses[i]);
        feel_caps caps;
        FEEL_INIT(caps);
        CHECK(dev && feel_device_caps(dev, &caps) == FEEL_OK && caps.device_class == classes[i],
              "%s reports device_class %d (%s)", addresses[i], caps.device_class, caps.class_name);
        feel_close(dev);
    }
}

/* ---- 3. an effect from a parameter struct, and set_parameters with a mask -------------- */

/* The newest state report after the safety fade-in is complete. */
static bool settled_input(feel_device* dev, feel_input* in) {
    for (int i = 0; i < 3000; ++i) {
        if (feel_wait_input(dev, 500, in) != FEEL_OK) return false;
        if (in->fade_level >= 1.0f && i > 20) return true;
    }
    return false;
}

/* |reported force - spring law at the reported position| for an x spring of coefficient k
 * (both sides), centred on 0, no deadband, saturation 10000, times gain / 10000. */
static double spring_law_error(const feel_input* in, int32_t k, int32_t gain) {
    const double expected = -(double)k / 10000.0 * (double)in->position[0] * (double)gain / 10000.0;
    const double error = (double)in->force[0] - expected;
    return error < 0 ? -error : error;
}

static void test_params(void) {
    feel_open_options options;
    FEEL_INIT(options);
    options.sim_hand = "kinematic";  /* the handle stays exactly where the hand holds it */
    options.sim_motion = "hold:4000";
    feel_device* dev = feel_open_ex("sim:iforce2", &options);
    CHECK(dev != NULL, "feel_open_ex(sim:iforce2, kinematic hand at x = 4000): %s",
          dev ? "opened" : feel_last_error_message());
    if (!dev) return;

    feel_effect_params p;
    FEEL_INIT(p);
    CHECK(feel_effect_params_init(&p, FEEL_TYPE_SPRING) == FEEL_OK, "feel_effect_params_init(SPRING)");
    CHECK(p.type == FEEL_TYPE_SPRING && p.duration_us == FEEL_INFINITE && p.gain == 10000 && p.axis_count == 1 &&
              p.axes[0] == FEEL_AXIS_X && p.conditions[0].pos_saturation == 10000,
          "its defaults: infinite, gain 10000, one axis x, saturation 10000");
    p.conditions[0].pos_coefficient = 5000;
    p.conditions[0].neg_coefficient = 5000;
    feel_effect* spring = feel_create_effect(dev, &p, NULL, 0);
    CHECK(spring != NULL, "feel_create_effect(spring k = 5000): %s", spring ? "created" : feel_last_error_message());
    if (!spring) {
        feel_close(dev);
        return;
    }
    CHECK(feel_effect_start(spring, FEEL_INFINITE_ITERATIONS, false) == FEEL_OK, "started");
    feel_input in;
    FEEL_INIT(in);
    bool settled = settled_input(dev, &in);
    CHECK(settled && in.position[0] > 3900 && spring_law_error(&in, 5000, 10000) < 5,
          "the device reports force %.0f at x = %.0f: the spring law -k/10000*x gives %.0f", (double)in.force[0],
          (double)in.position[0], -0.5 * (double)in.position[0]);

    /* Only the type-specific block is masked: the new coefficient applies, the gain of 1 in
     * the struct does not. */
    feel_effect_params change = p;
    change.conditions[0].pos_coefficient = 10000;
    change.conditions[0].neg_coefficient = 10000;
    change.gain = 1;
    CHECK(feel_effect_set_parameters(spring, &change, FEEL_FIELD_TYPE_SPECIFIC, false, NULL, 0) == FEEL_OK,
          "set_parameters(TYPE_SPECIFIC: k = 10000) %s", feel_last_error_message());
    feel_effect_params now;
    FEEL_INIT(now);
    CHECK(feel_effect_get_parameters(spring, &now) == FEEL_OK && now.conditions[0].pos_coefficient == 10000 &&
              now.gain == 10000,
          "get_parameters: k = %d, gain = %d (the unmasked gain kept)", now.conditions[0].pos_coefficient, now.gain);
    settled = settled_input(dev, &in);
    CHECK(settled && spring_law_error(&in, 10000, 10000) < 5, "force %.0f at x = %.0f follows the new k (%.0f)",
          (double)in.force[0], (double)in.position[0], -(double)in.position[0]);
    feel_effect_status_info status;
    FEEL_INIT(status);
    CHECK(feel_effect_status(spring, &status) == FEEL_OK && status.state == FEEL_STATE_PLAYING,
          "without restart it plays on");

    /* A barrier's Offset-Flag (§3.8, "same as the wall"): the field grown at the struct's end
     * goes in and comes back; a value past FEEL_OFFSET_RELATIVE is refused, naming it. */
    feel_effect_params bp;
    FEEL_INIT(bp);
    CHECK(feel_effect_params_init(&bp, FEEL_TYPE_AXIS_BARRIER) == FEEL_OK && bp.barrier_offset_mode == FEEL_OFFSET_ABSOLUTE,
          "feel_effect_params_init(AXIS_BARRIER): absolute by default");
    bp.barrier.pos_hardness = 5000;
    bp.barrier.neg_hardness = 5000;
    bp.barrier.thickness = 300;
    bp.barrier_offset_mode = 7;
    CHECK(feel_create_effect(dev, &bp, NULL, 0) == NULL && strstr(feel_last_error_message(), "barrier_offset_mode") != NULL,
          "barrier_offset_mode 7 refused: %s", feel_last_error_message());
    bp.barrier_offset_mode = FEEL_OFFSET_RELATIVE;
    feel_effect* barrier = feel_create_effect(dev, &bp, NULL, 0);
    CHECK(barrier != NULL, "feel_create_effect(relative barrier): %s", barrier ? "created" : feel_last_error_message());
    if (barrier) {
        feel_effect_params back;
        FEEL_INIT(back);
        CHECK(feel_effect_get_parameters(barrier, &back) == FEEL_OK && back.barrier_offset_mode == FEEL_OFFSET_RELATIVE,
              "get_parameters: barrier_offset_mode = %d (relative)", back.barrier_offset_mode);
        feel_effect_destroy(barrier);
    }

    change.gain = 2500;
    CHECK(feel_effect_set_parameters(spring, &change, FEEL_FIELD_GAIN, false, NULL, 0) == FEEL_OK,
          "set_parameters(GAIN = 2500)");
    settled = settled_input(dev, &in);
    CHECK(settled && spring_law_error(&in, 10000, 2500) < 5, "force %.0f: a quarter of the law (%.0f)",
          (double)in.force[0], -0.25 * (double)in.position[0]);

    CHECK(feel_effect_stop(spring) == FEEL_OK, "stopped");
    CHECK(feel_effect_set_parameters(spring, &change, FEEL_FIELD_GAIN, true, NULL, 0) == FEEL_OK &&
              feel_effect_status(spring, &status) == FEEL_OK && status.state == FEEL_STATE_PLAYING,
          "with restart a stopped effect plays again (state %d)", status.state);

    /* Refusals name the field and range, and change nothing. */
    change.conditions[0].deadband = 12000;
    CHECK(feel_effect_set_parameters(spring, &change, FEEL_FIELD_TYPE_SPECIFIC, false, NULL, 0) ==
                  FEEL_ERROR_INVALID_PARAMETER &&
              strstr(feel_last_error_message(), "deadband = 12000") != NULL,
          "a deadband of 12000: %s", feel_last_error_message());
    CHECK(feel_effect_get_parameters(spring, &now) == FEEL_OK && now.conditions[0].deadband == 0,
          "and the effect is as it was");
    CHECK(feel_effect_set_parameters(spring, &change, 1u << 12, false, NULL, 0) == FEEL_ERROR_INVALID_PARAMETER,
          "an unknown mask bit: %s", feel_last_error_message());
    feel_effect_params bad = p;
    bad.type = 99;
    CHECK(feel_create_effect(dev, &bad, NULL, 0) == NULL &&
              strcmp(feel_last_error_message(), "feel_create_effect: type = 99 is out of range (allowed 0..32)") == 0,
          "type 99: %s", feel_last_error_message());

    /* Unload keeps the handle and its parameters; download brings it back. */
    CHECK(feel_effect_unload(spring) == FEEL_OK && feel_effect_start(spring, 1, false) != FEEL_OK,
          "unloaded, it cannot start: %s", feel_last_error_message());
    CHECK(feel_effect_download(spring) == FEEL_OK && feel_effect_start(spring, 1, false) == FEEL_OK,
          "downloaded again, it starts");

    /* ---- 4. sized structs ---- */
    feel_caps caps = {0};
    CHECK(feel_device_caps(dev, &caps) == FEEL_ERROR_INVALID_PARAMETER && strstr(feel_last_error_message(), "size = 0"),
          "caps.size = 0: %s", feel_last_error_message());
    struct newer_params {     /* feel_effect_params as a later version might extend it */
        feel_effect_params known;
        int64_t field_from_the_future;
    } newer;
    memset(&newer, 0, sizeof newer);
    newer.known = p;
    newer.known.size = sizeof newer;
    feel_effect* e = feel_create_effect(dev, &newer.known, NULL, 0);
    CHECK(e != NULL, "a larger params struct whose extra fields are zero is accepted: %s",
          e ? "created" : feel_last_error_message());
    feel_effect_destroy(e);
    newer.field_from_the_future = 7;
    CHECK(feel_create_effect(dev, &newer.known, NULL, 0) == NULL && feel_last_error() == FEEL_ERROR_NOT_SUPPORTED,
          "and refused once they are not: %s", feel_last_error_message());
    struct newer_input {
        feel_input known;
        int64_t field_from_the_future;
    } big;
    memset(&big, 0, sizeof big);
    big.known.size = sizeof big;
    big.field_from_the_future = -1;
    CHECK(feel_poll_input(dev, &big.known) == FEEL_OK && big.field_from_the_future == -1 &&
              big.known.size == sizeof big && big.known.reports_received > 0,
          "a larger out struct is filled as far as feel knows, the rest left alone");

    feel_effect_destroy(spring);
    feel_close(dev);
}

/* ---- 5. EnumEffects and the pool ------------------------------------------------------- */

static void test_types_and_pool(void) {
    feel_device* one = feel_open("sim:iforce1");
    uint64_t types = 0;
    feel_caps one_caps;
    FEEL_INIT(one_caps);
    CHECK(one && feel_device_effect_types(one, &types) == FEEL_OK && (types & FEEL_TYPE_BIT(FEEL_TYPE_SPRING)) &&
              (types & FEEL_TYPE_BIT(FEEL_TYPE_DYNAMIC_RECOIL)) && feel_device_caps(one, &one_caps) == FEEL_OK &&
              !(one_caps.supported_types & FEEL_TYPE_BIT(FEEL_TYPE_DYNAMIC_RECOIL)),
          "an I-FORCE 1.x-class device plays no dynamics, and the host creates them (emulated; types %#llx)",
          (unsigned long long)types);
    feel_close(one);

    feel_device* dev = feel_open("sim:iforce2");
    CHECK(dev && feel_device_effect_types(dev, &types) == FEEL_OK && types == (FEEL_TYPE_BIT(FEEL_TYPE_COUNT) - 1),
          "an I-FORCE 2.0-class device creates all %d types", FEEL_TYPE_COUNT);
    feel_caps caps;
    FEEL_INIT(caps);
    feel_pool_info before, after;
    FEEL_INIT(before);
    FEEL_INIT(after);
    CHECK(feel_device_caps(dev, &caps) == FEEL_OK && feel_device_pool(dev, &before) == FEEL_OK &&
              before.max_effects == caps.effect_slots,
          "pool: %d effect slots (%d free), %d of %d bytes free", before.max_effects, before.free_effects,
          before.free_bytes, before.total_bytes);
    feel_effect* e = feel_x_spring(dev, 1000, 1000, 0, 10000, 10000, 0);
    CHECK(e && feel_device_pool(dev, &after) == FEEL_OK && after.free_effects == before.free_effects - 1 &&
              after.free_bytes < before.free_bytes,
          "one more effect: %d slots free, %d bytes free", after.free_effects, after.free_bytes);
    char address[64];
    CHECK(feel_device_address(dev, address, sizeof address) == FEEL_OK && strcmp(address, "sim:iforce2") == 0,
          "feel_device_address: %s", address);
    CHECK(feel_set_report_rate(dev, 50) == FEEL_ERROR_INVALID_PARAMETER, "a report rate of 50 Hz: %s",
          feel_last_error_message());
    CHECK(feel_set_report_rate(dev, 500) == FEEL_OK && feel_set_idf(dev, true, false) == FEEL_OK,
          "report rate 500 Hz, IDF for vibrations");
    feel_effect_destroy(e);
    feel_close(dev);
}

/* ---- 6. a sensation file onto an open device --------------------------------------- */

static void test_library_on_device(void) {
    feel_device* dev = feel_open("sim:iforce2");
    const char* only[1] = {"railing_impact"};
    feel_library* lib = feel_library_load_on(FEEL_SOURCE_DIR "/examples/primer.feel.json", dev, only, 1);
    CHECK(lib != NULL, "feel_library_load_on(primer, railing_impact only): %s",
          lib ? "loaded" : feel_last_error_message());
    if (!lib) {
        feel_close(dev);
        return;
    }
    CHECK(feel_library_sensation_count(lib) == 1 && strcmp(feel_library_sensation_name(lib, 0), "railing_impact") == 0,
          "one sensation, railing_impact");
    CHECK(feel_library_sensation_name(lib, 1) == NULL && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER,
          "index 1: %s", feel_last_error_message());
    const int32_t n = feel_library_effect_count(lib, "railing_impact");
    CHECK(n >= 1, "railing_impact has %d effect(s)", n);
    feel_effect* first = feel_library_effect(lib, "railing_impact", 0);
    feel_effect_params params;
    FEEL_INIT(params);
    CHECK(first && feel_effect_get_parameters(first, &params) == FEEL_OK, "its first effect is a type %d",
          params.type);
    params.gain = 5000;
    CHECK(feel_effect_set_parameters(first, &params, FEEL_FIELD_GAIN, false, NULL, 0) == FEEL_OK,
          "altered before playing (§9.5): gain 5000");
    CHECK(feel_library_play_ex(lib, "railing_impact", 1) == FEEL_OK, "played once");
    sleep_ms(50);
    CHECK(feel_library_stop_all(lib) == FEEL_OK, "stopped");
    feel_effect_destroy(first);
    CHECK(feel_last_error() == FEEL_ERROR_INVALID_PARAMETER, "a library's effect cannot be destroyed: %s",
          feel_last_error_message());
    CHECK(feel_library_effect_count(lib, "vortex") == 0 && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER,
          "an unknown sensation: %s", feel_last_error_message());
    feel_library_free(lib);
    CHECK(feel_device_connected(dev), "the caller's device stays open after feel_library_free");
    feel_close(dev);
}

/* ---- 7. calls that never stall a frame -------------------------------------------- */

typedef struct seen_outcomes {
    int count, failed, coalesced;
    uint64_t last_ticket;
    bool sizes_ok;
} seen_outcomes;

static void on_outcome(const feel_outcome* o, void* user_data) {
    seen_outcomes* seen = (seen_outcomes*)user_data;
    ++seen->count;
    if (o->code != FEEL_OK) ++seen->failed;
    if (o->coalesced) ++seen->coalesced;
    if (o->ticket > seen->last_ticket) seen->last_ticket = o->ticket;
    if (o->size != sizeof(feel_outcome)) seen->sizes_ok = false;
}

static void test_queue(void) {
    feel_open_options options;
    FEEL_INIT(options);
    options.sim_hand = "kinematic";
    options.sim_motion = "hold:-2000";
    feel_device* dev = feel_open_ex("sim:iforce2", &options);
    feel_queue* queue = dev ? feel_queue_create(dev, 0, 0) : NULL;
    CHECK(queue != NULL, "feel_queue_create: %s", queue ? "made" : feel_last_error_message());
    if (!queue) {
        feel_close(dev);
        return;
    }
    feel_effect_params p;
    FEEL_INIT(p);
    feel_effect_params_init(&p, FEEL_TYPE_SPRING);
    p.conditions[0].pos_coefficient = p.conditions[0].neg_coefficient = 1000;
    feel_effect* spring = feel_create_effect(dev, &p, NULL, 0);
    CHECK(spring && feel_queue_start(queue, spring, FEEL_INFINITE_ITERATIONS, false) == 1, "start queued: ticket 1");
    for (int i = 1; i <= 50; ++i) { /* a burst: coalesces to the newest, k = 5000 */
        p.conditions[0].pos_coefficient = p.conditions[0].neg_coefficient = 100 * i;
        if (feel_queue_set_parameters(queue, spring, &p, FEEL_FIELD_TYPE_SPECIFIC, false, NULL, 0) == 0) {
            CHECK(false, "feel_queue_set_parameters: %s", feel_last_error_message());
            break;
        }
    }
    CHECK(feel_queue_start(queue, NULL, 0, false) == 0 && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER,
          "a NULL effect is refused at once: %s", feel_last_error_message());
    CHECK(feel_queue_set_gain(queue, -1) == 0 && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER,
          "a gain of -1 is refused at once: %s", feel_last_error_message());
    CHECK(feel_queue_flush(queue, 10000) == FEEL_OK && feel_queue_pending(queue) == 0, "flushed");
    seen_outcomes seen = {0, 0, 0, 0, true};
    const int32_t n = feel_queue_poll(queue, on_outcome, &seen);
    CHECK(n == 51 && seen.count == 51 && seen.failed == 0 && seen.last_ticket == 51 && seen.sizes_ok,
          "51 outcomes on this thread's poll, none failed (%d coalesced)", seen.coalesced);
    feel_input in;
    FEEL_INIT(in);
    for (int i = 0; i < 30; ++i) feel_wait_input(dev, 500, &in);
    CHECK(settled_input(dev, &in) && spring_law_error(&in, 5000, 10000) < 5,
          "the spring plays the newest k: force %.0f at x = %.0f (law %.0f)", (double)in.force[0],
          (double)in.position[0], -0.5 * (double)in.position[0]);
    feel_queue_destroy(queue);
    feel_effect_destroy(spring);
    feel_close(dev);
}

int main(void) {
    test_version();
    test_enumerate();
    test_params();
    test_types_and_pool();
    test_library_on_device();
    test_queue();
    if (c_check_failures) printf("%d check(s) failed\n", c_check_failures);
    return c_check_failures ? 1 : 0;
}
