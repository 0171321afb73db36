/* fuzz_batch.c: libFuzzer harness of the batch (v2/cylinder_isect_batch.h; `make fuzz V=2`).
 *
 * The oracle is the batch's contract: cyl?_batch_build gives the first error the scalar API gives
 * for the cylinders, and on a built batch cyl?_batch_nearest and cyl?_batch_any give exactly what
 * the loops of cyl?_intersect and cyl?_occluded over the cylinders give (index, t bits, return
 * value, errors). Any difference aborts. A CYL_TRUSTED ray that breaks that option's promises
 * (a non-finite o or d, d = 0, tmin > tmax) is not compared: both answers are unspecified.
 *
 * Built with CYL_NO_DOUBLE (fuzz_batch_float_only: the float API computed in float, as a
 * firmware builds it) the float API alone.
 *
 * Input: byte 0 picks the API (bit 0) and the option set (bits 1..3), byte 1 the number of
 * cylinders (0..47), byte 2 how the ray is aimed; then the values, 3 bytes each: a 16-bit
 * integer times 2^(e - 64) for e = byte % 128, or (byte >= 248) one of 0, -0, +-inf, NaN, a huge
 * and a tiny value. Missing bytes read as 0.
 */
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cylinder_isect_batch.h"

/* A broken contract: say which, then abort (libFuzzer keeps the input). */
static void fz_check(int ok, const char *what)
{
    if (!ok) fprintf(stderr, "fuzz_batch: %s differs from the scalar loop\n", what), abort();
}

typedef struct fz_in { const uint8_t *p; size_t n, at; } fz_in;
static uint8_t fz_byte(fz_in *in) { return in->at < in->n ? in->p[in->at++] : 0; }
static double fz_value(fz_in *in, double huge, double tiny)
{
    uint8_t e = fz_byte(in), hi = fz_byte(in), lo = fz_byte(in);
    static const double zero = 0.0;
    switch (e) {
    case 248: return 0.0;
    case 249: return -zero;
    case 250: return (double)INFINITY;
    case 251: return -(double)INFINITY;
    case 252: return (double)NAN;
    case 253: return hi & 1 ? -huge : huge;
    case 254: return hi & 1 ? -tiny : tiny;
    default: return ldexp((double)(int16_t)(uint16_t)(hi << 8 | lo), (int)(e % 128) - 64);
    }
}

static const unsigned fz_opts[8] = {0u, CYL_CAPS, CYL_CAPS | CYL_NO_TANGENT, CYL_NO_NORMAL | CYL_NO_ERRBOUND,
                                    CYL_CAPS | CYL_TRUSTED, CYL_CAPS | CYL_PRECISE, CYL_OUTWARD, 0x80u};

