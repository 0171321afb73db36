/* batch.c: the batch queries of cylinder_isect_batch.h against the scalar calls they stand for.
 *
 * Compiled as it is it tests cylf_batch_*; with -DT_DOUBLE, cyld_batch_*. The contract is exact
 * agreement: cyl?_batch_nearest gives what a loop of cyl?_intersect over the cylinders in index
 * order keeping the smallest t (the lowest index among equal ones) gives, the same t bits;
 * cyl?_batch_any what a loop of cyl?_occluded gives; errors the scalar ones, nothing written.
 * So every check here compares with ==: sameness with the scalar call is the property under
 * test. The scenes are seeded random ones with the hard cases mixed in: origins inside and on
 * the surface, rays parallel and perpendicular to axes, grazing rays, tmin and tmax on a
 * crossing, cylinders and rays outside the filter's range, batch sizes around the block width.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "cylinder_isect_batch.h"

/* Only the 512-bit form (CYL_BATCH_VECTOR_BYTES 64) may include <immintrin.h>, whose parsing costs
   every unit that includes the batch's header (gcc's guard, then clang's). */
#if !(defined(CYL_BATCH_VECTOR_BYTES) && CYL_BATCH_VECTOR_BYTES == 64) && \
    (defined(_IMMINTRIN_H_INCLUDED) || defined(__IMMINTRIN_H))
#error "cylinder_isect_batch.h included <immintrin.h> outside its 512-bit form"
#endif

#ifdef T_DOUBLE
#define T double
#define CYL(x) cyld_##x
#define BATCH(x) cyl__db_##x /* the batch's internals, for the tests of its filter */
#define T_HUGE 1e200 /* beyond the filter's range (2^100): such cylinders are always asked */
#define TANG_TOL CYL_TANGENT_TOL
#define T_TINY_R 1e-250 /* r below the filter's range (2^-100) */
#else
#define T float
#define CYL(x) cylf_##x
#define BATCH(x) cyl__fb_##x
#define T_HUGE 1e30f /* beyond the filter's range (2^32) */
#define TANG_TOL (double)CYL_TANGENT_TOLF
#define T_TINY_R 1e-20f /* r below the filter's range (2^-32) */
#endif

void setUp(void) {}
void tearDown(void) {}

/* x == y, for the values this file knows are exact (no -Wfloat-equal: the point is exactness) */
static int eq(T x, T y) { return !(x < y) && !(x > y); }

/* ------------------------------------------------------------------ random scenes */
static uint64_t rng_state;
static double rnd(void) /* uniform in [0, 1) */
{
    rng_state = rng_state * 6364136223846793005u + 1442695040888963407u;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}
static T uni(double lo, double hi) { return (T)(lo + (hi - lo) * rnd()); }

static void unit_dir(T v[3])
{
    double x, y, z, n;
    do x = 2 * rnd() - 1, y = 2 * rnd() - 1, z = 2 * rnd() - 1, n = x * x + y * y + z * z; while (n > 1 || n < 1e-4);
    n = sqrt(n), v[0] = (T)(x / n), v[1] = (T)(y / n), v[2] = (T)(z / n);
}

/* A scene of n cylinders in a box of half side L: a quarter with axes along a coordinate axis
   exactly, some infinite, a few of radius far below their distance (thin: hair). */
static void scene(CYL(cylinder) *cy, size_t n, double L)
{
    size_t i;
    int k;
    for (i = 0; i < n; i++) {
        for (k = 0; k < 3; k++) cy[i].c[k] = uni(-L, L);
        if (rnd() < 0.25) {
            k = (int)(rnd() * 3);
            cy[i].a[0] = cy[i].a[1] = cy[i].a[2] = 0, cy[i].a[k] = rnd() < 0.5 ? 1 : -2;
        } else unit_dir(cy[i].a);
        if (rnd() < 0.3) cy[i].a[0] *= 3, cy[i].a[1] *= 3, cy[i].a[2] *= 3; /* a of any length */
        cy[i].r = rnd() < 0.1 ? uni(1e-4, 1e-3) * (T)L : uni(0.01, 0.08) * (T)L;
        cy[i].h = rnd() < 0.1 ? (T)INFINITY : uni(0.02, 0.5) * (T)L;
    }
}

/* Unit u, v perpendicular to c's axis and to each other (in double). */
static void frame(const CYL(cylinder) *c, double u[3], double v[3])
{
    double a[3], p = 0, q = 0, an = 0;
    int k;
    for (k = 0; k < 3; k++) a[k] = (double)c->a[k], an += a[k] * a[k];
    do {
        for (k = 0, p = 0; k < 3; k++) u[k] = 2 * rnd() - 1, p += u[k] * a[k];
        for (k = 0, q = 0; k < 3; k++) u[k] -= p / an * a[k], q += u[k] * u[k];
    } while (q < 1e-6);
    for (k = 0; k < 3; k++) u[k] /= sqrt(q);
    an = sqrt(an);
    v[0] = (a[1] * u[2] - a[2] * u[1]) / an, v[1] = (a[2] * u[0] - a[0] * u[2]) / an, v[2] = (a[0] * u[1] - a[1] * u[0]) / an;
}

