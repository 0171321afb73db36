/* Contract tests, scaling and invariance: what must not change the answer. Power-of-two scalings
 * of the lengths, of d and of a (exact, so compared with ==), translations, and the options that
 * only drop work (CYL_NO_NORMAL, CYL_NO_ERRBOUND, CYL_TRUSTED).
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=invariance CFG=gcc-O0 (tests/README.md).
 */
#include "contract.h"

/* ================================================================== option bits */
static void test_no_normal_no_errbound_trusted(void)
{
    size_t i, k;
    char m[160];
    for (i = 0; i < N_SCENES; i++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            Ray ray;
            Cyl cyl;
            Hit base[2], other[2];
            unsigned opts = opt_sets[k];
            int n, j;
            scene_get(&scenes[i], &ray, &cyl);
            sentinel(base, 2);
            n = rt_intersect_all(&ray, &cyl, opts, base);

            sentinel(other, 2);
            snprintf(m, sizeof m, "%s, opts 0x%x: CYL_NO_NORMAL", scenes[i].name, opts);
            EQ_INT(n, rt_intersect_all(&ray, &cyl, opts | CYL_NO_NORMAL, other), m);
            for (j = 0; j < n; j++) {
                VEC_EXACT(other[j].n, 0, 0, 0, "CYL_NO_NORMAL leaves n = {0,0,0}");
                EXACT(base[j].t, other[j].t, "CYL_NO_NORMAL: same t");
                EQ_INT(base[j].part, other[j].part, "CYL_NO_NORMAL: same part");
                EQ_INT(base[j].flags, other[j].flags, "CYL_NO_NORMAL: same flags");
                NEAR(base[j].v, other[j].v, 0, "CYL_NO_NORMAL: same v");
            }
            sentinel(other, 2);
            snprintf(m, sizeof m, "%s, opts 0x%x: CYL_NO_ERRBOUND", scenes[i].name, opts);
            EQ_INT(n, rt_intersect_all(&ray, &cyl, opts | CYL_NO_ERRBOUND, other), m);
            for (j = 0; j < n; j++) {
                CHECK(isinf(other[j].t_err) && other[j].t_err > 0, "NO_ERRBOUND: t_err = +inf");
                EXACT(base[j].t, other[j].t, "CYL_NO_ERRBOUND: same t");
                EQ_INT(base[j].part, other[j].part, "CYL_NO_ERRBOUND: same part");
                EQ_INT(base[j].flags, other[j].flags, "CYL_NO_ERRBOUND: same flags");
                VEC_EXACT(other[j].n, base[j].n[0], base[j].n[1], base[j].n[2], "same n");
            }
            sentinel(other, 2);
            snprintf(m, sizeof m, "%s, opts 0x%x: CYL_TRUSTED", scenes[i].name, opts);
            EQ_INT(n, rt_intersect_all(&ray, &cyl, opts | CYL_TRUSTED, other), m);
            for (j = 0; j < n; j++) SAME_HIT(&base[j], &other[j], 1, m);
            {
                Hit h1, h2;
                int r1, r2;
                sentinel(&h1, 1);
                sentinel(&h2, 1);
                r1 = rt_intersect(&ray, &cyl, opts, &h1);
                r2 = rt_intersect(&ray, &cyl, opts | CYL_TRUSTED, &h2);
                EQ_INT(r1, r2, m);
                CHECK(memcmp(&h1, &h2, sizeof h1) == 0, "CYL_TRUSTED intersect: same bytes");
                EQ_INT(rt_occluded(&ray, &cyl, opts),
                       rt_occluded(&ray, &cyl, opts | CYL_TRUSTED), m);
            }
        }
    }
}

/* ================================================================== invariances */
static void scale_scene(Ray *ray, Cyl *cyl, int len_exp, int d_exp, int a_exp)
{
    int i;
    for (i = 0; i < 3; i++) {
        ray->o[i] = T_LDEXP(ray->o[i], len_exp);
        cyl->c[i] = T_LDEXP(cyl->c[i], len_exp);
        ray->d[i] = T_LDEXP(ray->d[i], d_exp);
        cyl->a[i] = T_LDEXP(cyl->a[i], a_exp);
    }
    cyl->r = T_LDEXP(cyl->r, len_exp);
    cyl->h = T_LDEXP(cyl->h, len_exp);
}

