/* The C ABI from C (C11): what a C game does with feel.h, on the in-process simulated
 * I-FORCE 2.0 joystick. Each check prints what it found; main returns nonzero if any fails.
 *
 *  1. open sim:iforce2 (the hand sweeping x) and read its capabilities;
 *  2. an x spring (§8.2 XSpring) started and playing; its force opposes the displacement;
 *  3. errors: a bad gain and a bad wrapper argument name the parameter and the range;
 *     NULL handles are refused;
 *  4. interim reports of a dynamic arrive through a C callback;
 *  5. the two calls of §9.5: load examples/primer.feel.json and play a sensation.
 */
#include <stdatomic.h>
#include <stdbool.h>
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

static atomic_int interim_reports;
static atomic_int final_reports;

static void on_report(const feel_dynamic_event* event, void* user_data) {
    (void)user_data;
    if (event->kind == FEEL_REPORT_INTERIM) atomic_fetch_add(&interim_reports, 1);
    if (event->kind == FEEL_REPORT_FINAL) atomic_fetch_add(&final_reports, 1);
}

static void test_device(void) {
    feel_open_options options;
    FEEL_INIT(options);
    options.sim_hand = "kinematic";          /* the handle goes exactly where the motion says */
    options.sim_motion = "sine:x:6000:1";    /* ±6000 along x at 1 Hz */
    feel_device* dev = feel_open_ex("sim:iforce2", &options);
    CHECK(dev != NULL, "feel_open_ex(sim:iforce2): %s", dev ? "opened" : feel_last_error_message());
    if (!dev) return;

    int rc = FEEL_OK;
    feel_caps caps;
    FEEL_INIT(caps);
    CHECK(feel_device_caps(dev, &caps) == FEEL_OK, "feel_device_caps: %s, %d axes, %d buttons, class %s",
          caps.device, caps.axis_count, caps.button_count, caps.class_name);
    CHECK(strcmp(caps.device, "iforce2") == 0 && caps.axis_count == 2, "the device is the 2-axis iforce2");
    CHECK((caps.supported_types & FEEL_TYPE_BIT(FEEL_TYPE_SPRING)) != 0, "it plays springs");
    CHECK(caps.local_reflexes, "an I-FORCE 2.0-class device runs reflexes itself");

    /* §8.2 XSpring(KPos, KNeg, Offset, PosSat, NegSat, DeadBand) */
    feel_effect* spring = feel_x_spring(dev, 5000, 5000, 0, 10000, 10000, 0);
    CHECK(spring != NULL, "feel_x_spring: %s", spring ? "created" : feel_last_error_message());
    if (spring) {
        rc = feel_effect_start(spring, FEEL_INFINITE_ITERATIONS, false);
        CHECK(rc == FEEL_OK, "feel_effect_start(INFINITE) %s", feel_last_error_message());
        feel_effect_status_info status;
        FEEL_INIT(status);
        CHECK(feel_effect_status(spring, &status) == FEEL_OK && status.state == FEEL_STATE_PLAYING,
              "the spring plays (state %d)", status.state);
        CHECK(!status.emulated, "and not emulated");

        /* Over a second of the hand's sine the spring must push against the displacement:
         * F = -5000/10000 * x, so force and position have opposite signs wherever |x| is large. */
        int opposing = 0, samples = 0;
        int64_t t0 = -1;
        for (int i = 0; i < 5000; ++i) {
            feel_input in;
            FEEL_INIT(in);
            if (feel_wait_input(dev, 500, &in) != FEEL_OK) {
                CHECK(false, "feel_wait_input: %s", feel_last_error_message());
                break;
            }
            if (t0 < 0) t0 = in.t_us;
            if (in.t_us - t0 > 1000000) break; /* one period of the hand's sine */
            if (in.position[0] > 2000.0f || in.position[0] < -2000.0f) {
                ++samples;
                if (in.force[0] * in.position[0] < 0.0f) ++opposing;
            }
        }
        CHECK(samples >= 5 && opposing == samples, "the spring's force opposes the displacement (%d of %d reports)",
              opposing, samples);

        feel_input in;

        FEEL_INIT(in);
        CHECK(feel_poll_input(dev, &in) == FEEL_OK && in.reports_received > 0 && in.playing_effects >= 1,
              "feel_poll_input: %llu reports, %d playing, x = %.0f, force x = %.0f",
              (unsigned long long)in.reports_received, in.playing_effects, (double)in.position[0],
              (double)in.force[0]);
        CHECK(feel_effect_stop(spring) == FEEL_OK, "feel_effect_stop");
    }

    /* Errors. */
    rc = feel_set_gain(dev, 12000);
    CHECK(rc == FEEL_ERROR_INVALID_PARAMETER, "feel_set_gain(12000) -> %s", feel_error_name(rc));
    CHECK(strstr(feel_last_error_message(), "gain") && strstr(feel_last_error_message(), "0..10000"),
          "its message names the gain and the range: \"%s\"", feel_last_error_message());
    CHECK(feel_set_gain(dev, 8000) == FEEL_OK && feel_last_error() == FEEL_OK && feel_last_error_message()[0] == 0,
          "feel_set_gain(8000) succeeds and clears the last error");

    feel_effect* bad = feel_x_spring(dev, 1000, 1000, 0, 10000, 10000, 12000);
    CHECK(bad == NULL && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER, "feel_x_spring(deadband 12000) is refused");
    CHECK(strcmp(feel_last_error_message(), "x_spring: deadband = 12000 is out of range (allowed 0..10000)") == 0,
          "with \"%s\"", feel_last_error_message());

    bad = feel_periodic(dev, 42, 1000, 0, 0, 10000, FEEL_INFINITE, 0, feel_no_trigger(), 0);
    CHECK(bad == NULL && strstr(feel_last_error_message(), "waveform = 42 is out of range (allowed 0..4)"),
          "a bad waveform: \"%s\"", feel_last_error_message());

    CHECK(feel_effect_start(NULL, 1, false) == FEEL_ERROR_INVALID_PARAMETER &&
              strcmp(feel_last_error_message(), "feel_effect_start: effect is NULL") == 0,
          "a NULL effect: \"%s\"", feel_last_error_message());
    CHECK(feel_x_spring(NULL, 1, 1, 0, 1, 1, 0) == NULL && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER,
          "a NULL device: \"%s\"", feel_last_error_message());
    CHECK(feel_poll_input(dev, NULL) == FEEL_ERROR_INVALID_PARAMETER, "a NULL out pointer: \"%s\"",
          feel_last_error_message());

    /* Interim reports through a C callback (§5.2): a control law with interim reporting. */
    feel_effect* law = feel_dynamic_control_law(dev, 5000, 5000, 5000, 500, 3000, 0, 0, 0, 0, 0, true, FEEL_AXIS_X);
    CHECK(law != NULL, "feel_dynamic_control_law: %s", law ? "created" : feel_last_error_message());
    if (law) {
        feel_subscription* sub = feel_effect_subscribe(law, on_report, NULL);
        CHECK(sub != NULL, "feel_effect_subscribe: %s", sub ? "subscribed" : feel_last_error_message());
        CHECK(feel_effect_start(law, FEEL_EFFECT_ITERATIONS, true) == FEEL_OK, "started solo");
        sleep_ms(500);
        feel_unsubscribe(sub);
        const int n = atomic_load(&interim_reports);
        const double expected = 0.5 * caps.interim_report_hz;
        CHECK(n >= 0.5 * expected && n <= 1.5 * expected, "%d interim reports in 0.5 s at %.0f Hz (about %.0f)", n,
              caps.interim_report_hz, expected);
        feel_effect_destroy(law);
    }

    feel_effect_destroy(spring);
    feel_close(dev);
    feel_close(NULL); /* harmless */
}