/* A ray aimed at cylinder j of the scene in one of several hard ways, else random. */
static CYL(ray) ray_for(const CYL(cylinder) *cy, size_t n, double L, unsigned opts)
{
    CYL(ray) ray;
    const CYL(cylinder) *c = &cy[(size_t)(rnd() * (double)n) % (n ? n : 1)];
    double kind = rnd();
    int k;
    unit_dir(ray.d), ray.tmin = 0, ray.tmax = (T)INFINITY;
    for (k = 0; k < 3; k++) ray.o[k] = uni(-1.5 * L, 1.5 * L);
    if (!n) return ray;
    if (kind < 0.15) /* from the center of a cylinder: inside */
        for (k = 0; k < 3; k++) ray.o[k] = c->c[k];
    else if (kind < 0.3) /* along the axis of one, exactly */
        for (k = 0; k < 3; k++) ray.d[k] = rnd() < 0.5 ? c->a[k] : -c->a[k];
    else if (kind < 0.45) { /* toward its center: crosses it */
        for (k = 0; k < 3; k++) ray.d[k] = c->c[k] - ray.o[k];
    } else if (kind < 0.55) { /* perpendicular to a coordinate axis (d_z = 0) */
        ray.d[2] = 0;
        if (eq(ray.d[0], 0) && eq(ray.d[1], 0)) ray.d[0] = 1;
    } else if (kind < 0.65) { /* toward a point at distance r from the axis: crosses there */
        double u[3], v[3];
        frame(c, u, v);
        for (k = 0; k < 3; k++) ray.d[k] = (T)((double)c->c[k] + u[k] * (double)c->r - (double)ray.o[k]);
    } else if (kind < 0.8) { /* grazing: a line at distance r(1 + eps) from the axis, eps at the tangent band's edges */
        static const double eps[] = {0, 1e-3, -1e-3, 9.5367431640625e-07, -9.5367431640625e-07, 9.094947017729282e-13, -9.094947017729282e-13};
        double u[3], v[3], an = 0, rho, beta = rnd() < 0.5 ? 0 : (double)uni(-0.3, 0.3), z = (double)uni(-0.6, 0.6) * (double)c->h;
        double e = rnd() < 0.5 ? eps[(int)(rnd() * 7)] : (TANG_TOL / 2) * (rnd() < 0.5 ? 1 : -1) * (1 + (double)uni(-1e-3, 1e-3));
        frame(c, u, v);
        for (k = 0; k < 3; k++) an += (double)c->a[k] * (double)c->a[k];
        an = sqrt(an), rho = (double)c->r * (1 + e);
        if (!(z < 1e30 && z > -1e30)) z = 0; /* an infinite tube */
        for (k = 0; k < 3; k++)
            ray.o[k] = (T)((double)c->c[k] + rho * u[k] - 5 * (double)c->r * v[k] + z * (double)c->a[k] / an),
            ray.d[k] = (T)(v[k] + beta * (double)c->a[k] / an);
    }
    if (eq(ray.d[0], 0) && eq(ray.d[1], 0) && eq(ray.d[2], 0)) ray.d[0] = 1;
    if (rnd() < 0.2) { /* tmin or tmax exactly on a crossing of some cylinder */
        CYL(hit) h;
        if (CYL(intersect)(&ray, c, opts, &h) == CYL_HIT) {
            if (rnd() < 0.5) ray.tmax = h.t;
            else ray.tmin = h.t;
        }
    } else if (rnd() < 0.2) ray.tmin = uni(-L, 0), ray.tmax = uni(0, 2 * L);
    return ray;
}

/* The scalar loops the batch stands for. */
static int loop_nearest(const CYL(ray) *ray, const CYL(cylinder) *cy, size_t n, unsigned opts, size_t *idx, T *t)
{
    CYL(hit) h;
    size_t i;
    int rc, got = 0;
    for (i = 0; i < n; i++) {
        rc = CYL(intersect)(ray, &cy[i], opts, &h);
        if (rc < 0) return rc;
        if (rc == CYL_HIT && (!got || h.t < *t)) *idx = i, *t = h.t, got = 1;
    }
    return got;
}
static int loop_any(const CYL(ray) *ray, const CYL(cylinder) *cy, size_t n, unsigned opts)
{
    size_t i;
    int rc;
    for (i = 0; i < n; i++)
        if ((rc = CYL(occluded)(ray, &cy[i], opts)) != 0) return rc;
    return 0;
}

/* Builds a batch of cy[0..n) in fresh memory at an odd offset (any alignment is accepted). */
static void *build(CYL(batch) *b, const CYL(cylinder) *cy, size_t n)
{
    unsigned char *mem = (unsigned char *)malloc(CYL(batch_bytes)(n) + 1);
    TEST_ASSERT_NOT_NULL(mem);
    TEST_ASSERT_EQUAL_INT(0, CYL(batch_build)(b, mem + 1, cy, n));
    return mem;
}

/* Every query of one ray, both ways, must agree bit for bit. */
static void agree(const CYL(batch) *b, const CYL(ray) *ray, const CYL(cylinder) *cy, size_t n, unsigned opts)
{
    size_t i1 = (size_t)-1, i2 = (size_t)-1;
    T t1 = -1, t2 = -1;
    int r1 = CYL(batch_nearest)(b, ray, opts, &i1, &t1), r2 = loop_nearest(ray, cy, n, opts, &i2, &t2);
    TEST_ASSERT_EQUAL_INT_MESSAGE(r2, r1, "nearest: the return value");
    if (r1 == CYL_HIT) {
        TEST_ASSERT_TRUE_MESSAGE(i1 == i2, "nearest: the index");
        TEST_ASSERT_TRUE_MESSAGE(memcmp(&t1, &t2, sizeof t1) == 0, "nearest: the t bits");
    } else TEST_ASSERT_TRUE_MESSAGE(i1 == (size_t)-1 && eq(t1, -1), "nearest: *i and *t untouched without a hit");
    TEST_ASSERT_EQUAL_INT_MESSAGE(loop_any(ray, cy, n, opts), CYL(batch_any)(b, ray, opts), "any");
}

