/* ff_spy: what a force-feedback program asked the kernel, written down as it asks.
 *
 * Preloaded (LD_PRELOAD) into the judges in the test VM (fftest, SDL2's testhaptic), it
 * wraps ioctl() and write() and, before passing each call on unchanged, logs to the file
 * named by $FF_SPY_LOG every
 *   EVIOCSFF   an effect upload: every field of struct ff_effect that its type uses
 *   EVIOCRMFF  an effect erase
 *   EV_FF      events written to the device: play/stop (code = effect id), FF_GAIN,
 *              FF_AUTOCENTER
 * with the CLOCK_MONOTONIC time, and after an EVIOCSFF the id the kernel gave and the
 * result. This is the checker's truth (tests/linux/check_device_log.cpp): the programs'
 * own requests, read from the calls they make, not from feel. It changes nothing.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <linux/input.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static FILE *spy_log(void)
{
    static FILE *f;
    if (!f) {
        const char *path = getenv("FF_SPY_LOG");
        if (!path) return NULL;
        f = fopen(path, "a");
        if (f) setvbuf(f, NULL, _IOLBF, 0);
    }
    return f;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void envelope(FILE *f, const struct ff_envelope *e)
{
    fprintf(f, " attack_length=%u attack_level=%u fade_length=%u fade_level=%u", e->attack_length,
            e->attack_level, e->fade_length, e->fade_level);
}

static void log_effect(FILE *f, double t, const struct ff_effect *e)
{
    fprintf(f, "%.6f upload id=%d type=0x%x direction=%u trigger_button=%u trigger_interval=%u length=%u delay=%u",
            t, e->id, e->type, e->direction, e->trigger.button, e->trigger.interval, e->replay.length,
            e->replay.delay);
    switch (e->type) {
    case FF_CONSTANT:
        fprintf(f, " level=%d", e->u.constant.level);
        envelope(f, &e->u.constant.envelope);
        break;
    case FF_RAMP:
        fprintf(f, " start_level=%d end_level=%d", e->u.ramp.start_level, e->u.ramp.end_level);
        envelope(f, &e->u.ramp.envelope);
        break;
    case FF_PERIODIC:
        fprintf(f, " waveform=0x%x period=%u magnitude=%d offset=%d phase=%u", e->u.periodic.waveform,
                e->u.periodic.period, e->u.periodic.magnitude, e->u.periodic.offset, e->u.periodic.phase);
        envelope(f, &e->u.periodic.envelope);
        break;
    case FF_SPRING:
    case FF_FRICTION:
    case FF_DAMPER:
    case FF_INERTIA:
        for (int a = 0; a < 2; ++a) {
            const struct ff_condition_effect *c = &e->u.condition[a];
            fprintf(f, " right_saturation%d=%u left_saturation%d=%u right_coeff%d=%d left_coeff%d=%d deadband%d=%u center%d=%d",
                    a, c->right_saturation, a, c->left_saturation, a, c->right_coeff, a, c->left_coeff, a,
                    c->deadband, a, c->center);
        }
        break;
    case FF_RUMBLE:
        fprintf(f, " strong_magnitude=%u weak_magnitude=%u", e->u.rumble.strong_magnitude,
                e->u.rumble.weak_magnitude);
        break;
    default: break;
    }
    fprintf(f, "\n");
}

int ioctl(int fd, unsigned long request, ...)
{
    static int (*real_ioctl)(int, unsigned long, ...);
    if (!real_ioctl) real_ioctl = (int (*)(int, unsigned long, ...))dlsym(RTLD_NEXT, "ioctl");
    va_list ap;
    va_start(ap, request);
    void *arg = va_arg(ap, void *);
    va_end(ap);
    FILE *f = spy_log();
    const double t = now_s();
    if (f && request == EVIOCSFF) log_effect(f, t, (const struct ff_effect *)arg);
    const int r = real_ioctl(fd, request, arg);
    const int saved = errno;
    if (f && request == EVIOCSFF) {
        fprintf(f, "%.6f uploaded id=%d result=%d errno=%d\n", now_s(), ((const struct ff_effect *)arg)->id, r,
                r < 0 ? saved : 0);
    }
    if (f && request == EVIOCRMFF) fprintf(f, "%.6f erase id=%ld result=%d\n", t, (long)arg, r);
    errno = saved;
    return r;
}

ssize_t write(int fd, const void *buf, size_t count)
{
    static ssize_t (*real_write)(int, const void *, size_t);
    if (!real_write) real_write = (ssize_t(*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
    FILE *f = spy_log();
    if (f && count >= sizeof(struct input_event) && count % sizeof(struct input_event) == 0) {
        const struct input_event *ev = buf;
        for (size_t i = 0; i < count / sizeof(struct input_event); ++i) {
            if (ev[i].type != EV_FF) continue;
            if (ev[i].code == FF_GAIN) {
                fprintf(f, "%.6f gain value=%d\n", now_s(), ev[i].value);
            } else if (ev[i].code == FF_AUTOCENTER) {
                fprintf(f, "%.6f autocenter value=%d\n", now_s(), ev[i].value);
            } else {
                fprintf(f, "%.6f play id=%u value=%d\n", now_s(), ev[i].code, ev[i].value);
            }
        }
    }
    return real_write(fd, buf, count);
}
