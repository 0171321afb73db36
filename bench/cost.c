/* cost.c: what one call of the library costs against the end-point routine, measured in a
 * program that uses the library the way a renderer does (`make cost`, `make cost-time`).
 *
 *   build/cost/cost-VER-MARCH [--n N] [--seed S]            (under callgrind, see below)
 *   build/cost/cost-VER-MARCH --time [--n N] [--seed S] [--block-ms M] [--rounds R]
 *
 * One translation unit, built as users build (gcc -std=c99 -O2, with and without
 * -march=x86-64-v3): it includes whichever cylinder_isect.h the include path finds first (v1
 * with -I., v2 with -iquote v2 -I.) and bench/alt_formulations.h. Like a renderer it calls
 * every entry point (intersect, intersect_all, occluded) in both precisions with several
 * constant option sets, each call site in a loop function of its own, so that whether gcc
 * inlines an entry point and folds its options is decided as in a real program with several
 * call sites; nothing here forces inlining (unlike bench/eval.c's `flatten`).
 *
 * The cases: bench/cases.c's well-conditioned family (BF_WELL) in float and in double, N cases
 * generated from the seed, those of finite height kept (as bench's capped timed sets), every
 * variant fed its own input form, prepared before anything is counted or timed: the library
 * its rays and cylinders; the end-point routine (altf_/altd_endpoint_solve) its (pa, pb, ra)
 * and unit-direction rays (tmin, tmax scaled). Every loop has the same shape: one call per
 * case over the arrays of rays and cylinders, the hit in a local array, the t of each hit
 * summed and returned (stored into a volatile by the caller), so nothing is optimised away.
 * The empty loop reads the same arrays without a call; its count or time is subtracted.
 *
 * Both modes first print "compiler VERSION" (gcc's __VERSION__).
 * Default mode: for each loop, prints "cost PREC NAME CASES" and calls cost_run once, which
 * runs the loop once over the cases. Run under
 *   valgrind --tool=callgrind --toggle-collect=cost_run --dump-after=cost_run
 * the k-th dump counts the k-th loop (bench/cost_report.py pairs them). A loop whose call
 * returns an error on the first case (CYL_PRECISE compiled out: CYL_E_OPTION), or whose
 * option the header does not have, is not run: "na PREC NAME CODE" instead, without a dump.
 * --time: for each loop, "time PREC NAME CASES NS": nanoseconds per call (the empty loop's
 * subtracted), the fastest of R rounds, each of about M ms (clock_gettime, CLOCK_MONOTONIC).
 */
#define _POSIX_C_SOURCE 199309L
#include "cylinder_isect.h"
#include "alt_formulations.h"
#include "cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#if defined(__GNUC__) || defined(__clang__)
#define COST_NOINLINE __attribute__((noinline))
#else
#define COST_NOINLINE
#endif
#if defined(__GNUC__) && !defined(__clang__)
#define COST_MARKER __attribute__((noinline, noclone))
#else
#define COST_MARKER COST_NOINLINE
#endif

/* CYL_PRECISE compiled out (or gone from the header): those loops are reported "n/a" */
#if defined(CYL_PRECISE) && !defined(CYL_NO_PRECISE)
#define COST_PRECISE CYL_PRECISE
#define COST_HAS_PRECISE 1
#else
#define COST_PRECISE 0u
#define COST_HAS_PRECISE 0
#endif

#define COST_PLAIN (CYL_CAPS | CYL_NO_ERRBOUND | CYL_NO_NORMAL)
#define COST_DEFAULT CYL_CAPS
#define COST_PREC_OPTS (CYL_CAPS | COST_PRECISE)

/* One precision's cases in one variant's input form: n rays and n cylinders (the library's
   cyl?_ray and cyl?_cylinder, or unit-direction rays and alt?_endpoint_cyl). */
typedef struct cost_set {
    int n;
    const void *rays, *cyls;
} cost_set;

typedef double (*cost_loop_fn)(const cost_set *s);

volatile double cost_sink;
/* the return value of the last call of the last loop run (checked on a one-case run) */
static int cost_last_rc;

/* The loop every measured call site sits in. CALL is one call on case i (R[i], C[i], hit
   array h); USE the hit's value that is summed. */