/* agree() for each of the k option sets opts[]. */
static void agree_each(const CYL(batch) *b, const CYL(ray) *ray, const CYL(cylinder) *cy, size_t n, const unsigned *opts, size_t k)
{
    size_t o;
    for (o = 0; o < k; o++) agree(b, ray, cy, n, opts[o]);
}

static const unsigned opt_sets[] = {0u, CYL_CAPS, CYL_CAPS | CYL_NO_TANGENT, CYL_NO_NORMAL | CYL_NO_ERRBOUND,
                                    CYL_CAPS | CYL_OUTWARD | CYL_TRUSTED,
#ifndef CYL_NO_PRECISE
                                    CYL_CAPS | CYL_PRECISE
#endif
};
#define COUNT(a) (sizeof (a) / sizeof (a)[0])
#define N_OPTS COUNT(opt_sets)

/* ------------------------------------------------------------------ tests */
static void test_random_scenes_agree_with_the_scalar_loop(void)
{
    static const size_t sizes[] = {1, 7, 8, 9, 15, 16, 17, 100, 700};
    size_t s, r, o;
    rng_state = 20261207u;
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        CYL(cylinder) *cy = (CYL(cylinder) *)malloc(n * sizeof *cy);
        CYL(batch) b;
        void *mem;
        double L = rnd() < 0.5 ? 10 : 1000;
        TEST_ASSERT_NOT_NULL(cy);
        scene(cy, n, L);
        mem = build(&b, cy, n);
        for (r = 0; r < 200; r++)
            for (o = 0; o < N_OPTS; o++) {
                CYL(ray) ray = ray_for(cy, n, L, opt_sets[o]);
                agree(&b, &ray, cy, n, opt_sets[o]);
            }
        free(mem), free(cy);
    }
}

/* The cylinders copied: the caller's array may change or go once built. */
static void test_the_batch_keeps_its_own_copy(void)
{
    CYL(cylinder) cy[3] = {{{0, 0, 0}, {0, 0, 1}, 1, 2}, {{5, 0, 0}, {0, 0, 1}, 1, 2}, {{9, 0, 0}, {0, 1, 0}, 1, 2}};
    const CYL(cylinder) keep[3] = {{{0, 0, 0}, {0, 0, 1}, 1, 2}, {{5, 0, 0}, {0, 0, 1}, 1, 2}, {{9, 0, 0}, {0, 1, 0}, 1, 2}};
    CYL(ray) ray = {{-5, 0, 0}, {1, 0, 0}, 0, 100};
    CYL(batch) b;
    void *mem = build(&b, cy, 3);
    size_t i = 9;
    T t = 0;
    memset(cy, 0xff, sizeof cy); /* NaNs */
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(batch_nearest)(&b, &ray, 0u, &i, &t));
    TEST_ASSERT_TRUE(i == 0 && eq(t, 4)); /* the wall of the first at x = -1 */
    agree(&b, &ray, keep, 3, 0u);
    free(mem);
}

/* Equal t: the lowest index wins, as in the loop; tmin and tmax inclusive on a crossing. */
static void test_ties_and_range_ends(void)
{
    CYL(cylinder) cy[20];
    CYL(ray) ray = {{-5, 0, 0}, {1, 0, 0}, 0, 100};
    CYL(batch) b;
    void *mem;
    size_t i = 0, k;
    T t = 0;
    for (k = 0; k < 20; k++) { /* the same tube twenty times, and a farther one at 13 */
        CYL(cylinder) c = {{0, 0, 0}, {0, 0, 1}, 1, 2};
        if (k == 13) c.c[0] = -2;
        cy[k] = c;
    }
    mem = build(&b, cy, 20);
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(batch_nearest)(&b, &ray, 0u, &i, &t));
    TEST_ASSERT_TRUE(i == 13 && eq(t, 2));
    ray.tmin = 2, ray.tmax = 2; /* exactly on 13's crossing */
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(batch_nearest)(&b, &ray, 0u, &i, &t));
    TEST_ASSERT_TRUE(i == 13 && eq(t, 2));
    ray.tmin = 4, ray.tmax = 4; /* the others' entries: the first of them */
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(batch_nearest)(&b, &ray, 0u, &i, &t));
    TEST_ASSERT_TRUE(i == 0 && eq(t, 4));
    ray.tmin = (T)4.5, ray.tmax = (T)5.5; /* between crossings */
    TEST_ASSERT_EQUAL_INT(CYL_MISS, CYL(batch_nearest)(&b, &ray, 0u, &i, &t));
    TEST_ASSERT_EQUAL_INT(0, CYL(batch_any)(&b, &ray, 0u));
    free(mem);
}