/* Special scenes for the invariance tests beside the generic ones: tangent-band and parallel. */
static int special_scene(int idx, Ray *ray, Cyl *cyl, const char **name)
{
    T ttol = (T)TOL_TANGENT, ptol = (T)TOL_PARALLEL;
    switch (idx) {
    case 0: *ray = mk_ray(-3, L(1) - ttol / 8, 0, 1, 0, 0); *cyl = z_cyl(2);
        *name = "grazing (e = tol/4)"; return 1;
    case 1: *ray = mk_ray(-3, L(1) - 2 * ttol, 0, 1, 0, 0); *cyl = z_cyl(2);
        *name = "near-grazing (e = 4 tol)"; return 1;
    case 2: *ray = mk_ray(L(0.25), 0, -5, ptol / 4, 0, 1); *cyl = z_cyl(2);
        *name = "parallel (sin = tol/4)"; return 1;
    case 3: *ray = mk_ray(-3, 0, 1, 1, 0, 0); *cyl = z_cyl(2);
        *name = "rim plane"; return 1;
    case 4: *ray = mk_ray(-16, 12, L(0.5), 1, 0, 0); *cyl = mk_cyl(0, 0, 0, 0, 0, 1, 13, 2);
        *name = "5-12-13"; return 1;
    default: return 0;
    }
}

static int get_any_scene(size_t idx, Ray *ray, Cyl *cyl, const char **name)
{
    if (idx < N_SCENES) {
        scene_get(&scenes[idx], ray, cyl);
        *name = scenes[idx].name;
        return 1;
    }
    return special_scene((int)(idx - N_SCENES), ray, cyl, name);
}

/* The scaled hit against the base one scaled: exactly where the answers are correctly rounded
 * (v1); in v2's default tier the exact path, which answers the scaled scene out of the hot
 * path's range, takes a compensated step the hot path does not (its N8), so there the two
 * [t - t_err, t + t_err] must meet (each holds the exact t, which scales exactly), v agree
 * within what t's and its own rounding allow, n within TOL_NORMAL. */
#define SCALE_EXACT (CYL_VERSION_MAJOR < 2)
static void chk_scaled_at(const Hit *base, const Hit *h, const Ray *ray, const Cyl *cyl, int le,
                          int de, const char *m, int line)
{
    long double tb = (long double)T_LDEXP(base->t, le - de), eb, d2 = 0, w2 = 0, size;
    int i;
    if (SCALE_EXACT) {
        chk_exact_at(T_LDEXP(base->t, le - de), h->t, m, line);
        chk_exact_at(T_LDEXP(base->t_err, le - de), h->t_err, m, line);
        chk_exact_at(T_LDEXP(base->v, le), h->v, m, line);
        chk_vec_exact_at(h->n, base->n[0], base->n[1], base->n[2], m, line);
        return;
    }
    eb = (long double)T_LDEXP(base->t_err, le - de) + (long double)h->t_err;
    for (i = 0; i < 3; i++) {
        long double w = (long double)ray->o[i] - (long double)cyl->c[i];
        long double d = (long double)ray->d[i];
        d2 += d * d, w2 += w * w;
    }
    size = fmaxl(fmaxl(sqrtl(w2), fabsl((long double)h->t) * sqrtl(d2)),
                 fmaxl((long double)cyl->r, (long double)cyl->h / 2));
    UNITY_TEST_ASSERT(fabsl((long double)h->t - tb) <= eb, line, m);
    chk_near_at((long double)T_LDEXP(base->v, le), (long double)h->v,
                sqrtl(d2) * eb + TOL_V * size, m, line);
    chk_vec_near_at(h->n, (long double)base->n[0], (long double)base->n[1],
                    (long double)base->n[2], TOL_NORMAL, m, line);
}

/* Lengths scaled by 2^k (o, c, r, h; d and a fixed): t, v and t_err scale by 2^k, the normal,
 * part and flags are identical. d scaled by 2^k: t and t_err scale by 2^-k. a scaled: nothing
 * changes. Powers of two are exact: the answers are exactly scaled where correctly rounded, and
 * agree within their bounds otherwise (chk_scaled_at). */
static void test_scale_invariance(void)
{
    static const int exps[] = {T_BIG_EXP, -T_BIG_EXP};
    static const int dexps[] = {T_DIR_EXP, -T_DIR_EXP};
    size_t idx, k, e;
    const char *name;
    char m[200];
    Ray ray0;
    Cyl cyl0;
    for (idx = 0; get_any_scene(idx, &ray0, &cyl0, &name); idx++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            unsigned opts = opt_sets[k];
            Hit base[2];
            int n;
            sentinel(base, 2);
            n = rt_intersect_all(&ray0, &cyl0, opts, base);
            for (e = 0; e < 2; e++) {
                int variant;
                for (variant = 0; variant < 3; variant++) {
                    Ray ray = ray0;
                    Cyl cyl = cyl0;
                    Hit hs[2];
                    int j, le = 0, de = 0, ae = 0;
                    if (variant == 0) le = exps[e];
                    if (variant == 1) de = dexps[e];
                    if (variant == 2) ae = dexps[e];
                    scale_scene(&ray, &cyl, le, de, ae);
                    snprintf(m, sizeof m, "%s, opts 0x%x, lengths*2^%d d*2^%d a*2^%d", name,
                             opts, le, de, ae);
                    sentinel(hs, 2);
                    EQ_INT(n, rt_intersect_all(&ray, &cyl, opts, hs), m);
                    for (j = 0; j < n; j++) {
                        chk_scaled_at(&base[j], &hs[j], &ray, &cyl, le, de, m, __LINE__);
                        EQ_INT(base[j].part, hs[j].part, m);
                        EQ_INT(base[j].flags, hs[j].flags, m);
                    }
                }
            }
        }
    }
}