#define COST_LOOP(NAME, RAY_T, CYL_T, HIT_T, CALL, USE)                                      \
    static COST_NOINLINE double NAME(const cost_set *s)                                      \
    {                                                                                        \
        const RAY_T *R = (const RAY_T *)s->rays;                                             \
        const CYL_T *C = (const CYL_T *)s->cyls;                                             \
        HIT_T h[2];                                                                          \
        double acc = 0;                                                                      \
        int i, n = s->n, rc = 0;                                                             \
        memset(h, 0, sizeof h);                                                              \
        for (i = 0; i < n; ++i) {                                                            \
            rc = (CALL);                                                                     \
            if (rc > 0) acc += (USE);                                                        \
        }                                                                                    \
        cost_last_rc = rc;                                                                   \
        return acc;                                                                          \
    }

/* the call sites of one precision: P is f or d */
#define COST_SITES(P)                                                                        \
    COST_LOOP(empty_##P, cyl##P##_ray, cyl##P##_cylinder, cyl##P##_hit,                      \
              R[i].tmin <= C[i].r, (double)R[i].tmax)                                     \
    COST_LOOP(endpoint_##P, cyl##P##_ray, alt##P##_endpoint_cyl, alt##P##_out,               \
              alt##P##_endpoint_solve(&R[i], &C[i], &h[0]), (double)h[0].t)                  \
    COST_SITES_OF(P, plain, COST_PLAIN)                                                      \
    COST_SITES_OF(P, default, COST_DEFAULT)                                                  \
    COST_SITES_OF(P, bound, CYL_CAPS | CYL_NO_NORMAL)                                        \
    COST_SITES_OF(P, normal, CYL_CAPS | CYL_NO_ERRBOUND)                                     \
    COST_SITES_OF(P, precise, COST_PREC_OPTS)                                                \
    COST_SITES_OF(P, open, 0u)                                                               \
    COST_SITES_OF(P, outward, CYL_OUTWARD)
#define COST_SITES_OF(P, TAG, OPTS)                                                          \
    COST_LOOP(intersect_##P##_##TAG, cyl##P##_ray, cyl##P##_cylinder, cyl##P##_hit,          \
              cyl##P##_intersect(&R[i], &C[i], (OPTS), &h[0]), (double)h[0].t)               \
    COST_LOOP(all_##P##_##TAG, cyl##P##_ray, cyl##P##_cylinder, cyl##P##_hit,                \
              cyl##P##_intersect_all(&R[i], &C[i], (OPTS), h),                               \
              (double)h[0].t + (double)h[rc - 1].t)                                          \
    COST_LOOP(occluded_##P##_##TAG, cyl##P##_ray, cyl##P##_cylinder, cyl##P##_hit,           \
              cyl##P##_occluded(&R[i], &C[i], (OPTS)), 1.0)

COST_SITES(f)
COST_SITES(d)

enum { IN_LIB, IN_EP };

typedef struct cost_loop {
    int prec;           /* 24 or 53 */
    const char *name;   /* "empty", "endpoint", "intersect:plain", ... */
    int input;          /* IN_LIB or IN_EP */
    int precise;        /* uses CYL_PRECISE */
    cost_loop_fn fn;
} cost_loop;

#define COST_ROWS_OF(P, PREC, TAG, PRECISE)                                                  \
    {PREC, "intersect:" #TAG, IN_LIB, PRECISE, intersect_##P##_##TAG},                       \
    {PREC, "intersect_all:" #TAG, IN_LIB, PRECISE, all_##P##_##TAG},                         \
    {PREC, "occluded:" #TAG, IN_LIB, PRECISE, occluded_##P##_##TAG}
#define COST_ROWS(P, PREC)                                                                   \
    {PREC, "empty", IN_LIB, 0, empty_##P},                                                   \
    {PREC, "endpoint", IN_EP, 0, endpoint_##P},                                              \
    COST_ROWS_OF(P, PREC, plain, 0),                                                         \
    COST_ROWS_OF(P, PREC, default, 0),                                                       \
    COST_ROWS_OF(P, PREC, bound, 0),                                                         \
    COST_ROWS_OF(P, PREC, normal, 0),                                                        \
    COST_ROWS_OF(P, PREC, precise, 1),                                                       \
    COST_ROWS_OF(P, PREC, open, 0),                                                          \
    COST_ROWS_OF(P, PREC, outward, 0)

static const cost_loop cost_loops[] = {COST_ROWS(f, 24), COST_ROWS(d, 53)};
#define COST_NLOOPS ((int)(sizeof cost_loops / sizeof cost_loops[0]))

/* The marker callgrind toggles collection on and dumps after: one loop, once. */
void cost_run(cost_loop_fn fn, const cost_set *s);
COST_MARKER void cost_run(cost_loop_fn fn, const cost_set *s)
{
    cost_sink += fn(s);
}

/* ------------------------------------------------------------------ the cases */

typedef struct cost_data {
    cost_set lib, ep;   /* the library's form, the end-point routine's */
} cost_data;

static void *cost_alloc(size_t n, size_t size)
{
    void *p = calloc(n > 0 ? n : 1, size);
    if (!p) {
        fprintf(stderr, "cost: out of memory\n");
        exit(1);
    }
    return p;
}

/* n cases of the family, those of finite height kept, in both input forms (as eval.c's
   to_inputs: values rounded once to the precision; the unit ray's d and t range scaled in
   double, then rounded) */
static void cost_make(int prec, uint64_t seed, int n, cost_data *out)
{
    size_t rs = prec == 24 ? sizeof(cylf_ray) : sizeof(cyld_ray);
    size_t cs = prec == 24 ? sizeof(cylf_cylinder) : sizeof(cyld_cylinder);
    size_t es = prec == 24 ? sizeof(altf_endpoint_cyl) : sizeof(altd_endpoint_cyl);
    void *rays = cost_alloc((size_t)n, rs), *cyls = cost_alloc((size_t)n, cs);
    void *urays = cost_alloc((size_t)n, rs), *ep = cost_alloc((size_t)n, es);
    int i, j, m = 0;
    for (i = 0; i < n; ++i) {
        bench_case k;
        double dl;
        bench_case_gen(BF_WELL, prec, seed, (uint64_t)i, &k);
        if (!isfinite(k.h)) continue;   /* the end-point routine cannot express it */
        dl = sqrt(k.d[0] * k.d[0] + k.d[1] * k.d[1] + k.d[2] * k.d[2]);
        if (prec == 24) {
            cylf_ray *r = (cylf_ray *)rays + m, *u = (cylf_ray *)urays + m;
            cylf_cylinder *c = (cylf_cylinder *)cyls + m;
            for (j = 0; j < 3; ++j) {
                r->o[j] = (float)k.o[j]; r->d[j] = (float)k.d[j];
                c->c[j] = (float)k.c[j]; c->a[j] = (float)k.a[j];
                u->o[j] = r->o[j]; u->d[j] = (float)(k.d[j] / dl);
            }
            r->tmin = (float)k.tmin; r->tmax = (float)k.tmax;
            u->tmin = (float)(k.tmin * dl); u->tmax = (float)(k.tmax * dl);
            c->r = (float)k.r; c->h = (float)k.h;
            altf_endpoint_from(c, (altf_endpoint_cyl *)ep + m);
        } else {
            cyld_ray *r = (cyld_ray *)rays + m, *u = (cyld_ray *)urays + m;
            cyld_cylinder *c = (cyld_cylinder *)cyls + m;
            for (j = 0; j < 3; ++j) {
                r->o[j] = k.o[j]; r->d[j] = k.d[j];
                c->c[j] = k.c[j]; c->a[j] = k.a[j];
                u->o[j] = r->o[j]; u->d[j] = k.d[j] / dl;
            }
            r->tmin = k.tmin; r->tmax = k.tmax;
            u->tmin = k.tmin * dl; u->tmax = k.tmax * dl;
            c->r = k.r; c->h = k.h;
            altd_endpoint_from(c, (altd_endpoint_cyl *)ep + m);
        }
        ++m;
    }
    out->lib.n = out->ep.n = m;
    out->lib.rays = rays;
    out->lib.cyls = cyls;
    out->ep.rays = urays;
    out->ep.cyls = ep;
}

static void cost_free(cost_data *d)
{
    free((void *)d->lib.rays); free((void *)d->lib.cyls);
    free((void *)d->ep.rays); free((void *)d->ep.cyls);
}

/* ------------------------------------------------------------------ running */

static double cost_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* 0 if the loop can run; else the code it is "n/a" for (the first case's error return, or
   CYL_E_OPTION for a CYL_PRECISE the header compiles out or lacks) */
static int cost_probe(const cost_loop *l, const cost_set *s)
{
    cost_set one = *s;
    if (l->precise && !COST_HAS_PRECISE) return CYL_E_OPTION;
    if (s->n < 1) return 0;
    one.n = 1;
    cost_sink += l->fn(&one);
    return cost_last_rc < 0 ? cost_last_rc : 0;
}

/* seconds for reps passes of the loop */
static double cost_time_loop(const cost_loop *l, const cost_set *s, int reps)
{
    double t0 = cost_now(), t1;
    int k;
    for (k = 0; k < reps; ++k) cost_sink += l->fn(s);
    t1 = cost_now();
    return t1 - t0;
}

int main(int argc, char **argv)
{
    unsigned long long seed = 20261122ull;
    int n = 2000, time_mode = 0, rounds = 5, i, p, rd;
    double block_ms = 4.0;
    cost_data data[2];
    int na[COST_NLOOPS], reps[COST_NLOOPS];
    double best[COST_NLOOPS];

    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--n") && i + 1 < argc) n = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--block-ms") && i + 1 < argc) block_ms = atof(argv[++i]);
        else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--time")) time_mode = 1;
        else {
            fprintf(stderr, "usage: %s [--time] [--n N] [--seed S] [--block-ms M] [--rounds R]\n",
                    argv[0]);
            return 2;
        }
    }
    if (n < 1 || rounds < 1 || !(block_ms > 0)) return 2;

#ifdef __VERSION__
    printf("compiler %s\n", __VERSION__);
#endif
    /* every input form of both precisions, before anything is counted */
    for (p = 0; p < 2; ++p) cost_make(p == 0 ? 24 : 53, (uint64_t)seed, n, &data[p]);
    for (i = 0; i < COST_NLOOPS; ++i) {
        const cost_loop *l = &cost_loops[i];
        const cost_data *d = &data[l->prec == 24 ? 0 : 1];
        na[i] = cost_probe(l, l->input == IN_EP ? &d->ep : &d->lib);
    }

    if (!time_mode) {
        for (i = 0; i < COST_NLOOPS; ++i) {
            const cost_loop *l = &cost_loops[i];
            const cost_data *d = &data[l->prec == 24 ? 0 : 1];
            const cost_set *s = l->input == IN_EP ? &d->ep : &d->lib;
            if (na[i]) {
                printf("na %d %s %d\n", l->prec, l->name, na[i]);
                continue;
            }
            printf("cost %d %s %d\n", l->prec, l->name, s->n);
            fflush(stdout);
            cost_run(l->fn, s);
        }
    } else {
        /* calibrate each loop to about block_ms, then rounds of every loop in turn, starting
           with a different one each round; the fastest round counts (interference only ever
           adds time) */
        for (i = 0; i < COST_NLOOPS; ++i) {
            const cost_loop *l = &cost_loops[i];
            const cost_data *d = &data[l->prec == 24 ? 0 : 1];
            const cost_set *s = l->input == IN_EP ? &d->ep : &d->lib;
            double t1;
            best[i] = (double)INFINITY;
            reps[i] = 1;
            if (na[i]) continue;
            t1 = cost_time_loop(l, s, 1);
            reps[i] = (int)(block_ms * 1e-3 / (t1 > 1e-7 ? t1 : 1e-7));
            if (reps[i] < 1) reps[i] = 1;
        }
        for (rd = 0; rd < rounds; ++rd)
            for (p = 0; p < COST_NLOOPS; ++p) {
                int j = (p + rd * 7) % COST_NLOOPS;
                const cost_loop *l = &cost_loops[j];
                const cost_data *d = &data[l->prec == 24 ? 0 : 1];
                const cost_set *s = l->input == IN_EP ? &d->ep : &d->lib;
                double t;
                if (na[j]) continue;
                t = cost_time_loop(l, s, reps[j]);
                if (t < best[j]) best[j] = t;
            }
        for (i = 0; i < COST_NLOOPS; ++i) {
            const cost_loop *l = &cost_loops[i];
            const cost_data *d = &data[l->prec == 24 ? 0 : 1];
            const cost_set *s = l->input == IN_EP ? &d->ep : &d->lib;
            double ns, ns_empty = 0;
            int e;
            if (na[i]) {
                printf("na %d %s %d\n", l->prec, l->name, na[i]);
                continue;
            }
            for (e = 0; e < COST_NLOOPS; ++e)
                if (cost_loops[e].prec == l->prec && !strcmp(cost_loops[e].name, "empty"))
                    ns_empty = best[e] / ((double)s->n * reps[e]) * 1e9;
            ns = best[i] / ((double)s->n * reps[i]) * 1e9;
            if (strcmp(l->name, "empty") != 0) ns -= ns_empty;
            printf("time %d %s %d %.3f\n", l->prec, l->name, s->n, ns);
        }
    }
    for (p = 0; p < 2; ++p) cost_free(&data[p]);
    return 0;
}
