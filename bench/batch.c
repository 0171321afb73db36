/* batch.c: one ray against N cylinders, the batch against the scalar loop (`make bench-batch`).
 *
 *   build/bench-batch/batch-KEY [--runs R] [--tests M]
 *
 * For float and double and N = 1024, 4096, 65536 and 2^20: a scene of N capped cylinders
 * (seeded; centers uniform in a cube whose side grows as N^(1/3), so the density stays; radii
 * 0.5 to 2, heights 2 to 10, axes uniform), rays from uniform points of the cube in uniform
 * directions, tmin 0, tmax infinite. Timed, per ray: the loop a user writes without the batch
 * (cyl?_intersect on every cylinder with CYL_CAPS, keeping the smallest t) and
 * cyl?_batch_nearest(.., CYL_CAPS, ..); about M tests (rays × N) per timing, the median of R
 * timings. Both answers are compared ray by ray (index and t): a difference stops the run.
 * Prints one markdown row per precision and N: KEY (the build: its flags and the batch's
 * vector or portable form), ns per test, tests per second, and for the batch its speed-up
 * over the scalar loop of the same binary.
 */
#define _POSIX_C_SOURCE 199309L
#include "cylinder_isect_batch.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static uint64_t rng_state;
static double rnd(void)
{
    rng_state = rng_state * 6364136223846793005u + 1442695040888963407u;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}
static void unit_dir(double v[3])
{
    double n;
    do v[0] = 2 * rnd() - 1, v[1] = 2 * rnd() - 1, v[2] = 2 * rnd() - 1, n = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    while (n > 1 || n < 1e-4);
    n = sqrt(n), v[0] /= n, v[1] /= n, v[2] /= n;
}
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

#if defined(__GNUC__) || defined(__clang__)
#define BENCH_NOINLINE __attribute__((noinline))
#else
#define BENCH_NOINLINE
#endif

static const char *key = "?";
static int runs = 5;
static double tests = 4e6;

