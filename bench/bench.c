/* bench.c: error against run time, every variant side by side on the same seeded cases.
 *
 *   build/bench/bench [--seed S] [--n N] [--rounds R] [--block-ms M] [--json FILE] [--time-only]
 *   build/bench/bench --insn-all [--seed S] [--n N]          (run under callgrind, see below)
 *
 * For each precision, family and caps on/off: N cases (bench/cases.c), their exact answers
 * (ref/cyl_ref.c), the accuracy metrics of every variant (bench/eval.c), then the time per
 * call: R rounds, in each round every variant runs once over the set's timed cases (with caps
 * those of finite height, see eval.h), repeated to about M milliseconds, starting with a
 * different variant each round; the fastest round counts (on a shared machine interference
 * only adds time). Every variant runs on its own inputs, prepared before timing (eval.c).
 * Prints a summary and writes all numbers to FILE (JSON) for bench/report.py.
 * --time-only: the same timing without the reference and the accuracy (seconds, not
 * minutes), so that `make report` can take the median of several runs.
 * --insn-all: for every set and variant (and an empty loop, variant "none"), calls
 * bench_insn_run once, which runs the variant's timing loop once over the set's timed cases;
 * before each call it prints "insn PREC FAMILY CAPS VARIANT CASES". Run under
 * `valgrind --tool=callgrind --toggle-collect=bench_insn_run --dump-after=bench_insn_run`,
 * the k-th dump counts the k-th call: `make insn` pairs them and subtracts the empty loop.
 * `make report` runs all three. */
#include "eval.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef BENCH_CFLAGS
#define BENCH_CFLAGS "?"
#endif