/* Cylinders and rays beyond the filter's range are asked, not dropped. */
static void test_out_of_range_inputs_agree(void)
{
    enum { N = 40 };
    CYL(cylinder) cy[N];
    CYL(batch) b;
    void *mem;
    size_t k, r;
    rng_state = 7u;
    scene(cy, N, 10);
    cy[3].c[0] = T_HUGE, cy[3].a[1] = T_HUGE / 4; /* far and long-axed */
    cy[11].r = (T)1e-30, cy[11].c[0] = cy[11].c[1] = cy[11].c[2] = 0; /* a thread at the origin */
    cy[17].a[0] = cy[17].a[1] = 0, cy[17].a[2] = (T)1e-30;
    mem = build(&b, cy, N);
    for (r = 0; r < 300; r++) {
        CYL(ray) ray = ray_for(cy, N, 10, CYL_CAPS);
        if (r % 3 == 0) for (k = 0; k < 3; k++) ray.o[k] *= T_HUGE / 100; /* the ray out of range */
        if (r % 5 == 0) ray.d[0] *= (T)1e-30, ray.d[1] *= (T)1e-30, ray.d[2] *= (T)1e-30;
        if (r % 7 == 0) ray.d[0] *= (T)3e6, ray.d[1] *= (T)3e6, ray.d[2] *= (T)3e6; /* t in units of a long d */
        if (r % 11 == 0) ray.tmin = (T)1e-38, ray.tmax = (T)3e-38; /* tmin, tmax scaled with d: beyond float's range */
        agree(&b, &ray, cy, N, CYL_CAPS);
        agree(&b, &ray, cy, N, 0u);
    }
    free(mem);
}

/* Grazing rays started next to their contact point (|o − c| about r): there the filter's own
   rounding slack, which grows with |o − c|², is below the tangent band, so the band itself must
   keep the contacts the scalar call reports (e inside the band) and their neighbours. */
static void test_contacts_seen_from_close_by(void)
{
    enum { N = 12, RAYS = 400 };
    static const double edge[] = {0.25, 0.45, 0.499, 0.5, 0.501, 0.55, 1.0};
    static const unsigned opts[] = {0u, CYL_CAPS, CYL_CAPS | CYL_NO_TANGENT};
    CYL(cylinder) cy[N];
    CYL(batch) b;
    void *mem;
    size_t r;
    int k;
    rng_state = 99u;
    scene(cy, N, 10);
    mem = build(&b, cy, N);
    for (r = 0; r < RAYS; r++) {
        const CYL(cylinder) *c = &cy[r % N];
        double u[3], v[3], e = TANG_TOL * edge[(size_t)(rnd() * 7) % 7] * (rnd() < 0.5 ? 1 : -1);
        double rho = (double)c->r * (1 + e), back = (double)c->r * (rnd() < 0.5 ? 0.05 : 0.5);
        CYL(ray) ray;
        frame(c, u, v);
        for (k = 0; k < 3; k++) /* at distance rho from the axis, in the plane of the center */
            ray.o[k] = (T)((double)c->c[k] + rho * u[k] - back * v[k]), ray.d[k] = (T)v[k];
        ray.tmin = 0, ray.tmax = (T)INFINITY;
        agree_each(&b, &ray, cy, N, opts, COUNT(opts));
    }
    free(mem);
}

/* 2^e times a value in [1, 2), e uniform in [lo, hi] clamped to [LO, HI] (T's exponents, less
   a margin: every value finite and normal). */
#ifdef T_DOUBLE
enum { LO = -900, HI = 900 };
#else
enum { LO = -110, HI = 110 };
#endif
static T mag(int lo, int hi)
{
    int e = lo + (int)(rnd() * (hi - lo + 1));
    return (T)ldexp(1 + rnd(), e < LO ? LO : e > HI ? HI : e);
}

/* Scenes of any proportions, at any scale: each trial a scale 2^E over most of T's exponents,
   then, independently, cylinders whose centers lie 2^(E−40) to 2^(E+10) from the origin, whose
   radii and heights lie within 2^(E−100) to 2^(E+40), and a ray from 2^(E−60) to 2^(E+20) off one
   of the centers, aimed at it, along its axis or anywhere. So thin, flat, long, far and tiny
   cylinders straddle the filter's range (float in float: 2^16, r from 2^-20, h/2 2^±58; float
   in double 2^32; double 2^100, h/2 2^±400) and the ratios where the scalar call's exact path
   raises r or h/2. It holds r's lower limit in every working type; the ranges' upper edges are
   narrower (test_fuzz_range_edges_asked, test_fuzz_out_of_range_cylinder_raised_by_the_call). */
