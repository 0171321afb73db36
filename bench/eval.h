/* eval.h: variants, case sets and accuracy/timing metrics shared by the benchmark (bench.c)
 * and the accuracy test (test_accuracy.c). Build with ref/cyl_ref.c and bench/cases.c,
 * link -lmpfr -lgmp -lm. */
#ifndef BENCH_EVAL_H
#define BENCH_EVAL_H

#include "cylinder_isect.h"
#include "cyl_ref.h"
#include "cases.h"

enum { EV_LIB, EV_LITERAL, EV_QUILEZ };

typedef int (*ev_call_fn)(const void *ray, const void *cyl, void *hit);
typedef double (*ev_time_fn)(const void *rays, const void *cyls, int n, int reps);

typedef struct ev_variant {
    const char *name;       /* "lib", "lib+PRECISE", "literal", ... */
    int prec;               /* 24 (float) or 53 (double) */
    int kind;               /* EV_LIB, EV_LITERAL, EV_QUILEZ */
    unsigned opts;          /* option bits other than CYL_CAPS */
    ev_call_fn call[2];     /* [caps]: one call with constant options */
    ev_time_fn time[2];     /* [caps]: seconds for reps passes over n cases */
} ev_variant;

extern const ev_variant ev_variants[];
extern const int ev_variant_count;

/* One family in one precision with caps on or off, with its exact reference answers. */
typedef struct ev_set {
    int prec, family, caps, n;
    bench_case *cases;
    void *rays, *cyls;          /* cylf_ or cyld_ arrays */
    cyl_ref_result *ref;
} ev_set;

void ev_set_make(ev_set *s, int prec, int family, int caps, uint64_t seed, int n);
void ev_set_free(ev_set *s);

/* Is this variant usable in this build (CYL_PRECISE compiled in and implemented)? */
int ev_variant_available(const ev_variant *v);

typedef struct ev_stats {
    int n, n_error;             /* cases, error returns */
    int ref_hits, lib_hits;
    int miscls;                 /* hit/miss, part or crossing different from the reference */
    int miscls_out;             /* ... whose margin exceeds the band 2^-(p-8) */
    double miscls_worst_margin; /* largest margin among the misclassified (0 if none) */
    int miscls_worst_index;     /* case index of that one (-1 if none) */
    int compared;               /* hits compared for t (same part, same crossing) */
    double ulp_median, ulp_p99, ulp_max;   /* |t error| in ulps of the exact t */
    double rel_max;             /* max |t error| / max(|t|, r/|d|) */
    int cond_n;                 /* compared hits that are well-conditioned */
    double cond_ulp_max;        /* max ulps over those */
    int cond_worst_index;
    double nrm_max;             /* max |n - n_exact| (about the angle), margin above the band */
    int terr_checked, terr_fail;            /* exact t outside [t - t_err, t + t_err] */
    int terr_fail_index;
    int all_miscls, all_miscls_out;   /* intersect_all: count, part or crossing differs */
    int occ_miscls, occ_miscls_out;   /* occluded differs from "the reference has a hit" */
    double ns_per_call;         /* filled by bench.c's timing */
} ev_stats;

/* Accuracy of a variant on a set. */
void ev_eval(const ev_variant *v, const ev_set *s, ev_stats *st);

/* Band of margins inside which either answer is accepted: 2^-(p-8). */
double ev_band(int prec);

/* Condition number of the reference hit's t, relative to |t|: grazing wall hits, and hits
   much closer to the origin than the radius crossing time r/|d|, are ill-conditioned. */
double ev_kappa(const ev_set *s, int i);

/* Is the case well-conditioned for t (kappa <= EV_KAPPA_MAX and margin above the band)? */
#define EV_KAPPA_MAX 1.0 /* ulps targets apply where a relative data change u moves t by <= 1 ulp */
int ev_well_conditioned(const ev_set *s, int i);

#endif