/* Lengths and d scaled together by 2^k leave t unchanged. k around the edge of v2's hot range
 * (N2: |a|²|o − c|², |a|²|d|² and r²A summed at most 2^450 in double, 2^60 in float computed
 * in float) and beyond it, where the products the bounds form (|a|²D up to their squares)
 * would overflow on a hot path that took them: the answers agree with k = 0 within their
 * bounds, part and flags the same. */
static void test_scale_across_hot_range_edge(void)
{
    static const int edge[] = {T_EDGE_EXPS};
    size_t idx, k, e;
    const char *name;
    char m[200];
    Ray ray0;
    Cyl cyl0;
    for (idx = 0; get_any_scene(idx, &ray0, &cyl0, &name); idx++)
        for (k = 0; k < N_OPT_SETS; k++) {
            Hit base[2];
            int n;
            sentinel(base, 2);
            n = rt_intersect_all(&ray0, &cyl0, opt_sets[k], base);
            for (e = 0; e < sizeof edge / sizeof edge[0]; e++) {
                Ray ray = ray0;
                Cyl cyl = cyl0;
                Hit hs[2];
                int j;
                scale_scene(&ray, &cyl, edge[e], edge[e], 0);
                snprintf(m, sizeof m, "%s, opts 0x%x, lengths and d*2^%d", name, opt_sets[k], edge[e]);
                sentinel(hs, 2);
                EQ_INT(n, rt_intersect_all(&ray, &cyl, opt_sets[k], hs), m);
                for (j = 0; j < n; j++) {
                    chk_scaled_at(&base[j], &hs[j], &ray, &cyl, edge[e], edge[e], m, __LINE__);
                    EQ_INT(base[j].part, hs[j].part, m);
                    EQ_INT(base[j].flags, hs[j].flags, m);
                }
            }
        }
}

/* Translating o and c together (exactly: dyadic coordinates) moves nothing but the frame. */
static void test_translation_invariance(void)
{
    static const double offs[][3] = {{64, -128, 32}, {-1024, 512, 2048}, {0.5, 0.25, -0.75}};
    size_t idx, k, o;
    const char *name;
    char m[200];
    Ray ray0;
    Cyl cyl0;
    for (idx = 0; idx < N_SCENES && get_any_scene(idx, &ray0, &cyl0, &name); idx++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            unsigned opts = opt_sets[k];
            Hit base[2];
            int n;
            RefGeom g;
            ref_geom(&ray0, &cyl0, &g);
            sentinel(base, 2);
            n = rt_intersect_all(&ray0, &cyl0, opts, base);
            for (o = 0; o < sizeof offs / sizeof offs[0]; o++) {
                Ray ray = ray0;
                Cyl cyl = cyl0;
                Hit hs[2];
                int j, i;
                for (i = 0; i < 3; i++) {
                    ray.o[i] += (T)offs[o][i];
                    cyl.c[i] += (T)offs[o][i];
                }
                snprintf(m, sizeof m, "%s, opts 0x%x, offset %d", name, opts, (int)o);
                sentinel(hs, 2);
                EQ_INT(n, rt_intersect_all(&ray, &cyl, opts, hs), m);
                for (j = 0; j < n; j++) {
                    long double sc = fabsl((long double)base[j].t) > g.tscale
                                         ? fabsl((long double)base[j].t) : g.tscale;
                    NEAR(base[j].t, hs[j].t, TOL_T_ULP4 * sc, m);
                    NEAR(base[j].v, hs[j].v, TOL_V * (sqrtl(dotl3(g.w, g.w)) + g.r), m);
                    VEC_NEAR(hs[j].n, base[j].n[0], base[j].n[1], base[j].n[2], TOL_NORMAL, m);
                    EQ_INT(base[j].part, hs[j].part, m);
                    EQ_INT(base[j].flags, hs[j].flags, m);
                }
            }
        }
    }
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_invariance(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_no_normal_no_errbound_trusted);
    RUN_TEST(test_scale_invariance);
    RUN_TEST(test_scale_across_hot_range_edge);
    RUN_TEST(test_translation_invariance);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_invariance();
    return UNITY_END();
}
#endif
