/* A C program built with `pkg-config --cflags --libs feel` against an installed libfeel.so
 * (scripts/test-install.sh): opens the in-process simulated I-FORCE 2.0 stick held by a
 * kinematic hand at x = -3000, plays an x spring from a parameter struct, and checks that
 * the force the device reports follows the spring law F = -k/10000 * x (§3.2) at the
 * position it reports. */
#include <math.h>
#include <stdio.h>

#include "feel/feel.h"

int main(void) {
    if (feel_version() != FEEL_VERSION) {
        fprintf(stderr, "libfeel %s but headers %s\n", feel_version_string(), FEEL_VERSION_STRING);
        return 1;
    }
    feel_open_options options;
    FEEL_INIT(options);
    options.sim_hand = "kinematic";
    options.sim_motion = "hold:-3000";
    feel_device* dev = feel_open_ex("sim:iforce2", &options);
    if (!dev) {
        fprintf(stderr, "feel_open_ex: %s\n", feel_last_error_message());
        return 1;
    }
    feel_effect_params p;
    FEEL_INIT(p);
    feel_effect_params_init(&p, FEEL_TYPE_SPRING);
    p.conditions[0].pos_coefficient = 8000;
    p.conditions[0].neg_coefficient = 8000;
    feel_effect* spring = feel_create_effect(dev, &p, NULL, 0);
    if (!spring || feel_effect_start(spring, FEEL_INFINITE_ITERATIONS, false) != FEEL_OK) {
        fprintf(stderr, "spring: %s\n", feel_last_error_message());
        return 1;
    }
    feel_input in;
    FEEL_INIT(in);
    for (int i = 0; i < 3000; ++i) { /* until the safety fade-in is complete */
        if (feel_wait_input(dev, 500, &in) != FEEL_OK) {
            fprintf(stderr, "feel_wait_input: %s\n", feel_last_error_message());
            return 1;
        }
        if (in.fade_level >= 1.0f && i > 20) break;
    }
    const double expected = -0.8 * in.position[0];
    printf("libfeel %s: x = %.0f, force = %.0f, spring law %.0f\n", feel_version_string(), (double)in.position[0],
           (double)in.force[0], expected);
    const int ok = in.position[0] < -2900 && fabs(in.force[0] - expected) < 30;
    feel_effect_destroy(spring);
    feel_close(dev);
    return ok ? 0 : 1;
}
