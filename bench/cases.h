/* cases.h: reproducible stiff and extreme ray/cylinder case families for the benchmark, the
 * accuracy test and the fuzzer's seeds. Every case is a pure function of (family, prec, seed,
 * index): bench_case_gen(BF_GRAZING, 24, 42, 17, &k) is the same case on every machine.
 *
 * Values are generated in double, then (prec == 24) rounded to float, so a float case holds
 * exactly the float inputs the float routines see; the exact reference works on those values.
 * The cylinder geometry and the ray are generated; caps on/off is a variant applied by the
 * caller (every case is run both ways). */
#ifndef BENCH_CASES_H
#define BENCH_CASES_H

#include <stdint.h>

enum bench_family {
    BF_WELL,       /* well-conditioned random: origin 2..10 r away, aimed near the cylinder */
    BF_FAR,        /* origin far away: |o - c| from 1e2 r to 1e7 r */
    BF_PARALLEL,   /* angle between d and the axis 1e-1 .. 1e-12 */
    BF_GRAZING,    /* ray-axis distance r (1 +- 10^-k), k = 1..15 */
    BF_THIN,       /* thin and long: r/h from 1e-2 down to 1e-8 */
    BF_SURFACE,    /* origin on the surface (rounded), tmin = 0: secondary rays */
    BF_HUGE,       /* a well case scaled by 2^50 (float) / 2^400 (double) */
    BF_TINY,       /* a well case scaled by 2^-50 (float) / 2^-400 (double) */
    BF_AXIS,       /* axis-aligned exact cases: small integers, exact tangencies and rims */
    BF_TRANGE,     /* tmin or tmax within a relative 10^-k (k = 1..15) of a hit */
    BF_FLAT,       /* flat disks (r/h 1e2 .. 1e9), origin exactly on the wall near a rim but
                      for 2^-12 .. 2^-40 (2^-60) r, ray nearly parallel to the axis (1e-1 ..
                      6e-8 float, 1.3e-16 double): the rim decision amplifies C's rounding by
                      about r/(h sin) (fuzz finding 32) */
    BF_COUNT
};

typedef struct bench_case {
    double o[3], d[3], tmin, tmax;  /* ray */
    double c[3], a[3], r, h;        /* cylinder (h may be +INFINITY) */
    int family;
} bench_case;

const char *bench_family_name(int family);
/* The family of that name ("well", "far", ...), or BF_COUNT for none (command lines). */
int bench_family_index(const char *name);

/* Fills *out with case number index of the family, in precision prec (24 or 53). */
void bench_case_gen(int family, int prec, uint64_t seed, uint64_t index, bench_case *out);

/* The generator itself, exposed for other uses: splitmix64 (Steele, Lea and Flood 2014). */
uint64_t bench_rng_next(uint64_t *state);
double bench_rng_unit(uint64_t *state);   /* uniform in [0, 1) with 53 random bits */

#endif
