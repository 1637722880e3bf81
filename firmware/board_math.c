/* The board's double sin, cos, exp and expm1 (issue 14, flash).
 *
 * Design. The engine calls these four in double where the dynamics need exactness (the
 * control laws' exact step, their propagators, directions: docs/dynamics.md). newlib's
 * versions are built for every argument a double can hold: its sin and cos reduce
 * arguments up to 10^308 with 1200 bits of 2/pi (__kernel_rem_pio2), and with exp and
 * expm1 they take 8.3 KB of the board's flash. The engine's arguments are small (angles
 * of one turn, a frequency times a piece of one tick, a rate times a tick), so these
 * reduce with short splits of the constants and evaluate Taylor polynomials, in about a
 * tenth of the bytes:
 *
 *   sin, cos   x = k*pi/2 + r with pi/2 in three parts (33 + 33 + 53 bits: k*part is exact
 *              for |k| < 2^20, so r is right to about one unit in its last place for
 *              |x| < 2^20); sin r and cos r by their series to r^17 and r^18 (|r| <= pi/4:
 *              the next term is below 2^-60). Larger arguments are reduced 19 bits at a
 *              time, as accurately as pi/2's 119 bits allow: far beyond 2^20 not to the
 *              last place, but always to a finite result within [-1, 1] (the engine never
 *              passes such an argument).
 *   exp        x = k*ln2 + r, ln2 in two parts (k*ln2's high part exact for |k| < 2^21),
 *              |r| <= ln2/2, e^r by its series to r^13, times 2^k.
 *   expm1      for |x| <= ln2/2 its series x + x^2/2! + ... to x^15 (no cancellation:
 *              expm1 of a tiny x is x to full precision); beyond, 2^k*(1 + expm1 r) - 1
 *              arranged so that the only cancellation is the exact 2^k - 1.
 *
 * Each result is within 2 units in the last place of the true value (measured against
 * glibc's, which are within 1: tests/firmware/board_math_test.cpp). The board's forces
 * differ from the x86 build's (glibc) by these last bits, as they did with newlib's, and
 * the 1-unit comparison of make test bounds what that does to a force.
 *
 * Each function is in a section of its own (-ffunction-sections) and the link collects
 * unreferenced sections (--gc-sections): a function no engine code calls is not in the
 * image (since the control laws compute in float, issue 14, their callers are the paddle's
 * double step, the slings, directions, texture and contact surfaces; docs/firmware.md).
 *
 * IEEE special values: NaN in, NaN out; sin and cos of an infinity are NaN; exp(+inf) is
 * +inf and exp(-inf) 0; expm1(-inf) is -1; overflow gives +inf, underflow 0 (or a
 * subnormal, rounded twice). errno is not set (the engine does not read it). */
#include "board_math.h"

#include <stdint.h>

typedef union {
    double d;
    uint64_t u;
} DoubleBits;

static double from_bits(uint64_t u) {
    DoubleBits v;
    v.u = u;
    return v.d;
}

static uint64_t bits_of(double d) {
    DoubleBits v;
    v.d = d;
    return v.u;
}

static int is_nan_or_inf(double x) { return ((bits_of(x) >> 52) & 0x7ff) == 0x7ff; }

/* y * 2^k for any int k in -2200..2200 (subnormal results are rounded twice). */
static double times_pow2(double y, int k) {
    while (k > 1000) {
        y *= 0x1p1000;
        k -= 1000;
    }
    while (k < -1000) {
        y *= 0x1p-1000;
        k += 1000;
    }
    return y * from_bits((uint64_t)(k + 1023) << 52);
}

/* The nearest integer to v, |v| < 2^31. */
static int nearest(double v) { return (int)(v < 0 ? v - 0.5 : v + 0.5); }

/* --- sin and cos ------------------------------------------------------------------ */

static const double kPio2High = 0x1.921fb544p+0;      /* pi/2 to 33 bits */
static const double kPio2Mid = 0x1.0b4611a6p-34;      /* the next 33 bits */
static const double kPio2Low = 0x1.3198a2e037073p-69; /* the next 53 bits */
static const double kTwoOverPi = 0x1.45f306dc9c883p-1;

/* c[0] + z*(c[1] + z*(... + z*c[n-1])): one loop instead of the nested expression written
 * out (each double operation is a call on the board: the loop is a third of the bytes, the
 * same operations in the same order). */
static double horner(const double* c, int n, double z) {
    double p = c[n - 1];
    for (int i = n - 2; i >= 0; --i) p = c[i] + z * p;
    return p;
}

/* sin r for |r| <= pi/4: r + r^3 * (-1/3! + r^2/5! - ... + r^14/17!). */
static const double kSinSeries[] = {-1.0 / 6,           1.0 / 120,           -1.0 / 5040,
                                    1.0 / 362880,       -1.0 / 39916800,     1.0 / 6227020800.0,
                                    -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};

static double sin_reduced(double r) {
    const double z = r * r;
    return r + r * z * horner(kSinSeries, 8, z);
}

/* cos r for |r| <= pi/4: 1 - r^2/2 + r^4 * (1/4! - r^2/6! + ... + r^14/18!), with the
 * rounding of 1 - r^2/2 carried into the small terms. */
