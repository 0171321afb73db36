/* Side-by-side timing of the configurations of embedded/configs.txt on this machine: ns per
 * call of each configuration's wrapper over the same rays, the configurations interleaved
 * (every round times each of them once, in a rotated order) so that drift in the machine's load
 * hits all of them alike. Prints CSV: config,precision,ns_median,ns_q1,ns_q3,results,ratio,
 * where ratio = median / median of the "open" configuration of the same precision.
 * Built and run by scripts/cross.sh sizes; the list of wrappers comes from cfg_list.h, which
 * that script generates from embedded/configs.txt. Timing is reported, never asserted. */
#define _POSIX_C_SOURCE 199309L
#include "cylinder_isect.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Rays per timed pass and timed rounds: a pass is long enough (tens of microseconds) for the
 * clock, a round short enough that load changes between configurations are rare. */
#define N_RAYS 2048
#define N_ROUNDS_DEFAULT 61

unsigned cfg_runtime_opts = 0u;
int cfg_runtime_entry = 0;

#define CFG(p, name, rt, entry) \
    int cfg##p##_##name(const cyl##p##_ray *ray, const cyl##p##_cylinder *cyl, cyl##p##_hit hits[2]);
#include "cfg_list.h"
#undef CFG

typedef struct cfg_entry {
    const char *name;
    char prec;
    int (*ff)(const cylf_ray *, const cylf_cylinder *, cylf_hit[2]);
    int (*fd)(const cyld_ray *, const cyld_cylinder *, cyld_hit[2]);
} cfg_entry;

#define CFG_f(name) { #name, 'f', cfgf_##name, NULL },
#define CFG_d(name) { #name, 'd', NULL, cfgd_##name },
#define CFG(p, name, rt, entry) CFG_##p(name)
static const cfg_entry cfgs[] = {
#include "cfg_list.h"
};
#undef CFG
#define N_CFGS (sizeof cfgs / sizeof cfgs[0])

static cylf_ray rays_f[N_RAYS];
static cyld_ray rays_d[N_RAYS];
static cylf_cylinder cyl_f;
static cyld_cylinder cyl_d;

/* Deterministic uniform numbers in [0, 1): a 64-bit LCG (Knuth's MMIX constants). */
static unsigned long long lcg_state = 0x2545F4914F6CDD1DULL;
static double uniform(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) * (1.0 / 9007199254740992.0);
}

/* A tilted, capped cylinder and rays from a sphere around it aimed at its bounding box, so that
 * about half of them hit, with directions of varied length. */
static void make_scene(void)
{
    static const double c[3] = { 0.25, -0.5, 1.0 }, a[3] = { 0.3, 1.0, -0.2 };
    int i, k;
    for (k = 0; k < 3; k++) {
        cyl_d.c[k] = c[k];
        cyl_d.a[k] = a[k];
    }
    cyl_d.r = 0.75;
    cyl_d.h = 3.0;
    for (i = 0; i < N_RAYS; i++) {
        double o[3], tgt[3], len = 0.0, z = 2.0 * uniform() - 1.0, phi = 6.283185307179586 * uniform();
        double s = sqrt(1.0 - z * z), scale = 0.5 + 1.5 * uniform();
        o[0] = c[0] + 6.0 * s * cos(phi);
        o[1] = c[1] + 6.0 * s * sin(phi);
        o[2] = c[2] + 6.0 * z;
        for (k = 0; k < 3; k++) tgt[k] = c[k] + 2.4 * (2.0 * uniform() - 1.0);
        for (k = 0; k < 3; k++) len += (tgt[k] - o[k]) * (tgt[k] - o[k]);
        len = sqrt(len);
        for (k = 0; k < 3; k++) {
            rays_d[i].o[k] = o[k];
            rays_d[i].d[k] = (tgt[k] - o[k]) / len * scale;
        }
        rays_d[i].tmin = 0.0;
        rays_d[i].tmax = 1e30;
    }
    for (k = 0; k < 3; k++) {
        cyl_f.c[k] = (float)cyl_d.c[k];
        cyl_f.a[k] = (float)cyl_d.a[k];
    }
    cyl_f.r = (float)cyl_d.r;
    cyl_f.h = (float)cyl_d.h;
    for (i = 0; i < N_RAYS; i++) {
        for (k = 0; k < 3; k++) {
            rays_f[i].o[k] = (float)rays_d[i].o[k];
            rays_f[i].d[k] = (float)rays_d[i].d[k];
        }
        rays_f[i].tmin = 0.0f;
        rays_f[i].tmax = 1e30f;
    }
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* One pass of a configuration over every ray; returns the sum of the results (kept, so the
 * calls cannot be dropped, and printed, so that configurations can be compared for sanity). */
static long run_pass(const cfg_entry *e)
{
    long sum = 0;
    int i;
    if (e->prec == 'f') {
        cylf_hit hits[2];
        for (i = 0; i < N_RAYS; i++) sum += e->ff(&rays_f[i], &cyl_f, hits);
    } else {
        cyld_hit hits[2];
        for (i = 0; i < N_RAYS; i++) sum += e->fd(&rays_d[i], &cyl_d, hits);
    }
    return sum;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

int main(void)
{
    int rounds = N_ROUNDS_DEFAULT, r;
    size_t k, open_f = N_CFGS, open_d = N_CFGS;
    static double ns[N_CFGS][1001];
    long results[N_CFGS];
    const char *env = getenv("TIMING_ROUNDS");
    if (env != NULL) rounds = atoi(env);
    if (rounds < 5) rounds = 5;
    if (rounds > 1001) rounds = 1001;
    make_scene();
    for (k = 0; k < N_CFGS; k++) results[k] = run_pass(&cfgs[k]); /* warm up caches and predictors */
    for (r = 0; r < rounds; r++) {
        for (k = 0; k < N_CFGS; k++) {
            size_t j = (k + (size_t)r) % N_CFGS;
            double t0 = now_ns();
            long s = run_pass(&cfgs[j]);
            double t1 = now_ns();
            if (s != results[j]) {
                fprintf(stderr, "timing: %s changed its results between passes\n", cfgs[j].name);
                return 1;
            }
            ns[j][r] = (t1 - t0) / N_RAYS;
        }
    }
    for (k = 0; k < N_CFGS; k++) {
        qsort(ns[k], (size_t)rounds, sizeof(double), cmp_double);
        if (strcmp(cfgs[k].name, "open") == 0) {
            if (cfgs[k].prec == 'f') open_f = k; else open_d = k;
        }
    }
    printf("config,precision,ns_median,ns_q1,ns_q3,results,ratio\n");
    for (k = 0; k < N_CFGS; k++) {
        size_t ref = cfgs[k].prec == 'f' ? open_f : open_d;
        double med = ns[k][rounds / 2];
        double ratio = ref < N_CFGS ? med / ns[ref][rounds / 2] : 0.0;
        printf("%s,%c,%.2f,%.2f,%.2f,%ld,%.3f\n", cfgs[k].name, cfgs[k].prec, med, ns[k][rounds / 4],
               ns[k][(3 * rounds) / 4], results[k], ratio);
    }
    return 0;
}
