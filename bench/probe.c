/* probe.c: one case of the benchmark in full, to reproduce and debug a reported number.
 *
 *   build/bench/probe PREC FAMILY CAPS INDEX [SEED]      e.g.  probe 24 well 1 634
 *
 * Prints the inputs as exact hex floats (ready to paste into a regression test), the exact
 * reference answer with its margins and t condition number, and every variant's answer with
 * its error in ulps. The indices are the ones bench and test_accuracy report. */
#include "eval.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    int prec, fam, caps, idx, i, j;
    unsigned long long seed = 20261122ull;
    ev_set s;
    const cyl_ref_result *ref;
    const bench_case *k;
    if (argc < 5) {
        fprintf(stderr, "usage: %s PREC(24|53) FAMILY CAPS(0|1) INDEX [SEED]\n", argv[0]);
        return 2;
    }
    prec = atoi(argv[1]);
    fam = bench_family_index(argv[2]);
    caps = atoi(argv[3]);
    idx = atoi(argv[4]);
    if (argc > 5) seed = strtoull(argv[5], NULL, 0);
    if (fam == BF_COUNT || (prec != 24 && prec != 53) || idx < 0) return 2;

    ev_set_make(&s, prec, fam, caps, (uint64_t)seed, idx + 1);
    k = &s.cases[idx];
    ref = &s.ref[idx];
    printf("case %s prec %d caps %d index %d seed %llu\n", bench_family_name(fam), prec, caps,
           idx, seed);
    printf("  o = {%a, %a, %a}  d = {%a, %a, %a}\n", k->o[0], k->o[1], k->o[2], k->d[0], k->d[1],
           k->d[2]);
    printf("  c = {%a, %a, %a}  a = {%a, %a, %a}\n", k->c[0], k->c[1], k->c[2], k->a[0], k->a[1],
           k->a[2]);
    printf("  r = %a  h = %a  tmin = %a  tmax = %a\n", k->r, k->h, k->tmin, k->tmax);
    printf("reference: status %d count %d  e %.6g  sin2 %.6g  margins: tangent %.3g parallel "
           "%.3g rim %.3g trange %.3g -> %.3g  kappa %.3g (full %.3g)  well-conditioned %d\n",
           ref->status, ref->count, ref->e, ref->sin2, ref->m_tangent, ref->m_parallel,
           ref->m_rim, ref->m_trange, ref->margin, ev_kappa(&s, idx), ev_kappa_full(&s, idx),
           ev_well_conditioned(&s, idx));
    for (j = 0; j < ref->count; ++j)
        printf("  hit %d: t %.17g (%a)  part %d  flags %u  v %.9g  n {%.9g, %.9g, %.9g}\n", j,
               ref->hit[j].t[0], ref->hit[j].t[0], ref->hit[j].part, ref->hit[j].flags,
               ref->hit[j].v, ref->hit[j].n[0], ref->hit[j].n[1], ref->hit[j].n[2]);
    for (i = 0; i < ev_variant_count; ++i) {
        const ev_variant *v = &ev_variants[i];
        ev_out o;
        double t, te;
        int rc, part;
        unsigned fl;
        if (v->prec != prec) continue;
        if (!ev_expressible(v, &s, idx)) {
            printf("  %-27s cannot express this case\n", v->name);
            continue;
        }
        ev_run(v, &s, idx, &o);
        rc = o.rc; t = o.t; te = o.t_err; part = o.part; fl = o.flags;
        printf("  %-27s rc %2d", v->name, rc);
        if (rc == CYL_HIT)
            printf("  t %.17g  t_err %.3g  part %d  flags %u  ulps %.3g  within %d", t, te, part,
                   fl, ref->count ? cyl_ref_ulps(&ref->hit[0], t, prec) : 0.0,
                   ref->count ? cyl_ref_t_within(&ref->hit[0], t, te) : -1);
        printf("\n");
    }
    ev_set_free(&s);
    return 0;
}