#define FZ_API(P, T, HUGE_, TINY_)                                                                    \
    /* an empty batch still reports the ray's and the options' errors (a valid cylinder's call's) */ \
    static int fz_ray_error_##P(const cyl##P##_ray *ray, unsigned opts)                               \
    {                                                                                                 \
        static const cyl##P##_cylinder unit = {{0, 0, 0}, {0, 0, 1}, 1, 1};                           \
        int rc = cyl##P##_occluded(ray, &unit, opts);                                                 \
        return rc < 0 ? rc : 0;                                                                       \
    }                                                                                                 \
    static void fz_##P(fz_in *in, unsigned opts, size_t n, uint8_t aim)                              \
    {                                                                                                 \
        static const cyl##P##_ray probe = {{0, 0, 0}, {1, 0, 0}, 0, 1};                              \
        cyl##P##_cylinder cy[48];                                                                     \
        cyl##P##_ray ray;                                                                             \
        cyl##P##_batch b;                                                                             \
        cyl##P##_hit h;                                                                               \
        size_t i, k, i1 = 7, i2 = 0;                                                                  \
        int want = 0, rc, r2 = 0, got = 0;                                                            \
        T t1 = 5, t2 = 0, t5 = 5;                                                                     \
        void *mem;                                                                                    \
        for (i = 0; i < n; i++) {                                                                     \
            for (k = 0; k < 3; k++) cy[i].c[k] = (T)fz_value(in, HUGE_, TINY_);                       \
            for (k = 0; k < 3; k++) cy[i].a[k] = (T)fz_value(in, HUGE_, TINY_);                       \
            cy[i].r = (T)fz_value(in, HUGE_, TINY_), cy[i].h = (T)fz_value(in, HUGE_, TINY_);           \
        }                                                                                             \
        for (k = 0; k < 3; k++) ray.o[k] = (T)fz_value(in, HUGE_, TINY_);                             \
        for (k = 0; k < 3; k++) ray.d[k] = (T)fz_value(in, HUGE_, TINY_);                             \
        ray.tmin = (T)fz_value(in, HUGE_, TINY_), ray.tmax = (T)fz_value(in, HUGE_, TINY_);            \
        if (aim & 1) ray.tmin = 0, ray.tmax = (T)INFINITY;                                           \
        if ((aim & 6) && n) { /* toward a cylinder's center, or along its axis */                    \
            const cyl##P##_cylinder *c = &cy[(aim >> 3) % n];                                         \
            for (k = 0; k < 3; k++) ray.d[k] = (aim & 2) ? c->c[k] - ray.o[k] : c->a[k];              \
        }                                                                                             \
        for (i = 0; i < n && want >= 0; i++) /* the first cylinder's error: want < 0 */               \
            want = cyl##P##_occluded(&probe, &cy[i], 0u);                                             \
        if (want > 0) want = 0;                                                                       \
        mem = malloc(cyl##P##_batch_bytes(n) + 1);                                                    \
        if (!mem) abort();                                                                            \
        rc = cyl##P##_batch_build(&b, (char *)mem + 1, cy, n);                                       \
        fz_check(rc == want, "build: the first cylinder's error, or 0");                              \
        /* CYL_TRUSTED on a ray that breaks its promises: unspecified, in the batch as in the call */ \
        if (rc == 0 && !((opts & CYL_TRUSTED) && fz_ray_error_##P(&ray, opts & ~CYL_TRUSTED))) {     \
            for (i = 0; i < n; i++) {                                                                 \
                int r = cyl##P##_intersect(&ray, &cy[i], opts, &h);                                   \
                if (r < 0) { r2 = r; break; }                                                         \
                if (r == CYL_HIT && (!got || h.t < t2)) i2 = i, t2 = h.t, got = 1;                    \
            }                                                                                         \
            if (!r2) r2 = got;                                                                        \
            if (!n) r2 = fz_ray_error_##P(&ray, opts);                                                \
            rc = cyl##P##_batch_nearest(&b, &ray, opts, &i1, &t1);                                   \
            fz_check(rc == r2, "nearest: the return value");                                                                    \
            fz_check(rc != CYL_HIT || (i1 == i2 && memcmp(&t1, &t2, sizeof t1) == 0), "nearest: index and t");            \
            fz_check(rc == CYL_HIT || (i1 == 7 && memcmp(&t1, &t5, sizeof t1) == 0), "nearest: untouched"); \
            for (r2 = 0, i = 0; i < n; i++)                                                           \
                if ((r2 = cyl##P##_occluded(&ray, &cy[i], opts)) != 0) break;                         \
            if (!n) r2 = fz_ray_error_##P(&ray, opts);                                                \
            fz_check(cyl##P##_batch_any(&b, &ray, opts) == r2, "any");                                   \
        }                                                                                             \
        free(mem);                                                                                    \
    }

FZ_API(f, float, 1e30, 1e-30)
#ifndef CYL_NO_DOUBLE
FZ_API(d, double, 1e200, 1e-200)
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size, 0};
    uint8_t sel = fz_byte(&in), n = fz_byte(&in), aim = fz_byte(&in);
    unsigned opts = fz_opts[(sel >> 1) & 7];
#ifdef CYL_NO_PRECISE
    if (opts & CYL_PRECISE) opts &= ~CYL_PRECISE;
#endif
#ifndef CYL_NO_DOUBLE
    if (sel & 1) fz_d(&in, opts, (size_t)(n % 48), aim);
    else
#endif
        fz_f(&in, opts, (size_t)(n % 48), aim);
    return 0;
}