static void test_library(void) {
    /* §9.5, call 1 and call 2. */
    feel_library* lib = feel_library_load(FEEL_SOURCE_DIR "/examples/primer.feel.json", "sim:iforce2");
    CHECK(lib != NULL, "feel_library_load(primer.feel.json): %s", lib ? "loaded" : feel_last_error_message());
    if (!lib) return;
    feel_device* dev = feel_library_device(lib);
    CHECK(dev != NULL, "feel_library_device");

    /* railing_impact: a vector force from the right (polar 9000): it pushes toward -x. */
    int rc = feel_library_play(lib, "railing_impact");
    CHECK(rc == FEEL_OK, "feel_library_play(railing_impact) %s", feel_last_error_message());
    float force_x = 0.0f;
    for (int i = 0; i < 100 && force_x > -500.0f; ++i) {
        feel_input in;
        FEEL_INIT(in);
        if (feel_wait_input(dev, 500, &in) != FEEL_OK) break;
        force_x = in.force[0];
    }
    CHECK(force_x < -500.0f, "the railing's impact pushes the stick left (force x = %.0f)", (double)force_x);
    CHECK(feel_library_stop(lib, "railing_impact") == FEEL_OK, "feel_library_stop");

    rc = feel_library_play(lib, "no_such_sensation");
    CHECK(rc == FEEL_ERROR_INVALID_PARAMETER, "an unknown sensation -> %s: \"%s\"", feel_error_name(rc),
          feel_last_error_message());
    feel_library_free(lib);

    lib = feel_library_load(FEEL_SOURCE_DIR "/examples/does_not_exist.feel.json", NULL);
    CHECK(lib == NULL && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER, "a missing file: \"%s\"",
          feel_last_error_message());
}

