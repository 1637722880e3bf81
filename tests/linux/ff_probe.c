/* ff_probe: the measurements of docs/usb-device.md ("Measured"), run in the test VM as a
 * game would, through evdev and the kernel's hid-pidff:
 *
 *   ff_probe EVENT latency N     N trials of: upload a constant force (EVIOCSFF) and play
 *                                it; print the CLOCK_MONOTONIC time before the upload. The
 *                                host side finds the first motor tick with that force in
 *                                feel's device log (same clock) and takes the difference.
 *   ff_probe EVENT flood SECONDS update one effect's level as fast as the kernel takes it
 *                                (each EVIOCSFF is a Set Constant Force report), while feel
 *                                logs its loop rate; prints how many updates went out.
 *   ff_probe EVENT invalid 0     uploads ff_effects a device cannot play (`feel bridge`:
 *                                docs/real-devices.md, "Errors"), then a valid one; prints
 *                                each EVIOCSFF's result and errno.
 */
#include <errno.h>
#include <fcntl.h>
#include <linux/input.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void sleep_s(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    nanosleep(&ts, NULL);
}

static struct ff_effect constant(short level, unsigned short length_ms)
{
    struct ff_effect e;
    memset(&e, 0, sizeof e);
    e.type = FF_CONSTANT;
    e.id = -1;
    e.direction = 0x4000;
    e.u.constant.level = level;
    e.replay.length = length_ms;
    return e;
}

static int play(int fd, int id, int value)
{
    struct input_event ev;
    memset(&ev, 0, sizeof ev);
    ev.type = EV_FF;
    ev.code = (unsigned short)id;
    ev.value = value;
    return write(fd, &ev, sizeof ev) == (ssize_t)sizeof ev ? 0 : -1;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: ff_probe EVENT latency N | ff_probe EVENT flood SECONDS\n");
        return 2;
    }
    const int fd = open(argv[1], O_RDWR);
    if (fd < 0) {
        perror(argv[1]);
        return 1;
    }
    if (strcmp(argv[2], "latency") == 0) {
        const int n = atoi(argv[3]);
        srand(1);
        for (int k = 0; k < n; ++k) {
            struct ff_effect e = constant(0x6000, 150);
            const double start = now_s();
            if (ioctl(fd, EVIOCSFF, &e) < 0 || play(fd, e.id, 1) < 0) {
                perror("upload and play");
                return 1;
            }
            const double played = now_s();
            printf("latency trial=%d start=%.6f played=%.6f\n", k, start, played);
            sleep_s(0.35);  /* the effect ends after 150 ms; the motors rest again */
            ioctl(fd, EVIOCRMFF, e.id);
            sleep_s(0.05 + (double)(rand() % 1000) * 1e-5);  /* a random phase against the 1 ms tick */
        }
    } else if (strcmp(argv[2], "invalid") == 0) {
        struct ff_effect cases[5];
        const char *names[5] = {"periodic_period_0", "endless_ramp", "envelope_level_0x8000", "trigger_not_a_button",
                                "valid_constant"};
        cases[0] = constant(0, 1000);
        cases[0].type = FF_PERIODIC;
        cases[0].u.periodic.waveform = FF_SINE;
        cases[0].u.periodic.period = 0;
        cases[0].u.periodic.magnitude = 0x4000;
        cases[1] = constant(0, 0);
        cases[1].type = FF_RAMP;
        cases[1].u.ramp.start_level = 0x1000;
        cases[2] = constant(0x1000, 1000);
        cases[2].u.constant.envelope.attack_level = 0x8000;
        cases[3] = constant(0x1000, 1000);
        cases[3].trigger.button = 0x6269;
        cases[4] = constant(0x1000, 1000);
        for (int k = 0; k < 5; ++k) {
            const int r = ioctl(fd, EVIOCSFF, &cases[k]);
            printf("invalid case=%s result=%d errno=%d\n", names[k], r, r < 0 ? errno : 0);
            if (r == 0) ioctl(fd, EVIOCRMFF, cases[k].id);
        }
    } else if (strcmp(argv[2], "flood") == 0) {
        const double seconds = atof(argv[3]);
        struct ff_effect e = constant(0x1000, 0);
        if (ioctl(fd, EVIOCSFF, &e) < 0 || play(fd, e.id, 1) < 0) {
            perror("upload and play");
            return 1;
        }
        const double start = now_s();
        long updates = 0;
        while (now_s() - start < seconds) {
            e.u.constant.level = (short)(0x1000 + (updates % 64) * 0x100);
            if (ioctl(fd, EVIOCSFF, &e) < 0) break;
            ++updates;
        }
        printf("flood start=%.6f end=%.6f updates=%ld\n", start, now_s(), updates);
        play(fd, e.id, 0);
        ioctl(fd, EVIOCRMFF, e.id);
    }
    close(fd);
    return 0;
}
