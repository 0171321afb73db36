/* insn.c: instructions per call of the benchmark's variants, for callgrind to count.
 *
 *   build/bench/insn PREC FAMILY CAPS VARIANT [N]     e.g.  insn 24 well 1 quilez 2000
 *
 * Runs N cases of the family (bench/cases.c, the report's seed) once through one variant's
 * timing loop (eval.c: the code the benchmark times, options folded), inside insn_run;
 * `make insn` runs it under `valgrind --tool=callgrind --toggle-collect=insn_run` (only that
 * function and what it calls is counted) and divides by N. Unlike time, the count is the same
 * on every run of the same binary, whatever else the machine does; it says nothing of latency,
 * mispredictions or cache, so it complements the report's ns/call and does not replace it.
 * VARIANT "none" runs a loop of the same shape without a call. */
#include "eval.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define INSN_SEED 20261122ull

static volatile double insn_sink;

typedef struct insn_io {
    const ev_variant *v;          /* NULL: the empty loop */
    int caps, n;
    const char *rays, *cyls;
    size_t rs, cs;
} insn_io;

#if defined(__GNUC__)
__attribute__((noinline))
#endif
void insn_run(const insn_io *io);

/* A variant runs its timing loop once (one pass, reps = 1): the code the benchmark times, with
   its options folded (eval.c, EV_TIMING). "none" runs a loop of the same shape without a call;
   its count, subtracted, leaves each call and its share of the loop. */
void insn_run(const insn_io *io)
{
    double acc = 0;
    int i;
    if (io->v) {
        insn_sink = io->v->time[io->caps](io->rays, io->cyls, io->n, 1);
        return;
    }
    for (i = 0; i < io->n; ++i) {
        const char *ray = io->rays + (size_t)i * io->rs;
        acc += (double)(unsigned char)ray[0];
    }
    insn_sink = acc;
}

int main(int argc, char **argv)
{
    insn_io io;
    int prec, fam, i, j;
    char *rays, *cyls;
    if (argc < 5) {
        fprintf(stderr, "usage: %s PREC(24|53) FAMILY CAPS(0|1) VARIANT|none [N]\n", argv[0]);
        return 2;
    }
    prec = atoi(argv[1]);
    fam = bench_family_index(argv[2]);
    io.caps = atoi(argv[3]) != 0;
    io.n = argc > 5 ? atoi(argv[5]) : 2000;
    io.v = NULL;
    for (i = 0; i < ev_variant_count; ++i)
        if (ev_variants[i].prec == prec && !strcmp(ev_variants[i].name, argv[4]))
            io.v = &ev_variants[i];
    if ((prec != 24 && prec != 53) || fam == BF_COUNT || io.n < 1 ||
        (!io.v && strcmp(argv[4], "none"))) {
        fprintf(stderr, "insn: unknown precision, family or variant\n");
        return 2;
    }
    io.rs = prec == 24 ? sizeof(cylf_ray) : sizeof(cyld_ray);
    io.cs = prec == 24 ? sizeof(cylf_cylinder) : sizeof(cyld_cylinder);
    rays = (char *)malloc(io.rs * (size_t)io.n);
    cyls = (char *)malloc(io.cs * (size_t)io.n);
    if (!rays || !cyls) return 1;
    for (i = 0; i < io.n; ++i) {
        bench_case k;
        bench_case_gen(fam, prec, INSN_SEED, (uint64_t)i, &k);
        if (prec == 24) {
            cylf_ray *r = (cylf_ray *)(void *)(rays + (size_t)i * io.rs);
            cylf_cylinder *c = (cylf_cylinder *)(void *)(cyls + (size_t)i * io.cs);
            for (j = 0; j < 3; ++j) {
                r->o[j] = (float)k.o[j]; r->d[j] = (float)k.d[j];
                c->c[j] = (float)k.c[j]; c->a[j] = (float)k.a[j];
            }
            r->tmin = (float)k.tmin; r->tmax = (float)k.tmax;
            c->r = (float)k.r; c->h = (float)k.h;
        } else {
            cyld_ray *r = (cyld_ray *)(void *)(rays + (size_t)i * io.rs);
            cyld_cylinder *c = (cyld_cylinder *)(void *)(cyls + (size_t)i * io.cs);
            for (j = 0; j < 3; ++j) {
                r->o[j] = k.o[j]; r->d[j] = k.d[j]; c->c[j] = k.c[j]; c->a[j] = k.a[j];
            }
            r->tmin = k.tmin; r->tmax = k.tmax; c->r = k.r; c->h = k.h;
        }
    }
    io.rays = rays;
    io.cyls = cyls;
    insn_run(&io);
    free(rays);
    free(cyls);
    return 0;
}