static int compare_i64(const void* a, const void* b) {
    const int64_t x = *(const int64_t*)a, y = *(const int64_t*)b;
    return (x > y) - (x < y);
}

static void test_input_subscription(void) {
    /* Every report, in order: at 500 reports a second the device's clock advances 2000 µs
     * from one report to the next (a skipped loop tick makes one gap longer), and a queue of
     * 1000 loses none over 300 ms. Read 7 at a time, so that most calls leave reports queued
     * for the next one. */
    feel_open_options options;
    FEEL_INIT(options);
    options.report_rate_hz = 500;
    feel_device* dev = feel_open_ex("sim:iforce2", &options);
    CHECK(dev != NULL, "feel_open_ex(sim:iforce2, 500 Hz reports): %s", dev ? "opened" : feel_last_error_message());
    if (!dev) return;
    feel_input_subscription* sub = feel_subscribe_input(dev, 1000);
    CHECK(sub != NULL, "feel_subscribe_input: %s", sub ? "subscribed" : feel_last_error_message());
    if (sub) {
        enum { kMax = 400 };
        static int64_t t[kMax];
        static int64_t gaps[kMax];
        int n = 0;
        uint64_t lost = 0;
        while (n < kMax && (n == 0 || t[n - 1] - t[0] < 300000)) {
            feel_input batch[7];
            batch[0].size = sizeof(feel_input);
            int32_t count = 0;
            uint64_t dropped = 0;
            if (feel_input_subscription_wait(sub, 500, batch, 7, &count, &dropped) != FEEL_OK) {
                CHECK(false, "feel_input_subscription_wait: %s", feel_last_error_message());
                break;
            }
            CHECK(count >= 1 && count <= 7, "a call gives 1..7 reports (%d)", count);
            lost += dropped;
            for (int i = 0; i < count && n < kMax; ++i) {
                CHECK(batch[i].size == sizeof(feel_input) && batch[i].axis_count == 2, "report %d is filled", n);
                t[n++] = batch[i].t_us;
            }
        }
        int increasing = 1;
        for (int i = 1; i < n; ++i) {
            gaps[i - 1] = t[i] - t[i - 1];
            if (gaps[i - 1] <= 0) increasing = 0;
        }
        CHECK(n > 100 && increasing, "%d reports, their device times strictly increasing", n);
        qsort(gaps, (size_t)(n - 1), sizeof gaps[0], compare_i64);
        CHECK(gaps[(n - 1) / 2] == 2000, "the median gap is the report period, 2000 µs (%lld)",
              (long long)gaps[(n - 1) / 2]);
        CHECK(lost == 0, "none lost (%llu)", (unsigned long long)lost);

        int32_t count = -1;
        feel_input one;
        FEEL_INIT(one);
        CHECK(feel_input_subscription_wait(sub, 500, &one, 0, &count, NULL) == FEEL_ERROR_INVALID_PARAMETER &&
                  strstr(feel_last_error_message(), "max_reports = 0 is out of range") && count == 0,
              "max_reports 0: \"%s\"", feel_last_error_message());
        one.size = 4;
        CHECK(feel_input_subscription_wait(sub, 500, &one, 1, &count, NULL) == FEEL_ERROR_INVALID_PARAMETER,
              "a report struct without its size: \"%s\"", feel_last_error_message());
        feel_unsubscribe_input(sub);
    }
    CHECK(feel_subscribe_input(dev, 0) == NULL && strstr(feel_last_error_message(), "capacity = 0 is out of range (allowed 1..1000000)"),
          "capacity 0: \"%s\"", feel_last_error_message());
    CHECK(feel_subscribe_input(NULL, 10) == NULL && feel_last_error() == FEEL_ERROR_INVALID_PARAMETER, "a NULL device");
    feel_unsubscribe_input(NULL); /* harmless */
    feel_close(dev);
}

int main(void) {
    test_device();
    test_input_subscription();
    test_library();
    if (c_check_failures) printf("%d check(s) failed\n", c_check_failures);
    else printf("all checks passed\n");
    return c_check_failures ? 1 : 0;
}