/* One precision's measurement, written once: P is f or d, T its type. */
#define BENCH(P, T)                                                                                   \
    static int loop_##P(const cyl##P##_ray *ray, const cyl##P##_cylinder *cy, size_t n, size_t *idx, T *t) \
    {                                                                                                 \
        cyl##P##_hit h;                                                                               \
        size_t i;                                                                                     \
        int got = 0;                                                                                  \
        for (i = 0; i < n; i++)                                                                       \
            if (cyl##P##_intersect(ray, &cy[i], CYL_CAPS, &h) == CYL_HIT && (!got || h.t < *t))       \
                *idx = i, *t = h.t, got = 1;                                                          \
        return got;                                                                                   \
    }                                                                                                 \
    /* The timed loops, each a function of its own (noinline), as a renderer's call site: what the \
       compiler makes of it does not depend on the checking code around it. */                      \
    BENCH_NOINLINE static double time_loop_##P(const cyl##P##_ray *rays, size_t nr, const cyl##P##_cylinder *cy, size_t n) \
    {                                                                                                 \
        double sum = 0;                                                                               \
        size_t r, ii = 0;                                                                             \
        T tt = 0;                                                                                     \
        for (r = 0; r < nr; r++) sum += loop_##P(&rays[r], cy, n, &ii, &tt) + (double)tt;             \
        return sum;                                                                                   \
    }                                                                                                 \
    BENCH_NOINLINE static double time_batch_##P(const cyl##P##_ray *rays, size_t nr, const cyl##P##_batch *b) \
    {                                                                                                 \
        double sum = 0;                                                                               \
        size_t r, ii = 0;                                                                             \
        T tt = 0;                                                                                     \
        for (r = 0; r < nr; r++) sum += cyl##P##_batch_nearest(b, &rays[r], CYL_CAPS, &ii, &tt) + (double)tt; \
        return sum;                                                                                   \
    }                                                                                                 \
    static void bench_##P(size_t n)                                                                   \
    {                                                                                                 \
        const double side = 10 * cbrt((double)n);                                                    \
        size_t nr = (size_t)(tests / (double)n) < 8 ? 8 : (size_t)(tests / (double)n), i, r, k, hits = 0; \
        cyl##P##_cylinder *cy = (cyl##P##_cylinder *)malloc(n * sizeof *cy);                          \
        cyl##P##_ray *rays = (cyl##P##_ray *)malloc(nr * sizeof *rays);                               \
        void *mem = malloc(cyl##P##_batch_bytes(n));                                                  \
        double tl[64], tb[64], v[3], t0;                                                              \
        volatile double sink = 0;                                                                     \
        cyl##P##_batch b;                                                                             \
        if (!cy || !rays || !mem) { fprintf(stderr, "out of memory\n"); exit(1); }                   \
        rng_state = 20261207u + n;                                                                    \
        for (i = 0; i < n; i++) {                                                                     \
            for (k = 0; k < 3; k++) cy[i].c[k] = (T)((rnd() - 0.5) * side);                            \
            unit_dir(v);                                                                              \
            for (k = 0; k < 3; k++) cy[i].a[k] = (T)v[k];                                              \
            cy[i].r = (T)(0.5 + 1.5 * rnd()), cy[i].h = (T)(2 + 8 * rnd());                           \
        }                                                                                             \
        for (r = 0; r < nr; r++) {                                                                    \
            for (k = 0; k < 3; k++) rays[r].o[k] = (T)((rnd() - 0.5) * side);                          \
            unit_dir(v);                                                                              \
            for (k = 0; k < 3; k++) rays[r].d[k] = (T)v[k];                                            \
            rays[r].tmin = 0, rays[r].tmax = (T)INFINITY;                                             \
        }                                                                                             \
        if (cyl##P##_batch_build(&b, mem, cy, n) != 0) { fprintf(stderr, "build failed\n"); exit(1); } \
        for (r = 0; r < nr; r++) { /* the same answers, ray by ray */                                 \
            size_t i1 = 0, i2 = 0;                                                                    \
            T t1 = 0, t2 = 0;                                                                         \
            int r1 = cyl##P##_batch_nearest(&b, &rays[r], CYL_CAPS, &i1, &t1);                       \
            int r2 = loop_##P(&rays[r], cy, n, &i2, &t2);                                             \
            if (r1 != r2 || (r1 == 1 && (i1 != i2 || memcmp(&t1, &t2, sizeof t1) != 0))) {            \
                fprintf(stderr, "batch and loop differ (ray %zu, n %zu)\n", r, n);                    \
                exit(1);                                                                              \
            }                                                                                         \
            hits += (size_t)r1;                                                                       \
        }                                                                                             \
        for (k = 0; k < (size_t)runs; k++) {                                                          \
            t0 = now();                                                                               \
            sink += time_loop_##P(rays, nr, cy, n);                                                   \
            tl[k] = (now() - t0) / (double)(nr * n) * 1e9;                                            \
            t0 = now();                                                                               \
            sink += time_batch_##P(rays, nr, &b);                                                     \
            tb[k] = (now() - t0) / (double)(nr * n) * 1e9;                                            \
        }                                                                                             \
        qsort(tl, (size_t)runs, sizeof tl[0], cmp_double), qsort(tb, (size_t)runs, sizeof tb[0], cmp_double); \
        printf("| %s | %s | %zu | %zu | %.0f%% | %.2f | %.3g | %.2f | %.3g | %.1fx |\n", key, #T, n, nr, \
               100.0 * (double)hits / (double)nr, tl[runs / 2], 1e9 / tl[runs / 2], tb[runs / 2],     \
               1e9 / tb[runs / 2], tl[runs / 2] / tb[runs / 2]);                                      \
        fflush(stdout);                                                                               \
        free(cy), free(rays), free(mem);                                                              \
        (void)sink;                                                                                   \
    }
BENCH(f, float)
BENCH(d, double)

int main(int argc, char **argv)
{
    static const size_t ns[] = {1024, 4096, 65536, 1048576};
    size_t i;
    int a;
    for (a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--runs") && a + 1 < argc) runs = atoi(argv[++a]);
        else if (!strcmp(argv[a], "--tests") && a + 1 < argc) tests = atof(argv[++a]);
        else if (!strcmp(argv[a], "--key") && a + 1 < argc) key = argv[++a];
        else {
            fprintf(stderr, "usage: %s [--key KEY] [--runs R] [--tests M]\n", argv[0]);
            return 2;
        }
    }
    if (runs < 1 || runs > 64) runs = 5;
    for (i = 0; i < sizeof ns / sizeof ns[0]; i++) bench_f(ns[i]);
    for (i = 0; i < sizeof ns / sizeof ns[0]; i++) bench_d(ns[i]);
    return 0;
}
