/* eval.h: variants, case sets and accuracy/timing metrics shared by the benchmark (bench.c)
 * and the accuracy test (test_accuracy.c). Build with ref/cyl_ref.c and bench/cases.c,
 * link -lmpfr -lgmp -lm. */
#ifndef BENCH_EVAL_H
#define BENCH_EVAL_H

#include "cylinder_isect.h"
#include "cyl_ref.h"
#include "cases.h"

enum { EV_LIB, EV_LITERAL, EV_ENDPOINT };

/* One set's cases in every variant's own input form, prepared before any call is timed. */
typedef struct ev_inputs {
    int n;
    void *rays, *cyls;      /* cylf_ or cyld_ ray and cylinder: the library; literal's ray */
    void *lit;              /* altf_/altd_literal_cyl (unit axis) */
    void *ep_rays, *ep;     /* unit-direction rays (t range scaled), altf_/altd_endpoint_cyl */
    double *ep_scale;       /* |d|: a case's t is the unit-direction ray's t / |d| */
} ev_inputs;

/* One variant's answer for one case, in the case's units. The alternatives' normals are
   outward (they do not turn them towards the ray) and their t_err is +INFINITY. */
typedef struct ev_out {
    int rc;
    double t, t_err, n[3];
    int part;
    unsigned flags;
} ev_out;

typedef int (*ev_call_fn)(const ev_inputs *in, int i, ev_out *o);
typedef double (*ev_time_fn)(const ev_inputs *in, int reps);

typedef struct ev_variant {
    const char *name;       /* "lib", "lib+PRECISE", "literal", "endpoint", ... */
    int prec;               /* 24 (float) or 53 (double) */
    int kind;               /* EV_LIB, EV_LITERAL, EV_ENDPOINT */
    unsigned opts;          /* the library's option bits other than CYL_CAPS (0 for the others) */
    ev_call_fn call[2];     /* [caps]: one call with constant options */
    ev_time_fn time[2];     /* [caps]: seconds for reps passes over in->n cases */
} ev_variant;

extern const ev_variant ev_variants[];
extern const int ev_variant_count;

/* One family in one precision with caps on or off, with its exact reference answers. */
typedef struct ev_set {
    int prec, family, caps, n;
    bench_case *cases;
    ev_inputs all;              /* every case: the accuracy */
    ev_inputs timed;            /* the cases timed and counted: with caps those of finite
                                   height (the end-point formulation cannot express the
                                   others, and every variant runs the same cases); without
                                   caps every case */
    cyl_ref_result *ref;        /* NULL from ev_set_inputs */
} ev_set;

/* The cases and their inputs, then (ev_set_make) the exact reference answers. */
void ev_set_inputs(ev_set *s, int prec, int family, int caps, uint64_t seed, int n);
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
    double stab_max;            /* max ulps / ev_kappa_full over compared hits above the band */
    int stab_worst_index;
    double nrm_max;             /* max |n - n_exact| (about the angle), margin above the band */
    int terr_checked, terr_fail;            /* exact t outside [t - t_err, t + t_err] */
    double terr_ulp_max;        /* widest t_err in ulps of the exact t, well-conditioned hits */
    int terr_fail_index;
    int all_miscls, all_miscls_out;   /* intersect_all: count, part or crossing differs */
    int occ_miscls, occ_miscls_out;   /* occluded differs from "the reference has a hit" */
} ev_stats;

/* One call of a variant on case i of the set (every case). */
void ev_run(const ev_variant *v, const ev_set *s, int i, ev_out *o);

/* Can this variant express case i (the end-point formulation: capped, finite height)? */
int ev_expressible(const ev_variant *v, const ev_set *s, int i);

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

/* The full first-order condition of t (every datum moved by a relative u), in units of u|t|:
   the ulps a backward-stable method may err by, about. */
double ev_kappa_full(const ev_set *s, int i);

#endif