static void test_any_proportions_agree(void)
{
    enum { TRIALS = 1500, NMAX = 24 };
    static const unsigned opts[] = {0u, CYL_CAPS, CYL_CAPS | CYL_TRUSTED};
    CYL(cylinder) cy[NMAX];
    size_t trial, i;
    int k;
    rng_state = 20261207u;
    for (trial = 0; trial < TRIALS; trial++) {
        const int E = LO + (int)(rnd() * (HI - LO + 1));
        size_t n = 1 + (size_t)(rnd() * NMAX) % NMAX;
        const CYL(cylinder) *c;
        CYL(ray) ray;
        CYL(batch) b;
        void *mem;
        T far, dir[3];
        for (i = 0; i < n; i++) {
            far = mag(E - 40, E + 10);
            unit_dir(dir);
            for (k = 0; k < 3; k++) cy[i].c[k] = dir[k] * far;
            unit_dir(cy[i].a);
            if (rnd() < 0.3) cy[i].a[0] = cy[i].a[1] = 0, cy[i].a[2] = 1;
            for (k = 0; k < 3; k++) cy[i].a[k] *= (T)ldexp(1, (int)(rnd() * 40) - 20);
            cy[i].r = mag(E - 100, E + 40), cy[i].h = rnd() < 0.1 ? (T)INFINITY : mag(E - 100, E + 40);
        }
        c = &cy[(size_t)(rnd() * (double)n) % n];
        far = mag(E - 60, E + 20);
        unit_dir(dir);
        for (k = 0; k < 3; k++) ray.o[k] = c->c[k] + dir[k] * far;
        if (rnd() < 0.5) /* toward the center: crosses the cylinder */
            for (k = 0; k < 3; k++) ray.d[k] = (T)((double)c->c[k] - (double)ray.o[k]);
        else if (rnd() < 0.5) /* along the axis */
            for (k = 0; k < 3; k++) ray.d[k] = c->a[k];
        else unit_dir(ray.d);
        if (eq(ray.d[0], 0) && eq(ray.d[1], 0) && eq(ray.d[2], 0)) ray.d[0] = 1;
        ray.tmin = 0, ray.tmax = rnd() < 0.3 ? mag(-30, 30) : (T)INFINITY;
        mem = build(&b, cy, n);
        agree_each(&b, &ray, cy, n, opts, COUNT(opts));
        free(mem);
    }
}

/* One scene at every scale 2^k over T's exponents, rays and all (powers of two: exact but for
   the rare subnormal; t scales with o, tmin with it, tmax infinite), so that every magnitude at
   which a product the filter forms overflows or underflows its type while the scalar call's
   does not (in float: (w·s)² overflows, |w|² and r² not yet, for |o − c| ~ r near 2^63) is met,
   not only sampled. Builds without optimization (-O0: gcc, clang and the sanitizers') take
   every fifth exponent, the ends included: they look for memory errors and undefined behaviour,
   which the scales between repeat, and the sweep took most of their time (7.7 s under ASan). */
static void test_every_scale_agrees(void)
{
    enum { N = 16, RAYS = 12 };
#ifdef __OPTIMIZE__
    const int step = 1;
#else
    const int step = 5;
#endif
    static const unsigned opts[] = {0u, CYL_CAPS};
    CYL(cylinder) base[N], cy[N];
    CYL(ray) rays[RAYS];
    size_t i, r;
    int e, k;
    rng_state = 640u;
    scene(base, N, 1);
    for (i = 0; i < N; i += 2) base[i].r = uni(0.5, 2); /* fat: o − c, r and w·s alike (L = 1) */
    for (r = 0; r < RAYS; r++) rays[r] = ray_for(base, N, 1, CYL_CAPS), rays[r].tmax = (T)INFINITY;
    for (e = LO; e <= HI; e += step) {
        const T s = (T)ldexp(1, e);
        CYL(batch) b;
        void *mem;
        for (i = 0; i < N; i++) {
            cy[i] = base[i], cy[i].r *= s, cy[i].h *= s;
            for (k = 0; k < 3; k++) cy[i].c[k] *= s;
        }
        mem = build(&b, cy, N);
        for (r = 0; r < RAYS; r++) {
            CYL(ray) ray = rays[r];
            for (k = 0; k < 3; k++) ray.o[k] *= s;
            ray.tmin *= s;
            agree_each(&b, &ray, cy, N, opts, COUNT(opts));
        }
        free(mem);
    }
}

#ifndef T_DOUBLE
/* Found by fuzz/fuzz_batch.c against filters whose range was wider than the header's (the
   scalar call hits; such a filter dropped the cylinder): a cylinder at 2^63 whose w·s squared
   overflows float while |w|² and r² do not (the float API computed in double; the filter's
   fused products, with AVX2, give that overflow), and a flat disk of radius 2^73 and height
   2^-55 (float computed in float). The range asks both. */
static void test_fuzz_range_edges_asked(void)
{
    const T big = (T)ldexp(1799, 52), r = (T)ldexp(1281, 63);
    CYL(cylinder) cy[2] = {{{big, (T)ldexp(1799, -53), big}, {big, big, big}, big, big},
                           {{(T)ldexp(12593, -15), (T)ldexp(12593, -15), (T)ldexp(12593, -15)},
                            {(T)ldexp(12593, -15), (T)ldexp(787, -11), (T)ldexp(257, -55)}, r, (T)ldexp(257, -63)}};
    CYL(ray) far = {{(T)ldexp(7061, -8), (T)ldexp(14135, -9), (T)ldexp(14135, -9)},
                    {-(T)ldexp(7061, -8), (T)ldexp(30583, 51), (T)ldexp(30583, 55)}, 0, (T)INFINITY};
    CYL(ray) disk = {{(T)ldexp(771, -12), (T)ldexp(771, -12), (T)ldexp(771, -12)},
                     {(T)ldexp(6425, -15), (T)ldexp(6425, -15), (T)ldexp(6425, -15)}, 0, (T)0.188232421875};
    CYL(batch) b;
    CYL(hit) h;
    void *mem = build(&b, cy, 2);
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(intersect)(&far, &cy[0], CYL_OUTWARD, &h));
    /* the disk is hit where float computes in float (in double the call misses it: agreement holds either way) */
    TEST_ASSERT_EQUAL_INT(CYL_FLOAT_WIDE ? CYL_MISS : CYL_HIT, CYL(intersect)(&disk, &cy[1], CYL_CAPS | CYL_TRUSTED, &h));
    agree(&b, &far, cy, 2, CYL_OUTWARD);
    agree(&b, &disk, cy, 2, CYL_CAPS | CYL_TRUSTED);
    free(mem);
}
#endif

