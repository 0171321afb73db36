/* cases.c: the case families of cases.h. */
#include "cases.h"

#include <math.h>
#include <string.h>

static const char *const family_names[BF_COUNT] = {
    "well", "far", "parallel", "grazing", "thin", "surface", "huge", "tiny", "axis", "trange",
    "flat"
};

const char *bench_family_name(int family)
{
    return family >= 0 && family < BF_COUNT ? family_names[family] : "?";
}

int bench_family_index(const char *name)
{
    int fam = 0;
    while (fam < BF_COUNT && strcmp(name, bench_family_name(fam)) != 0) ++fam;
    return fam;
}

uint64_t bench_rng_next(uint64_t *state)
{
    uint64_t z = (*state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

double bench_rng_unit(uint64_t *state)
{
    return (double)(bench_rng_next(state) >> 11) * 0x1p-53;
}

static double U(uint64_t *s, double lo, double hi) { return lo + (hi - lo) * bench_rng_unit(s); }
static double LOG10U(uint64_t *s, double lo, double hi) { return pow(10.0, U(s, lo, hi)); }
static int IRAND(uint64_t *s, int n) { return (int)(bench_rng_next(s) % (uint64_t)n); }

static double dot3(const double x[3], const double y[3])
{
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

static void unit_vec(uint64_t *s, double v[3])
{
    double l;
    do {
        v[0] = U(s, -1, 1); v[1] = U(s, -1, 1); v[2] = U(s, -1, 1);
        l = dot3(v, v);
    } while (l > 1.0 || l < 1e-4);
    l = sqrt(l);
    v[0] /= l; v[1] /= l; v[2] /= l;
}

/* a unit vector orthogonal to the unit vector a */
static void perp_vec(uint64_t *s, const double a[3], double p[3])
{
    double l, k;
    do {
        unit_vec(s, p);
        k = dot3(p, a);
        p[0] -= k * a[0]; p[1] -= k * a[1]; p[2] -= k * a[2];
        l = sqrt(dot3(p, p));
    } while (l < 1e-3);
    p[0] /= l; p[1] /= l; p[2] /= l;
}

static void cross3(const double x[3], const double y[3], double r[3])
{
    r[0] = x[1] * y[2] - x[2] * y[1];
    r[1] = x[2] * y[0] - x[0] * y[2];
    r[2] = x[0] * y[1] - x[1] * y[0];
}

/* random cylinder: returns the unit axis in ah; the stored axis has a random length */
static void base_cyl(uint64_t *s, bench_case *k, double ah[3], int allow_inf)
{
    double al = U(s, 0.5, 2.0);
    int i;
    unit_vec(s, ah);
    for (i = 0; i < 3; ++i) {
        k->c[i] = U(s, -10, 10);
        k->a[i] = ah[i] * al;
    }
    k->r = U(s, 0.5, 2.0);
    k->h = allow_inf && IRAND(s, 10) == 0 ? (double)INFINITY : k->r * U(s, 0.5, 8.0);
}

/* a point near the cylinder: hits and misses in similar numbers */
static void near_target(uint64_t *s, const bench_case *k, const double ah[3], double x[3])
{
    double H = isfinite(k->h) ? k->h / 2 : 5 * k->r, e[3], v, rho;
    int i;
    perp_vec(s, ah, e);
    v = U(s, -1.3, 1.3) * H;
    rho = U(s, 0.0, 1.4) * k->r;
    for (i = 0; i < 3; ++i) x[i] = k->c[i] + ah[i] * v + e[i] * rho;
}

/* origin at distance dist from target, aimed at it; |d| random in [0.3, 3] */
static void aim_from(uint64_t *s, bench_case *k, const double target[3], double dist)
{
    double u[3], dl = U(s, 0.3, 3.0);
    int i;
    unit_vec(s, u);
    for (i = 0; i < 3; ++i) {
        k->o[i] = target[i] - u[i] * dist;
        k->d[i] = u[i] * dl;
    }
    k->tmin = 0;
    k->tmax = (double)INFINITY;
}

static void gen_well(uint64_t *s, bench_case *k, int allow_inf)
{
    double ah[3], x[3];
    base_cyl(s, k, ah, allow_inf);
    near_target(s, k, ah, x);
    aim_from(s, k, x, U(s, 2, 10) * k->r);
}

/* nearest open-tube hit t > 0 in plain double (used only to place t ranges) */
static int rough_hit(const bench_case *k, double *t_out)
{
    double al = sqrt(dot3(k->a, k->a)), ah[3], w[3], ad, aw, dp[3], wp[3], A, B, C, D, q, t1, t2;
    int i;
    for (i = 0; i < 3; ++i) { ah[i] = k->a[i] / al; w[i] = k->o[i] - k->c[i]; }
    ad = dot3(ah, k->d); aw = dot3(ah, w);
    for (i = 0; i < 3; ++i) { dp[i] = k->d[i] - ah[i] * ad; wp[i] = w[i] - ah[i] * aw; }
    A = dot3(dp, dp); B = dot3(dp, wp); C = dot3(wp, wp) - k->r * k->r;
    D = B * B - A * C;
    if (!(A > 0) || !(D > 0)) return 0;
    q = -(B + copysign(sqrt(D), B));
    t1 = q / A; t2 = C / q;
    if (t1 > t2) { double x = t1; t1 = t2; t2 = x; }
    for (i = 0; i < 2; ++i) {
        double t = i == 0 ? t1 : t2, v = aw + t * ad;
        if (t > 0 && (!isfinite(k->h) || fabs(v) <= k->h / 2)) { *t_out = t; return 1; }
    }
    return 0;
}

/* x rounded to float, as a double. Through a volatile: GCC 12.2 at -O2 (SLP vectorizer)
   drops the rounding of (double)(float)x on neighbouring struct members (reproduced on
   Debian bookworm's gcc 12.2.0-14), which left float cases holding non-float values. */
static double to_f(double x)
{
    volatile float f = (float)x;
    return (double)f;
}

void bench_case_gen(int family, int prec, uint64_t seed, uint64_t index, bench_case *k)
{
    uint64_t st = seed ^ (UINT64_C(0xA24BAED4963EE407) * (uint64_t)(family + 1)) ^
                  (UINT64_C(0x9FB21C651E98DF25) * (index + 1));
    uint64_t *s = &st;
    double ah[3], x[3], e[3];
    int i;
    (void)bench_rng_next(s);
    k->family = family;

    switch (family) {
    case BF_WELL:
    default:
        gen_well(s, k, 1);
        break;
    case BF_FAR:
        base_cyl(s, k, ah, 0);
        near_target(s, k, ah, x);
        aim_from(s, k, x, LOG10U(s, 2, 7) * k->r);
        break;
    case BF_PARALLEL: {
        double th = LOG10U(s, -12, -1), H, v0, rho0, dl = U(s, 0.3, 3.0), sg;
        base_cyl(s, k, ah, 0);
        if (IRAND(s, 5) == 0) k->h = (double)INFINITY;
        H = isfinite(k->h) ? k->h / 2 : 5 * k->r;
        if (IRAND(s, 2)) for (i = 0; i < 3; ++i) ah[i] = -ah[i];   /* either way along the axis */
        perp_vec(s, ah, e);
        v0 = -U(s, 0.0, 1.2) * H;
        if (IRAND(s, 2)) {          /* starts near the wall and crosses it inside the tube */
            rho0 = k->r - sin(th) * U(s, 0.0, 2.0) * H;
            sg = 1;
        } else {                    /* anywhere around the axis */
            rho0 = U(s, 0.0, 1.5) * k->r;
            sg = IRAND(s, 2) ? 1 : -1;
        }
        for (i = 0; i < 3; ++i) {
            k->o[i] = k->c[i] + ah[i] * v0 + e[i] * rho0;
            k->d[i] = (cos(th) * ah[i] + sg * sin(th) * e[i]) * dl;
        }
        k->tmin = 0;
        k->tmax = (double)INFINITY;
        break;
    }
    case BF_GRAZING: {
        double th = U(s, 0.2, 1.5), H, v0, n[3], dn[3], rho, dl = U(s, 0.3, 3.0), sd;
        int kexp = 1 + IRAND(s, 15);
        base_cyl(s, k, ah, 1);
        H = isfinite(k->h) ? k->h / 2 : 5 * k->r;
        perp_vec(s, ah, e);
        for (i = 0; i < 3; ++i) dn[i] = cos(th) * ah[i] + sin(th) * e[i];
        cross3(ah, dn, n);
        {
            double l = sqrt(dot3(n, n));
            for (i = 0; i < 3; ++i) n[i] /= l;
        }
        v0 = U(s, -0.8, 0.8) * H;
        rho = k->r * (1.0 + (IRAND(s, 2) ? 1.0 : -1.0) * pow(10.0, -kexp));
        sd = U(s, 2, 10) * k->r;
        for (i = 0; i < 3; ++i) {
            x[i] = k->c[i] + ah[i] * v0 + n[i] * rho;   /* closest point of the ray to the axis */
            k->o[i] = x[i] - dn[i] * sd;
            k->d[i] = dn[i] * dl;
        }
        k->tmin = 0;
        k->tmax = (double)INFINITY;
        break;
    }
    case BF_THIN: {
        double ratio = LOG10U(s, -8, -2);
        base_cyl(s, k, ah, 0);
        k->h = k->r / ratio;
        perp_vec(s, ah, e);
        {
            double v = U(s, -0.55, 0.55) * k->h, rho = U(s, 0.0, 1.4) * k->r;
            for (i = 0; i < 3; ++i) x[i] = k->c[i] + ah[i] * v + e[i] * rho;
        }
        aim_from(s, k, x, U(s, 2, 10) * k->r);
        break;
    }
    case BF_SURFACE: {
        double H, dl = U(s, 0.3, 3.0), u[3];
        base_cyl(s, k, ah, 0);
        H = k->h / 2;
        perp_vec(s, ah, e);
        if (IRAND(s, 10) < 7) {     /* a wall point */
            double v = U(s, -1, 1) * H;
            for (i = 0; i < 3; ++i) x[i] = k->c[i] + ah[i] * v + e[i] * k->r;
        } else {                    /* a cap point */
            double sg = IRAND(s, 2) ? 1.0 : -1.0, rho = U(s, 0, 1) * k->r;
            for (i = 0; i < 3; ++i) x[i] = k->c[i] + ah[i] * sg * H + e[i] * rho;
        }
        unit_vec(s, u);
        for (i = 0; i < 3; ++i) {
            k->o[i] = x[i];
            k->d[i] = u[i] * dl;
        }
        k->tmin = 0;
        k->tmax = (double)INFINITY;
        break;
    }
    case BF_HUGE:
    case BF_TINY: {
        int e2 = prec == 24 ? 50 : 400;
        double S = ldexp(1.0, family == BF_HUGE ? e2 : -e2);
        int scale_d = IRAND(s, 2);
        gen_well(s, k, 1);
        for (i = 0; i < 3; ++i) {
            k->o[i] *= S;
            k->c[i] *= S;
            if (scale_d) k->d[i] *= S;
        }
        k->r *= S;
        k->h *= S;
        break;
    }
    case BF_AXIS: {
        static const double lens[4] = {1.0, 2.0, 0.5, 3.0};
        static const double hs[5] = {2.0, 4.0, 1.0, 6.0, (double)INFINITY};
        int ax = IRAND(s, 3);
        for (i = 0; i < 3; ++i) {
            k->a[i] = 0;
            k->c[i] = (double)(IRAND(s, 9) - 4);
        }
        k->a[ax] = lens[IRAND(s, 4)] * (IRAND(s, 2) ? 1.0 : -1.0);
        k->r = lens[IRAND(s, 4)];
        k->h = hs[IRAND(s, 5)];
        for (i = 0; i < 3; ++i) k->o[i] = k->c[i] + 0.5 * (double)(IRAND(s, 33) - 16);
        if (IRAND(s, 3) != 0) {     /* aimed at an exact point: on the axis, wall or beyond */
            static const double offs[4] = {0.0, 0.5, 1.0, 1.5};
            double tg[3];
            int other = (ax + 1 + IRAND(s, 2)) % 3;
            do {
                for (i = 0; i < 3; ++i) tg[i] = k->c[i];
                tg[ax] += 0.5 * (double)(IRAND(s, 13) - 6);
                tg[other] += offs[IRAND(s, 4)] * k->r * (IRAND(s, 2) ? 1.0 : -1.0);
                for (i = 0; i < 3; ++i) k->d[i] = tg[i] - k->o[i];
                if (!(dot3(k->d, k->d) > 0)) k->o[other] += 1.0;
            } while (!(dot3(k->d, k->d) > 0));
        } else if (IRAND(s, 2)) {
            for (i = 0; i < 3; ++i) k->d[i] = 0;
            k->d[IRAND(s, 3)] = lens[IRAND(s, 4)] * (IRAND(s, 2) ? 1.0 : -1.0);
        } else {
            do {
                for (i = 0; i < 3; ++i) k->d[i] = (double)(IRAND(s, 5) - 2);
            } while (!(dot3(k->d, k->d) > 0));
        }
        k->tmin = IRAND(s, 4) == 0 ? 1.0 : 0.0;
        k->tmax = (double)INFINITY;
        break;
    }
    case BF_TRANGE: {
        double t0 = 0;
        int tries = 0;
        do {
            gen_well(s, k, 1);
        } while (!rough_hit(k, &t0) && ++tries < 100);
        {
            int kexp = 1 + IRAND(s, 15);
            double rel = (IRAND(s, 2) ? 1.0 : -1.0) * pow(10.0, -kexp);
            if (IRAND(s, 2)) k->tmax = t0 * (1 + rel);
            else k->tmin = t0 * (1 + rel);
        }
        break;
    }
    case BF_FLAT: {
        /* axis along a coordinate axis, c on it: the origin o = c + v0 a/|a| ± r e_j + δ e_l
           (e_j, e_l the other two axes, δ = ±r 2^-k) is exactly representable, so C =
           δ²|a|² is far below its rounding in the API's type (2^-2k of r²|a|²; k up to 40 for
           float, 60 for double). v0 within 1.2 half heights, or at 1e-8 .. 1e-1 of one from a
           rim. The ray
           runs along ±a with a small radial and tangential part: the crossing near t = 0 is
           decided against the rim from |v0 + t·â·d|, t = C/q */
        static const double lens[4] = {1.0, 2.0, 0.5, 3.0};
        double th = LOG10U(s, prec == 24 ? -7.2 : -15.9, -1), dl = U(s, 0.3, 3.0), v0, ps, sgn;
        int ax = IRAND(s, 3), j = (ax + 1 + IRAND(s, 2)) % 3, l = 3 - ax - j;
        int kexp = 12 + IRAND(s, prec == 24 ? 29 : 49);
        for (i = 0; i < 3; ++i) k->a[i] = k->c[i] = 0;
        sgn = IRAND(s, 2) ? 1.0 : -1.0;
        k->a[ax] = sgn * lens[IRAND(s, 4)];
        k->c[ax] = U(s, -10, 10);
        k->r = U(s, 0.5, 2.0);
        if (prec == 24) k->r = to_f(k->r);
        k->h = k->r / LOG10U(s, 2, 9);
        if (prec == 24) k->h = to_f(k->h);
        v0 = (IRAND(s, 2) ? U(s, -1.2, 1.2)
                          : (IRAND(s, 2) ? 1.0 : -1.0) *
                                (1.0 + (IRAND(s, 2) ? 1.0 : -1.0) * LOG10U(s, -8, -1))) *
             k->h / 2;
        k->o[ax] = k->c[ax] + v0;
        k->o[j] = IRAND(s, 2) ? k->r : -k->r;
        k->o[l] = (IRAND(s, 2) ? 1.0 : -1.0) * ldexp(k->r, -kexp);
        ps = U(s, 0, 6.283185307179586);
        k->d[ax] = (IRAND(s, 2) ? 1.0 : -1.0) * cos(th) * dl;
        k->d[j] = sin(th) * cos(ps) * dl;
        k->d[l] = sin(th) * sin(ps) * dl;
        k->tmin = IRAND(s, 4) == 0 ? -(double)INFINITY : 0.0;
        k->tmax = (double)INFINITY;
        break;
    }
    }

    if (prec == 24) {
        for (i = 0; i < 3; ++i) {
            k->o[i] = to_f(k->o[i]);
            k->d[i] = to_f(k->d[i]);
            k->c[i] = to_f(k->c[i]);
            k->a[i] = to_f(k->a[i]);
        }
        k->r = to_f(k->r);
        k->h = to_f(k->h);
        k->tmin = to_f(k->tmin);
        k->tmax = to_f(k->tmax);
    }
}
