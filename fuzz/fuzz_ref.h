/* fuzz_ref.h: the sampled exact-reference check, on top of ref/cyl_ref.h (MPFR). Included by
 * fuzz_check.h when FUZZ_HAVE_REF is defined (mk/fuzz.mk does so when ref/cyl_ref.c exists);
 * link ref/cyl_ref.c with -lmpfr -lgmp.
 *
 * For both tiers (default and CYL_PRECISE), with the error bound on:
 *   - every library hit whose root the reference also reports (same part and crossing
 *     direction, not tangent) encloses the exact t: t - t_err <= t_exact <= t + t_err;
 *   - where the reference's decision margin is wide (FZ_REF_FACTOR below), the library makes the
 *     same decisions: hit count, part and flags of each hit (outside the header's flat-disk
 *     limit, fz_flat_rim).
 */
#ifndef FUZZ_REF_H
#define FUZZ_REF_H

#include "cyl_ref.h"

/* A library decision may legitimately differ from the exact one within a margin of the
 * library's own rounding: u times the problem's size relative to r (the default path rounds
 * o - c, so an origin at |w| from the axis moves e by about u |w|/r), times a safety factor. */
#define FZ_REF_FACTOR 0x1p12L

/* The header's flat-disk limit (v1: N11): for an origin on the wall of a disk far wider than
 * high and a ray nearly parallel to the axis, the crossing near t = 0 is decided against the
 * rim with an error of about X = r/(h sin) times the solver's double words (2^-106; 2^-46 in a
 * float-only build), times up to 2^10, relative to the rim margin. A margin within that
 * (times 16) is not one the library promises to decide. v2's default tier decides it with
 * plain arithmetic, whose unit roundoff (2^-53; 2^-24 in a float-only build) takes the double
 * words' place (v2's N6); its certified tier (CYL_PRECISE) is held to v1's limit. */
static int fz_flat_rim(const fz_prob *p, const fz_geo *g, fz_real margin, int float_only, int plain)
{
  fz_real rho0 = fz_norm(g->axw);
  fz_real dw = plain ? (float_only ? 0x1p-24L : 0x1p-53L) : (float_only ? 0x1p-46L : 0x1p-106L);
  if (!(g->sin_th > 0) || !isfinite(g->H) || !(g->H > 0)) return 0;
  if (!(fabsl(rho0 - p->r) <= 0x1p-8L * p->r)) return 0; /* the origin on the wall */
  return margin <= 0x1p14L * dw * (p->r / (2 * g->H * g->sin_th));
}

static unsigned long fz_ref_decisions;