#ifdef T_DOUBLE
/* Found by fuzz/fuzz_batch.c: a block whose every cylinder is outside the filter's range (axes of
   length 1e-200) and which the tube test, underflowing, rejects whole: the flag must still ask. */
static void test_fuzz_block_of_out_of_range_cylinders(void)
{
    CYL(cylinder) cy[2] = {{{4.80562449e-07, -4.40619763e-16, 1e-200}, {0.0011100769, 5.59448321e-17, 1e-200}, 1e-200, 1e-200},
                           {{-3.07559967e-05, 1e-200, -2.23779328e-16}, {1e-200, 1e-200, -1e-200}, 2.90407092e+23, 3.12638804e-13}};
    CYL(ray) ray = {{2.927345865710862e-18, 3.3953950762111162e-12, 1.101868699230975e+21},
                    {1.101868699230975e+21, 1.1067325868285352e+21, 1e-200}, 0, (T)INFINITY};
    CYL(batch) b;
    void *mem = build(&b, cy, 2);
    size_t i = 9;
    T t = 0;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, CYL(batch_nearest)(&b, &ray, CYL_CAPS, &i, &t)); /* cylinder 1 */
    TEST_ASSERT_TRUE(i == 1);
    agree(&b, &ray, cy, 2, CYL_CAPS);
    agree(&b, &ray, cy, 2, 0u);
    free(mem);
}
#endif

#ifdef T_DOUBLE
/* Found by fuzz/fuzz_batch.c (CAPS|PRECISE): cylinder 10 (r = 1e200, h = 1.6e-16) lies outside the
   filter's range, where the scalar call's exact path raises h/2 (t = 0.747, t_err = inf; the true
   cap plane is crossed near t = 1). Once a nearer-in-index hit had set the best t, the slab test,
   which assumes the call's crossing on the true cap planes, dropped it: the slab must not judge
   a cylinder out of range either (H|a| infinite there too). */
static void test_fuzz_out_of_range_cylinder_raised_by_the_call(void)
{
    static const CYL(cylinder) cy[11] = {
        {{3.17412763e-13, 3.12638804e-13, 0.0}, {3.28070904e-13, -9.22337204e+18, 3.40394379e-13}, 3.13638004e-13, 3.13860049e-13},
        {{0.0, 1.53251977e-16, 1.66370823e-16}, {6.9388939e-18, -3.29813954e-12, -16199.0}, 8095.5, 8095.5},
        {{8095.5, 1157.5, 3.15303339e-13}, {5.60976332e-09, 5.60976332e-09, 5.60976332e-09}, 5.60976332e-09, 5.60976332e-09},
        {{5.60976332e-09, 5.60976332e-09, 3.13860049e-13}, {0.0, 2.38524478e-18, -3.32411876e-12}, 1.28019817e-12, 3.13860049e-13},
        {{5.04878699e-08, 1.75772584e-07, 6.58724457e-06}, {2.15004547e-08, -9.22337204e+18, 3.40394379e-13}, 3.17190718e-13, 3.13860049e-13},
        {{4.01740863e-11, 3.41523684e-18, 8095.5}, {8095.5, 8095.5, 7.84650123e-14}, 6.84785562e-13, 5.60976332e-09},
        {{5.60976332e-09, 5.60976332e-09, 5.60976332e-09}, {5.60976332e-09, 5.60976332e-09, 5.59793989e-09}, 3.13860049e-13, 1.08420217e-19},
        {{1.37151575e-17, 0.0, -1.77576053e-15}, {3.19633209e-13, 8095.5, 8095.5}, 8095.5, 8095.5},
        {{7.84650123e-14, 3.32722738e-12, 9.71661987e-16}, {-2.23779328e-16, 1e-200, 8.10197573e+18}, 8.10197573e+18, 8.10197573e+18},
        {{8.10197573e+18, 8.10197573e+18, 8.10197573e+18}, {8.10197573e+18, 8.10197573e+18, 3.57641602}, 114.304688, 0.000304013491},
        {{5.20417043e-18, 12141872500000.0, 7.84650123e-14}, {5.1159077e-13, 5.96311195e-19, 1.22124533e-15}, 1e+200, 1.60190871e-16}};
    CYL(ray) ray = {{-1.4584457033276614e+20, 126.4921875, 8095.5}, {1.4584457033276614e+20, -126.4921875, -8095.5}, 0, (T)INFINITY};
    CYL(batch) b;
    void *mem = build(&b, cy, 11);
    agree(&b, &ray, cy, 11, CYL_CAPS | CYL_PRECISE);
    agree(&b, &ray, cy, 11, CYL_CAPS);
    free(mem);
}
#endif

#ifndef T_DOUBLE
/* Found by fuzz/fuzz_batch.c (float, OUTWARD, open tubes): cylinder 8 lies out of range (|c| near
   2^70), so r² is infinite; P² overflowed too, D came out NaN, and the t interval's max(D, 0)
   turned the NaN into 0: a finite interval that missed the call's hit at t = 2^120. A NaN must
   stay one through the filter. */
