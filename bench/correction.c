/* correction.c: what a correction step triggered by t_err would cost the default tier, and
 * what accuracy it would buy (`make correction`, `make correction V=2`).
 *
 *   build/bench/correction [--seed S] [--n N]
 *
 * DESIGN.md's bound layer corrects a hit (one compensated Newton step, out of line) where its
 * t_err exceeds K ulps of t. For each precision, each family that issue 28's accuracy target
 * judges (well, huge, tiny, axis) and caps off and on, this prints, over the well-conditioned
 * hits the report judges (bench/eval.c's ev_well_conditioned, the library's part the
 * reference's), for K = 2, 4, ..., 256: the share of hits whose t_err exceeds K ulps (those a
 * step would correct) and the largest error, in ulps of the exact t, among the others (what
 * the step would leave). The library runs with its default options (the report's "lib"
 * variant), the reference is ref/cyl_ref.c (MPFR), the cases bench/cases.c's, as `make report`.
 */
#include "eval.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NK 8

int main(int argc, char **argv)
{
    static const int fams[] = {BF_WELL, BF_HUGE, BF_TINY, BF_AXIS};
    static const int precs[] = {24, 53};
    unsigned long long seed = 20261122ull;
    int n = 6000, a, p, f, caps, i, k;
    for (a = 1; a + 1 < argc; a += 2) {
        if (!strcmp(argv[a], "--seed")) seed = strtoull(argv[a + 1], NULL, 0);
        else if (!strcmp(argv[a], "--n")) n = atoi(argv[a + 1]);
        else break;
    }
    if (a < argc || n < 1) {
        fprintf(stderr, "usage: %s [--seed S] [--n N]\n", argv[0]);
        return 2;
    }
    printf("seed %llu, %d cases per family; per K: share of hits with t_err > K ulps / largest "
           "error (ulps) among the rest\n\n| precision | family | caps | hits | largest error |",
           seed, n);
    for (k = 0; k < NK; ++k) printf(" K = %d |", 2 << k);
    printf("\n|---|---|---|---:|---:|");
    for (k = 0; k < NK; ++k) printf("---:|");
    printf("\n");
    for (p = 0; p < 2; ++p) {
        int vi = -1;
        for (i = 0; i < ev_variant_count; ++i)
            if (ev_variants[i].prec == precs[p] && !strcmp(ev_variants[i].name, "lib")) vi = i;
        if (vi < 0) return 1;
        for (f = 0; f < (int)(sizeof fams / sizeof fams[0]); ++f)
            for (caps = 0; caps < 2; ++caps) {
                ev_set s;
                int hits = 0, corrected[NK] = {0};
                double left[NK] = {0}, worst = 0;
                ev_set_make(&s, precs[p], fams[f], caps, (uint64_t)seed, n);
                for (i = 0; i < n; ++i) {
                    const cyl_ref_hit *h = &s.ref[i].hit[0];
                    ev_out o;
                    double err, ulp;
                    if (s.ref[i].status != CYL_HIT || !ev_well_conditioned(&s, i)) continue;
                    ev_run(&ev_variants[vi], &s, i, &o);
                    if (o.rc != CYL_HIT || o.part != h->part) continue;
                    err = fabs(cyl_ref_ulps(h, o.t, precs[p]));
                    ulp = cyl_ref_ulp(h, precs[p]);
                    hits++;
                    if (err > worst) worst = err;
                    for (k = 0; k < NK; ++k) {
                        if (o.t_err > (2 << k) * ulp) corrected[k]++;
                        else if (err > left[k]) left[k] = err;
                    }
                }
                printf("| %s | %s | %d | %d | %.3g |", precs[p] == 24 ? "float" : "double",
                       bench_family_name(fams[f]), caps, hits, worst);
                for (k = 0; k < NK; ++k)
                    printf(" %.1f%% / %.3g |", hits ? 100.0 * corrected[k] / hits : 0.0, left[k]);
                printf("\n");
                ev_set_free(&s);
            }
    }
    return 0;
}