static void jnum(FILE *f, const char *key, double x, int comma)
{
    if (isnan(x)) fprintf(f, "\"%s\": NaN", key);
    else if (isinf(x)) fprintf(f, "\"%s\": %sInfinity", key, x < 0 ? "-" : "");
    else fprintf(f, "\"%s\": %.9g", key, x);
    if (comma) fputs(", ", f);
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

static volatile double insn_sink;

#if defined(__GNUC__)
__attribute__((noinline))
#endif
void bench_insn_run(const ev_variant *v, const ev_inputs *in, int caps);

/* The variant's timing loop once (the code the benchmark times); NULL: a loop of the same
   shape without a call, whose count, subtracted, leaves each call and its share of the loop. */
void bench_insn_run(const ev_variant *v, const ev_inputs *in, int caps)
{
    const char *rays = (const char *)in->rays;
    size_t rs = v ? 0 : sizeof(cylf_ray);
    double acc = 0;
    int i;
    if (v) {
        insn_sink = v->time[caps](in, 1);
        return;
    }
    for (i = 0; i < in->n; ++i) acc += (double)(unsigned char)rays[(size_t)i * rs];
    insn_sink = acc;
}

static int insn_all(unsigned long long seed, int n, const int *avail)
{
    int prec_i, fam, caps, i;
    for (prec_i = 0; prec_i < 2; ++prec_i) {
        int prec = prec_i == 0 ? 24 : 53;
        for (fam = 0; fam < BF_COUNT; ++fam)
            for (caps = 0; caps < 2; ++caps) {
                ev_set s;
                ev_set_inputs(&s, prec, fam, caps, (uint64_t)seed, n);
                for (i = -1; i < ev_variant_count; ++i) {
                    const ev_variant *v = i < 0 ? NULL : &ev_variants[i];
                    if (v && (v->prec != prec || !avail[i] || (v->kind == EV_ENDPOINT && !caps)))
                        continue;
                    printf("insn %d %s %d %s %d\n", prec, bench_family_name(fam), caps,
                           v ? v->name : "none", s.timed.n);
                    fflush(stdout);
                    bench_insn_run(v, &s.timed, caps);
                }
                ev_set_free(&s);
            }
    }
    return 0;
}

/* ns per call of each of the nv variants vidx[] on the set's timed cases */
static int time_set(const ev_set *s, const int *vidx, int nv, int rounds, double block_ms,
                    double *ns)
{
    int caps = s->caps, reps, rd, j;
    double *times;
    if (s->timed.n < 1) {
        for (j = 0; j < nv; ++j) ns[j] = (double)NAN;
        return 0;
    }
    /* calibrate on the first variant, then interleaved rounds */
    {
        double t1 = ev_variants[vidx[0]].time[caps](&s->timed, 1);
        reps = (int)(block_ms * 1e-3 / (t1 > 1e-7 ? t1 : 1e-7));
        if (reps < 1) reps = 1;
    }
    times = (double *)malloc(sizeof(double) * (size_t)(nv * rounds));
    if (!times) return 1;
    for (rd = 0; rd < rounds; ++rd)
        for (j = 0; j < nv; ++j) {
            int jj = (j + rd) % nv;
            const ev_variant *v = &ev_variants[vidx[jj]];
            times[jj * rounds + rd] = v->time[caps](&s->timed, reps);
        }
    for (j = 0; j < nv; ++j) {
        qsort(times + j * rounds, (size_t)rounds, sizeof(double), cmp_dbl);
        /* fastest round: on a shared machine, interference only ever adds time */
        ns[j] = times[j * rounds] / ((double)s->timed.n * reps) * 1e9;
    }
    free(times);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned long long seed = 20261122ull;
    int n = 6000, rounds = 9, i, prec_i, fam, caps, first = 1, time_only = 0, insn = 0;
    double block_ms = 4.0;
    const char *json = "build/bench/results.json";
    FILE *jf;
    int avail[64];

    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--n") && i + 1 < argc) n = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--rounds") && i + 1 < argc) rounds = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--block-ms") && i + 1 < argc) block_ms = atof(argv[++i]);
        else if (!strcmp(argv[i], "--json") && i + 1 < argc) json = argv[++i];
        else if (!strcmp(argv[i], "--time-only")) time_only = 1;
        else if (!strcmp(argv[i], "--insn-all")) insn = 1;
        else {
            fprintf(stderr, "usage: %s [--seed S] [--n N] [--rounds R] [--block-ms M] [--json F] "
                            "[--time-only | --insn-all]\n", argv[0]);
            return 2;
        }
    }
    if (n < 1 || rounds < 1 || ev_variant_count > 64) return 2;
    for (i = 0; i < ev_variant_count; ++i) avail[i] = ev_variant_available(&ev_variants[i]);
    if (insn) return insn_all(seed, n, avail);
    jf = fopen(json, "w");
    if (!jf) { perror(json); return 1; }

    fprintf(jf, "{\"seed\": %llu, \"n\": %d, \"rounds\": %d, \"block_ms\": %g, "
                "\"time_only\": %d,\n", seed, n, rounds, block_ms, time_only);
#ifdef __VERSION__
    fprintf(jf, " \"compiler\": \"%s\",\n", __VERSION__);
