/* bench.c: error against run time, every variant side by side on the same seeded cases.
 *
 *   build/bench/bench [--seed S] [--n N] [--rounds R] [--block-ms M] [--json FILE]
 *
 * For each precision, family and caps on/off: N cases (bench/cases.c), their exact answers
 * (ref/cyl_ref.c), the accuracy metrics of every variant (bench/eval.c), then the time per
 * call: R rounds, in each round every variant runs once over the N cases (repeated to about
 * M milliseconds), starting with a different variant each round; the fastest round counts
 * (on a shared machine interference only adds time).
 * Prints a summary and writes all numbers to FILE (JSON) for bench/report.py.
 * `make report` runs it with the defaults. */
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

int main(int argc, char **argv)
{
    unsigned long long seed = 20261122ull;
    int n = 6000, rounds = 9, i, prec_i, fam, caps, first = 1;
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
        else {
            fprintf(stderr, "usage: %s [--seed S] [--n N] [--rounds R] [--block-ms M] [--json F]\n",
                    argv[0]);
            return 2;
        }
    }
    if (n < 1 || rounds < 1 || ev_variant_count > 64) return 2;
    jf = fopen(json, "w");
    if (!jf) { perror(json); return 1; }

    for (i = 0; i < ev_variant_count; ++i) avail[i] = ev_variant_available(&ev_variants[i]);

    fprintf(jf, "{\"seed\": %llu, \"n\": %d, \"rounds\": %d, \"block_ms\": %g,\n", seed, n,
            rounds, block_ms);
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

    printf("seed %llu, %d cases per family x caps x precision\n", seed, n);
    printf("%-6s %-9s %-4s %-27s %6s %6s %6s %9s %9s %10s %6s %8s\n", "prec", "family", "caps",
           "variant", "miscl", ">band", "cmp", "ulp_p99", "ulp_max", "terr_fail", "ns",
           "wcond");

    for (prec_i = 0; prec_i < 2; ++prec_i) {
        int prec = prec_i == 0 ? 24 : 53;
        for (fam = 0; fam < BF_COUNT; ++fam) {
            for (caps = 0; caps < 2; ++caps) {
                ev_set s;
                ev_stats st[64];
                int vidx[64], nv = 0, reps, rd, j;
                double *times;
                ev_set_make(&s, prec, fam, caps, (uint64_t)seed, n);
                for (i = 0; i < ev_variant_count; ++i) {
                    const ev_variant *v = &ev_variants[i];
                    if (v->prec != prec || !avail[i]) continue;
                    if (v->kind == EV_QUILEZ && !caps) continue;   /* capped-only formulation */
                    vidx[nv++] = i;
                }
                for (j = 0; j < nv; ++j) ev_eval(&ev_variants[vidx[j]], &s, &st[j]);

                /* timing: calibrate on the first variant, then interleaved rounds */
                {
                    double t1 = ev_variants[vidx[0]].time[caps](s.rays, s.cyls, n, 1);
                    reps = (int)(block_ms * 1e-3 / (t1 > 1e-7 ? t1 : 1e-7));
                    if (reps < 1) reps = 1;
                }
                times = (double *)malloc(sizeof(double) * (size_t)(nv * rounds));
                if (!times) return 1;
                for (rd = 0; rd < rounds; ++rd)
                    for (j = 0; j < nv; ++j) {
                        int jj = (j + rd) % nv;
                        const ev_variant *v = &ev_variants[vidx[jj]];
                        times[jj * rounds + rd] = v->time[caps](s.rays, s.cyls, n, reps);
                    }
                for (j = 0; j < nv; ++j) {
                    qsort(times + j * rounds, (size_t)rounds, sizeof(double), cmp_dbl);
                    /* fastest round: on a shared machine, interference only ever adds time */
                    st[j].ns_per_call = times[j * rounds] / ((double)n * reps) * 1e9;
                }
                free(times);

                for (j = 0; j < nv; ++j) {
                    const ev_variant *v = &ev_variants[vidx[j]];
                    const ev_stats *t = &st[j];
                    printf("%-6s %-9s %-4d %-27s %6d %6d %6d %9.3g %9.3g %5d/%-5d %6.1f %8.3g\n",
                           prec == 24 ? "float" : "double", bench_family_name(fam), caps,
                           v->name, t->miscls, t->miscls_out, t->compared, t->ulp_p99,
                           t->ulp_max, t->terr_fail, t->terr_checked, t->ns_per_call,
                           t->cond_ulp_max);
                    fprintf(jf, "%s  {\"prec\": %d, \"family\": \"%s\", \"caps\": %d, "
                                "\"variant\": \"%s\", \"kind\": %d, \"opts\": %u, ",
                            first ? "" : ",\n", prec, bench_family_name(fam), caps, v->name,
                            v->kind, v->opts);
                    first = 0;
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
                    jnum(jf, "rel_max", t->rel_max, 1);
                    jnum(jf, "nrm_max", t->nrm_max, 1);
                    jnum(jf, "ns", t->ns_per_call, 0);
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