static void test_fuzz_nan_d_kept_through_the_interval(void)
{
    static const CYL(cylinder) cy[11] = {
        {{6.84785562e-13f, 1e-30f, 1e-30f}, {1e-30f, 1e-30f, 1e-30f}, 1e-30f, 1e-30f},
        {{0.0f, 0.0f, 5.82650247e-16f}, {1e-30f, 1e-30f, -1e-30f}, 1e-30f, 1e-30f},
        {{1e-30f, 1e-30f, 1e-30f}, {1e-30f, 1e-30f, 1e-30f}, 1e-30f, 1e-30f},
        {{1e-30f, 1e-30f, 1e-30f}, {1e-30f, -1.63768738e-15f, 1e-30f}, 1e-30f, 1e-30f},
        {{1e-30f, 1e-30f, -1e-30f}, {3.15303339e-13f, -2.34649633e-10f, 1e-30f}, 1e-30f, 1e-30f},
        {{1e-30f, 1e-30f, 1e-30f}, {-9.61124897e-07f, 1e-30f, 1e-30f}, 1e-30f, 1e-30f},
        {{1e-30f, 1e-30f, -1e-30f}, {8.91647867e-16f, 9.91394467e-16f, 1.1018687e+21f}, 1.1018687e+21f, 1.1018687e+21f},
        {{0.0f, 15291.5f, 1.1018687e+21f}, {1.1018687e+21f, 2.80990029e+23f, 5.42101086e-20f}, 1.41039194e+23f, 1.1018687e+21f},
        {{2.56548798e+11f, 1.1018687e+21f, 3.8244568e+20f}, {1.1018687e+21f, 1.1018687e+21f, 1.1018687e+21f}, 1.1018687e+21f, 1.1018687e+21f},
        {{1.1018687e+21f, 1.1018687e+21f, 1.1018687e+21f}, {1.1018687e+21f, 1.17565568e+21f, 5.69652766e-05f}, 1.10673259e+21f, 1e-30f},
        {{1e-30f, 1e-30f, 1e-30f}, {1e-30f, 1e-30f, -258.0f}, 1e-30f, 2.25979235e-11f}};
    CYL(ray) ray = {{0, 0, 0}, {0, 0, 5.8265025e-16f}, 0, (T)INFINITY};
    CYL(batch) b;
    void *mem = build(&b, cy, 11);
    agree(&b, &ray, cy, 11, CYL_OUTWARD);
    agree(&b, &ray, cy, 11, 0u);
    free(mem);
}
#endif

/* A cylinder outside the filter's range (here r below 2^-200, float 2^-32) is always asked, even
   far from the ray; one inside it, as far, is not (the manual's range). */
static void test_out_of_range_cylinder_always_asked(void)
{
    CYL(cylinder) cy[3] = {{{0, 50, 0}, {0, 0, 1}, 1, 2}, {{0, 50, 0}, {0, 0, 1}, T_TINY_R, 2}, {{0, 0, 0}, {0, 0, 1}, 1, 2}};
    CYL(ray) ray = {{-5, 0, 0}, {1, 0, 0}, 0, 100};
    CYL(batch) b;
    void *mem = build(&b, cy, 3);
    unsigned m;
    BATCH(q) q;
    TEST_ASSERT_TRUE(BATCH(query)(&q, &ray));
    m = BATCH(block_of)(&b, 0, &q, 1, q.tmax);
    TEST_ASSERT_EQUAL_HEX(6u, m); /* 1 (out of range) and 2 (hit); not 0 */
    agree(&b, &ray, cy, 3, CYL_CAPS);
    free(mem);
}

/* The filter drops what is certainly missed: in a sparse scene, far from every cylinder
   being asked (else the batch would be the scalar loop with extra steps). */
static void test_the_filter_drops_certain_misses(void)
{
    enum { N = 1024 };
    CYL(cylinder) *cy = (CYL(cylinder) *)malloc(N * sizeof *cy);
    CYL(batch) b;
    void *mem;
    size_t k, r, asked = 0, rays = 100;
    rng_state = 99u;
    TEST_ASSERT_NOT_NULL(cy);
    scene(cy, N, 100);
    mem = build(&b, cy, N);
    for (r = 0; r < rays; r++) {
        BATCH(q) q;
        CYL(ray) ray = ray_for(cy, N, 100, CYL_CAPS);
        ray.tmin = 0, ray.tmax = (T)INFINITY;
        TEST_ASSERT_TRUE(BATCH(query)(&q, &ray));
        for (k = 0; k < b.nb; k++) {
            unsigned m = BATCH(block_of)(&b, k, &q, 1, q.tmax);
            for (; m; m &= m - 1u) asked++;
        }
    }
    /* about 4 % of such lines meet a tube's extent; the infinite ones more: 15 % is a failure */
    TEST_ASSERT_TRUE_MESSAGE(asked * 100 < 15 * N * rays, "the filter keeps too much");
    free(mem), free(cy);
}