#endif
    fprintf(jf, " \"cflags\": \"%s\",\n \"families\": [", BENCH_CFLAGS);
    for (fam = 0; fam < BF_COUNT; ++fam)
        fprintf(jf, "%s\"%s\"", fam ? ", " : "", bench_family_name(fam));
    fprintf(jf, "],\n \"unavailable\": [");
    {
        int c = 0;
        for (i = 0; i < ev_variant_count; ++i)
            if (!avail[i])
                fprintf(jf, "%s\"%s %s\"", c++ ? ", " : "", ev_variants[i].prec == 24 ? "float"
                                                                                    : "double",
                        ev_variants[i].name);
    }
    fprintf(jf, "],\n \"rows\": [\n");

    printf("seed %llu, %d cases per family x caps x precision%s\n", seed, n,
           time_only ? ", timing only" : "");
    if (!time_only)
        printf("%-6s %-9s %-4s %-27s %6s %6s %6s %9s %9s %10s %6s %8s\n", "prec", "family", "caps",
           "variant", "miscl", ">band", "cmp", "ulp_p99", "ulp_max", "terr_fail", "ns",
           "wcond");

    for (prec_i = 0; prec_i < 2; ++prec_i) {
        int prec = prec_i == 0 ? 24 : 53;
        for (fam = 0; fam < BF_COUNT; ++fam) {
            for (caps = 0; caps < 2; ++caps) {
                ev_set s;
                ev_stats st[64];
                double ns[64];
                int vidx[64], nv = 0, j;
                if (time_only) ev_set_inputs(&s, prec, fam, caps, (uint64_t)seed, n);
                else ev_set_make(&s, prec, fam, caps, (uint64_t)seed, n);
                for (i = 0; i < ev_variant_count; ++i) {
                    const ev_variant *v = &ev_variants[i];
                    if (v->prec != prec || !avail[i]) continue;
                    if (v->kind == EV_ENDPOINT && !caps) continue;  /* capped-only formulation */
                    vidx[nv++] = i;
                }
                memset(st, 0, sizeof st);
                if (!time_only)
                    for (j = 0; j < nv; ++j) ev_eval(&ev_variants[vidx[j]], &s, &st[j]);
                if (time_set(&s, vidx, nv, rounds, block_ms, ns)) return 1;

                for (j = 0; j < nv; ++j) {
                    const ev_variant *v = &ev_variants[vidx[j]];
                    const ev_stats *t = &st[j];
                    fprintf(jf, "%s  {\"prec\": %d, \"family\": \"%s\", \"caps\": %d, "
                                "\"variant\": \"%s\", \"kind\": %d, \"opts\": %u, \"timed_n\": %d, ",
                            first ? "" : ",\n", prec, bench_family_name(fam), caps, v->name,
                            v->kind, v->opts, s.timed.n);
                    first = 0;
                    if (time_only) {
                        jnum(jf, "ns", ns[j], 0);
                        fputc('}', jf);
                        continue;
                    }
                    printf("%-6s %-9s %-4d %-27s %6d %6d %6d %9.3g %9.3g %5d/%-5d %6.1f %8.3g\n",
                           prec == 24 ? "float" : "double", bench_family_name(fam), caps,
                           v->name, t->miscls, t->miscls_out, t->compared, t->ulp_p99,
                           t->ulp_max, t->terr_fail, t->terr_checked, ns[j], t->cond_ulp_max);
                    fprintf(jf, "\"n\": %d, \"n_error\": %d, \"ref_hits\": %d, \"lib_hits\": %d, "
                                "\"miscls\": %d, \"miscls_out\": %d, \"worst_index\": %d, ",
                            t->n, t->n_error, t->ref_hits, t->lib_hits, t->miscls, t->miscls_out,
                            t->miscls_worst_index);
                    jnum(jf, "worst_margin", t->miscls_worst_margin, 1);
                    fprintf(jf, "\"all_miscls\": %d, \"all_miscls_out\": %d, \"occ_miscls\": %d, "
                                "\"occ_miscls_out\": %d, ",
                            t->all_miscls, t->all_miscls_out, t->occ_miscls, t->occ_miscls_out);
                    fprintf(jf, "\"compared\": %d, \"cond_n\": %d, \"cond_worst_index\": %d, "
                                "\"terr_checked\": %d, \"terr_fail\": %d, \"terr_fail_index\": %d, ",
                            t->compared, t->cond_n, t->cond_worst_index, t->terr_checked,
                            t->terr_fail, t->terr_fail_index);
                    jnum(jf, "ulp_median", t->ulp_median, 1);
                    jnum(jf, "ulp_p99", t->ulp_p99, 1);
                    jnum(jf, "ulp_max", t->ulp_max, 1);
                    jnum(jf, "cond_ulp_max", t->cond_ulp_max, 1);
                    jnum(jf, "stab_max", t->stab_max, 1);
                    fprintf(jf, "\"stab_worst_index\": %d, ", t->stab_worst_index);
                    jnum(jf, "rel_max", t->rel_max, 1);
                    jnum(jf, "nrm_max", t->nrm_max, 1);
                    jnum(jf, "ns", ns[j], 0);
                    fputc('}', jf);
                }
                fflush(stdout);
                ev_set_free(&s);
            }
        }
    }
    fprintf(jf, "\n]}\n");
    fclose(jf);
    return 0;
}
