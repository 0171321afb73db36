/* cyl_ref.h: exact reference for ray/cylinder intersection (MPFR), for the tests, the fuzzer
 * and the benchmark of cylinder_isect.h.
 *
 * Build: compile ref/cyl_ref.c (C99) and link with -lmpfr -lgmp (Debian: libmpfr-dev).
 *        Include "cylinder_isect.h" is needed on the include path (-I<repo root>): the reference
 *        takes the result codes, option bits, part and flag values and the tolerance macros
 *        from it, so it always follows the library's contract.
 *
 *   cyl_ref_case in;  cyl_ref_result res;
 *   cyl_ref_from_f(&in, &ray, &cyl, opts);      (or cyl_ref_from_d for double inputs)
 *   cyl_ref_intersect(&in, &res);
 *   res.status, res.hit[0] ...                    what cylf_intersect must answer
 *   res.count, res.hit[0..1]                      what cylf_intersect_all must answer
 *   res.margin                                    how close the case is to a decision boundary
 *   cyl_ref_t_within(&res.hit[0], hit.t, hit.t_err)   exact check of the library's error bound
 *   cyl_ref_ulps(&res.hit[0], hit.t, 24)              signed error in ulps of the exact t
 *
 * What "exact" means here
 *   The inputs are taken as the given, already rounded numbers (a float converts exactly to
 *   double). Every polynomial quantity (w = o − c, the cross products a×d and a×w, the dot
 *   products, the quadratic's coefficients and discriminant, the tangency and parallel
 *   margins) is computed EXACTLY: each MPFR product gets precision prec(x)+prec(y) and each sum
 *   enough bits to span both operands' exponents, and every operation's ternary value is
 *   checked to be 0 (the program aborts otherwise). So no bit-count argument is needed: the
 *   precision grows with the exponent span of the case (×2^±400 inputs just work). Square
 *   roots and divisions are then done at P = max(320, 2·span + 64) bits, span being the
 *   exponent range of the case's nonzero inputs, so results derived from them (roots t, v,
 *   normals, cap crossings) are correct to far more than the 2^-106 kept in the output.
 *   Every hit-or-miss decision that can be written as the sign of a polynomial (parallel
 *   tolerance, tangency and its tolerance, which side of the discriminant) is decided exactly;
 *   the others (rim, t range) are decided at P bits, i.e. exactly unless the margin is below
 *   about 2^-(P-span), which the reported margins show.
 *
 * Contract implemented (the library's, see cylinder_isect.h)
 *   surface = points at distance r from the axis line with axial coordinate v = â·(x − c) in
 *   [−h/2, h/2]; open tube by default, solid capped cylinder with CYL_CAPS, h = +INFINITY is the
 *   infinite tube; accepted t in [tmin, tmax]; sin θ ≤ parallel tolerance → no wall crossing;
 *   CYL_NO_TANGENT → contacts with |1 − ρ²/r²| ≤ tangent tolerance are misses. The tolerances
 *   are the library's macros for precision 24 (float) or 53 (double), chosen by case.prec.
 *   Open tube: both wall crossings; capped: entry and exit of the solid. Validation errors are
 *   returned in the library's order, also under CYL_TRUSTED (whose answer for invalid input is
 *   unspecified: compare only valid cases).
 */
#ifndef CYL_REF_H
#define CYL_REF_H

#include "cylinder_isect.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cyl_ref_case {
    double o[3], d[3], tmin, tmax;  /* the ray as given (float values convert exactly) */
    double c[3], a[3], r, h;        /* the cylinder as given */
    unsigned opts;                  /* CYL_* option bits (CAPS, NO_TANGENT, OUTWARD matter) */
    int prec;                       /* 24: float tolerances, 53: double tolerances */
} cyl_ref_case;

typedef struct cyl_ref_hit {
    double t[3];      /* exact t ≈ t[0] + t[1] + t[2] (t[0] is t rounded to nearest double;
                         the sum is within 2^-150 relative of the exact root) */
    double n[3];      /* unit normal, ray-facing (n·d ≤ 0), or outward with CYL_OUTWARD */
    double v;         /* axial coordinate â·(x − c) of the hit */
    int part;         /* CYL_SIDE, CYL_CAP_LOW, CYL_CAP_HIGH */
    unsigned flags;   /* CYL_F_INSIDE, CYL_F_TANGENT, CYL_F_PARALLEL as the library defines them */
} cyl_ref_hit;

typedef struct cyl_ref_result {
    int status;          /* CYL_HIT, CYL_MISS or the CYL_E_* code the library must return */
    int count;           /* number of hits intersect_all must return (0..2) */
    cyl_ref_hit hit[2];  /* sorted by t; hit[0] is intersect's answer */
    /* Conditioning of the case (exact values, rounded to double) */
    double e;            /* 1 − ρ²/r², ρ = distance between the ray line and the axis line */
    double sin2;         /* sin² of the angle between d and the axis */
    /* Decision margins: distance to the nearest boundary where the answer changes.
       A library decision farther than a few ulps from every boundary must be right. */
    double m_tangent;    /* |e| (and |e − tol| under CYL_NO_TANGENT): absolute, e is relative */
    double m_parallel;   /* |sin θ / tol_parallel − 1| (1 when the ray is exactly parallel) */
    double m_rim;        /* min over the candidate crossings: wall: ||v| − h/2| / (h/2),
                            cap plane: |ρ_x − r| / r (ρ_x = the crossing's distance to the axis);
                            +inf for the infinite tube */
    double m_trange;     /* min over surface crossings of dist(t, {tmin, tmax}) / max(|t|, r/|d|) */
    double margin;       /* min of the four */
    int prec_bits;       /* P used for square roots and divisions (≥ 320) */
} cyl_ref_result;

/* The exact answer for the case; returns res->status. */
int cyl_ref_intersect(const cyl_ref_case *in, cyl_ref_result *res);

/* Exact: 1 when the reference t of h lies in [t − t_err, t + t_err], else 0. */
int cyl_ref_t_within(const cyl_ref_hit *h, double t, double t_err);

/* The unit in the last place of the exact t at precision prec (24 or 53), with the subnormal
   ulp as a floor; and (t − exact t) in those units. */
double cyl_ref_ulp(const cyl_ref_hit *h, int prec);
double cyl_ref_ulps(const cyl_ref_hit *h, double t, int prec);

#ifndef CYL_NO_FLOAT
void cyl_ref_from_f(cyl_ref_case *in, const cylf_ray *ray, const cylf_cylinder *cyl,
                    unsigned opts);
#endif
#ifndef CYL_NO_DOUBLE
void cyl_ref_from_d(cyl_ref_case *in, const cyld_ray *ray, const cyld_cylinder *cyl,
                    unsigned opts);
#endif

#ifdef __cplusplus
}
#endif

#endif /* CYL_REF_H */