static void test_empty_batch(void)
{
    CYL(batch) b;
    CYL(ray) ray = {{0, 0, 0}, {1, 0, 0}, 0, 1}, bad = {{0, 0, 0}, {0, 0, 0}, 0, 1};
    size_t i = 5;
    T t = 3;
    TEST_ASSERT_EQUAL_INT(0, CYL(batch_build)(&b, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(CYL_MISS, CYL(batch_nearest)(&b, &ray, CYL_CAPS, &i, &t));
    TEST_ASSERT_EQUAL_INT(0, CYL(batch_any)(&b, &ray, CYL_CAPS));
    TEST_ASSERT_TRUE(i == 5 && eq(t, 3));
    TEST_ASSERT_EQUAL_INT(CYL_E_ZERO_DIR, CYL(batch_nearest)(&b, &bad, CYL_CAPS, &i, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_ZERO_DIR, CYL(batch_any)(&b, &bad, CYL_CAPS));
}

/* Build errors: the first bad cylinder's, in the scalar order; nothing written. */
static void test_build_errors(void)
{
    CYL(cylinder) cy[4] = {{{0, 0, 0}, {0, 0, 1}, 1, 2}, {{0, 0, 0}, {0, 0, 1}, 1, 2},
                           {{0, 0, 0}, {0, 0, 1}, 1, 2}, {{0, 0, 0}, {0, 0, 1}, 1, 2}};
    static unsigned char mem[4096], ref[4096];
    CYL(batch) b, b0;
    memset(mem, 0x5a, sizeof mem), memset(ref, 0x5a, sizeof ref), memset(&b, 0x3c, sizeof b), b0 = b;
    TEST_ASSERT_TRUE(CYL(batch_bytes)(4) <= sizeof mem);
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_build)(NULL, mem, cy, 4));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_build)(&b, NULL, cy, 4));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_build)(&b, mem, NULL, 4));
    cy[2].h = 0, cy[3].r = -1; /* the first error is cylinder 2's: CYL_E_HEIGHT */
    TEST_ASSERT_EQUAL_INT(CYL_E_HEIGHT, CYL(batch_build)(&b, mem, cy, 4));
    cy[1].a[0] = cy[1].a[2] = 0; /* now cylinder 1's: CYL_E_ZERO_AXIS */
    TEST_ASSERT_EQUAL_INT(CYL_E_ZERO_AXIS, CYL(batch_build)(&b, mem, cy, 4));
    cy[1].c[1] = (T)NAN; /* the scalar order: non-finite before a zero axis */
    TEST_ASSERT_EQUAL_INT(CYL_E_NONFINITE, CYL(batch_build)(&b, mem, cy, 4));
    cy[0].r = (T)INFINITY;
    TEST_ASSERT_EQUAL_INT(CYL_E_RADIUS, CYL(batch_build)(&b, mem, cy, 4));
    TEST_ASSERT_TRUE_MESSAGE(memcmp(mem, ref, sizeof mem) == 0, "memory written on an error");
    TEST_ASSERT_TRUE_MESSAGE(memcmp(&b, &b0, sizeof b) == 0, "the batch written on an error");
    TEST_ASSERT_TRUE(CYL(batch_bytes)(SIZE_MAX / 2) == 0); /* too large: 0 */
}

/* Query errors: the scalar call's, in its order; *i and *t untouched. */
static void test_query_errors(void)
{
    CYL(cylinder) cy[1] = {{{0, 0, 0}, {0, 0, 1}, 1, 2}};
    CYL(ray) ray = {{-5, 0, 0}, {1, 0, 0}, 0, 100}, bad;
    CYL(batch) b;
    void *mem = build(&b, cy, 1);
    size_t i = 5;
    T t = 3;
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_nearest)(NULL, &ray, 0u, &i, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_nearest)(&b, NULL, 0u, &i, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_nearest)(&b, &ray, 0u, NULL, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_nearest)(&b, &ray, 0u, &i, NULL));
    TEST_ASSERT_EQUAL_INT(CYL_E_NULL, CYL(batch_any)(&b, NULL, 0u));
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, CYL(batch_nearest)(&b, &ray, 0x80u, &i, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, CYL(batch_any)(&b, &ray, 0x80u));
    bad = ray, bad.o[1] = (T)INFINITY;
    TEST_ASSERT_EQUAL_INT(CYL_E_NONFINITE, CYL(batch_nearest)(&b, &bad, 0u, &i, &t));
    bad = ray, bad.tmin = 5, bad.tmax = 1;
    TEST_ASSERT_EQUAL_INT(CYL_E_TRANGE, CYL(batch_nearest)(&b, &bad, 0u, &i, &t));
    TEST_ASSERT_EQUAL_INT(CYL_E_TRANGE, CYL(batch_any)(&b, &bad, 0u));
    TEST_ASSERT_TRUE(i == 5 && eq(t, 3));
    free(mem);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_scenes_agree_with_the_scalar_loop);
    RUN_TEST(test_the_batch_keeps_its_own_copy);
    RUN_TEST(test_ties_and_range_ends);
    RUN_TEST(test_out_of_range_inputs_agree);
    RUN_TEST(test_contacts_seen_from_close_by);
    RUN_TEST(test_any_proportions_agree);
    RUN_TEST(test_every_scale_agrees);
    RUN_TEST(test_the_filter_drops_certain_misses);
    RUN_TEST(test_out_of_range_cylinder_always_asked);
#ifndef T_DOUBLE
    RUN_TEST(test_fuzz_nan_d_kept_through_the_interval);
    RUN_TEST(test_fuzz_range_edges_asked);
#endif
#ifdef T_DOUBLE
    RUN_TEST(test_fuzz_block_of_out_of_range_cylinders);
    RUN_TEST(test_fuzz_out_of_range_cylinder_raised_by_the_call);
#endif
    RUN_TEST(test_empty_batch);
    RUN_TEST(test_build_errors);
    RUN_TEST(test_query_errors);
    return UNITY_END();
}