#define FZ_DEFINE_REF(P, SUFFIX, PREC)                                                         \
  static void fz_ref_one_##SUFFIX(const char *tier, const P##_ray *ray, const P##_cylinder *cyl, unsigned opts) \
  {                                                                                            \
    cyl_ref_case rc;                                                                           \
    cyl_ref_result rr;                                                                         \
    fz_res lib = fz_call_##SUFFIX(1, ray, cyl, opts, 0, NULL);                                 \
    fz_prob p;                                                                                 \
    fz_geo g;                                                                                  \
    fz_real u = (PREC) == 24 ? FZ_U_F : FZ_U_D, thr;                                          \
    int j, m;                                                                                  \
    cyl_ref_from_##SUFFIX(&rc, ray, cyl, opts);                                                \
    cyl_ref_intersect(&rc, &rr);                                                               \
    if (rr.status < 0) fz_failf("reference: error %d on an input the library accepts", rr.status); \
    for (j = 0; j < lib.rc; j++) {                                                             \
      const fz_hit *h = &lib.h[j];                                                             \
      for (m = 0; m < rr.count; m++) {                                                         \
        const cyl_ref_hit *x = &rr.hit[m];                                                     \
        if (x->part != h->part || ((x->flags ^ h->flags) & CYL_F_INSIDE)) continue;           \
        if ((x->flags | h->flags) & CYL_F_TANGENT) continue;                                  \
        if (!cyl_ref_t_within(x, (double)h->t, (double)h->t_err))                              \
          fz_failf("%s tier: exact t=%.17g is outside t=%La +- %La (hit %d, part %d, %+.3g ulps)", tier, x->t[0], h->t, \
                   h->t_err, j, h->part, cyl_ref_ulps(x, (double)h->t, PREC));                 \
      }                                                                                        \
    }                                                                                          \
    fz_prob_##SUFFIX(ray, cyl, &p);                                                            \
    fz_geometry(&p, &g);                                                                       \
    if (!g.ok) return;                                                                         \
    thr = FZ_REF_FACTOR * u * (1 + fz_abssum(g.w) / p.r);                                      \
    if (!((fz_real)rr.margin > thr)) return;                                                   \
    if (fz_flat_rim(&p, &g, (fz_real)rr.margin, (PREC) == 24 && !CYL_FLOAT_WIDE,              \
                    CYL_VERSION_MAJOR >= 2 && !(opts & CYL_PRECISE))) return;                  \
    /* ref/cyl_ref.c decides the caps of a ray flagged parallel but not exactly parallel by the \
     * distance between the two lines (which meet far away), not by the crossing points: its  \
     * decisions are not used there (reported to the reference's owner) */                    \
    if (rr.sin2 > 0 && sqrt(rr.sin2) <= 2 * ((PREC) == 24 ? (double)CYL_PARALLEL_TOLF : CYL_PARALLEL_TOL)) return; \
    if (!((fz_real)rr.m_trange > thr / sqrtl(fminl(1, (fz_real)rr.m_tangent)))) return;       \
    /* the reference gives t in double and ignores representability: where an exact t is out \
     * of the precision's normal range ("not representable counts as a miss") or two exact   \
     * crossings round to one double (their order is then the reference's guess), the     \
     * decisions are not compared */                                                          \
    for (m = 0; m < rr.count; m++) {                                                           \
      double at = fabs(rr.hit[m].t[0]);                                                        \
      if (!(at < ((PREC) == 24 ? 0x1p124 : 0x1p1020)) || !(at > ((PREC) == 24 ? 0x1p-100 : 0x1p-1000))) return; \
    }                                                                                          \
    if (rr.count == 2 && !(rr.hit[0].t[0] < rr.hit[1].t[0])) return;                           \
    /* and our own long double analysis must agree that every decision is clear */             \
    if (!fz_well_conditioned(&p, &g, opts, u)) return;                                         \
    fz_ref_decisions++;                                                                        \
    if (lib.rc != rr.count)                                                                    \
      fz_failf("%s tier: %d hits, the exact answer has %d (decision margin %.3g)", tier, lib.rc, rr.count, rr.margin); \
    for (j = 0; j < lib.rc; j++)                                                               \
      if (lib.h[j].part != rr.hit[j].part || lib.h[j].flags != rr.hit[j].flags)                \
        fz_failf("%s tier: hit %d is part %d flags 0x%x, exactly part %d flags 0x%x (margin %.3g)", tier, j,      \
                 lib.h[j].part, lib.h[j].flags, rr.hit[j].part, rr.hit[j].flags, rr.margin);  \
  }                                                                                            \
  static void fz_ref_check_##SUFFIX(const P##_ray *ray, const P##_cylinder *cyl, unsigned opts) \
  {                                                                                            \
    unsigned base = opts & ~(unsigned)(CYL_TRUSTED | CYL_NO_ERRBOUND | CYL_PRECISE);           \
    fz_ref_one_##SUFFIX("default", ray, cyl, base);                                            \
    if (fz_precise_available()) fz_ref_one_##SUFFIX("precise", ray, cyl, base | CYL_PRECISE);  \
  }

#ifndef CYL_NO_FLOAT
FZ_DEFINE_REF(cylf, f, 24)
#endif
#ifndef CYL_NO_DOUBLE
FZ_DEFINE_REF(cyld, d, 53)
#endif

#endif /* FUZZ_REF_H */