static const double kCosSeries[] = {1.0 / 24,           -1.0 / 720,          1.0 / 40320,
                                    -1.0 / 3628800,     1.0 / 479001600.0,   -1.0 / 87178291200.0,
                                    1.0 / 20922789888000.0, -1.0 / 6402373705728000.0};

static double cos_reduced(double r) {
    const double z = r * r;
    const double half = 0.5 * z;
    const double w = 1.0 - half;
    return w + (((1.0 - w) - half) + z * z * horner(kCosSeries, 8, z));
}

/* x - dk * pi/2, for a dk of at most 20 significant bits: dk * kPio2High and dk * kPio2Mid
 * are exact, and so is x - dk * kPio2High when it is the nearest such multiple. */
static double minus_quarter_turns(double x, double dk) {
    return ((x - dk * kPio2High) - dk * kPio2Mid) - dk * kPio2Low;
}

/* x = (quadrant + 4n) * pi/2 + *r, |*r| <= pi/4 (to a few units in its last place). */
static int reduce_quadrant(double x, double* r) {
    int quadrant = 0;
    /* Beyond 2^20 the multiple is taken off 19 bits at a time (its top 20 bits, so that the
     * products above stay exact): a few steps for any finite x. Each step is as accurate as
     * pi/2's 119 bits allow, which for x far beyond 2^20 is not to the last place. */
    while (x > 0x1p20 || x < -0x1p20) {
        const double dk = from_bits(bits_of(x * kTwoOverPi) & ~((UINT64_C(1) << 33) - 1));
        if (dk > -0x1p53 && dk < 0x1p53) quadrant += (int)((int64_t)dk & 3); /* else a multiple of 4 */
        x = minus_quarter_turns(x, dk);
    }
    const int k = nearest(x * kTwoOverPi);
    *r = minus_quarter_turns(x, (double)k);
    return (quadrant + k) & 3;
}

double feel_board_sin(double x) {
    if (is_nan_or_inf(x)) return x - x;
    if (x > -0x1p-27 && x < 0x1p-27) return x; /* sin x = x - x^3/6: below half a unit */
    double r;
    switch (reduce_quadrant(x, &r)) {
        case 0: return sin_reduced(r);
        case 1: return cos_reduced(r);
        case 2: return -sin_reduced(r);
        default: return -cos_reduced(r);
    }
}

double feel_board_cos(double x) {
    if (is_nan_or_inf(x)) return x - x;
    if (x > -0x1p-27 && x < 0x1p-27) return 1.0;
    double r;
    switch (reduce_quadrant(x, &r)) {
        case 0: return cos_reduced(r);
        case 1: return -sin_reduced(r);
        case 2: return -cos_reduced(r);
        default: return sin_reduced(r);
    }
}

/* --- exp and expm1 ---------------------------------------------------------------- */

static const double kLn2High = 0x1.62e42ffp-1;           /* ln 2 to 32 bits */
static const double kLn2Low = -0x1.718432a1b0e26p-35;    /* the next 53 bits */
static const double kInvLn2 = 0x1.71547652b82fep+0;
static const double kExpOverflow = 0x1.62e42fefa39efp+9; /* ln of the largest double */
static const double kExpUnderflow = -0x1.74910d52d3052p+9; /* ln 2^-1075 */

/* e^r - 1 for |r| <= ln2/2 (0.347): r + r^2 * (1/2! + r/3! + ... + r^13/15!). */
static const double kExpm1Series[] = {1.0 / 2,         1.0 / 6,          1.0 / 24,           1.0 / 120,
                                      1.0 / 720,       1.0 / 5040,       1.0 / 40320,        1.0 / 362880,
                                      1.0 / 3628800,   1.0 / 39916800,   1.0 / 479001600.0,  1.0 / 6227020800.0,
                                      1.0 / 87178291200.0, 1.0 / 1307674368000.0};

static double expm1_reduced(double r) { return r + r * r * horner(kExpm1Series, 14, r); }

/* x = k*ln2 + *r. */
static int reduce_ln2(double x, double* r) {
    const int k = nearest(x * kInvLn2);
    const double dk = (double)k;
    *r = (x - dk * kLn2High) - dk * kLn2Low;
    return k;
}

double feel_board_exp(double x) {
    if (x != x) return x;
    if (x > kExpOverflow) return 0x1p1023 * 2.0; /* +inf */
    if (x < kExpUnderflow) return 0.0;
    double r;
    const int k = reduce_ln2(x, &r);
    return times_pow2(1.0 + expm1_reduced(r), k);
}

double feel_board_expm1(double x) {
    if (x != x) return x;
    if (x > kExpOverflow) return 0x1p1023 * 2.0;
    if (x < -40.0) return -1.0; /* e^x below 2^-57: -1 to the last bit */
    if (x > -0x1p-54 && x < 0x1p-54) return x; /* x + x^2/2: below half a unit; keeps -0 */
    if (x >= -0.34657359027997264 && x <= 0.34657359027997264) return expm1_reduced(x);
    double r;
    const int k = reduce_ln2(x, &r);
    const double e = expm1_reduced(r);
    if (k > 53) return times_pow2(1.0 + e, k); /* the -1 is below the last place */
    const double t = from_bits((uint64_t)(k + 1023) << 52); /* 2^k, exact; -58 <= k <= 53 */
    return (t - 1.0) + t * e; /* t - 1 is exact for k >= -53; below, the result is -1 */
}
