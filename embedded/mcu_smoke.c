/* Runs the float configurations exactly as they were compiled for a microcontroller (the
 * objects of `make sizes` for Cortex-M4F, Cortex-M0 and RV32IMAFC) on an emulated core, and
 * checks their answers on a few scenes whose results are known in closed form.
 *
 * Freestanding: no libc, no printf. Output and exit go through the Linux system-call ABI so
 * that qemu user mode can run the program: qemu-riscv32 for RV32IMAFC, qemu-arm -cpu max for
 * the Arm objects (qemu 7.2's user mode has no M-profile CPU; -cpu max executes the same
 * Thumb-2 and VFPv4 single-precision instructions). On a board, replace sys_write and
 * sys_exit. The output ends with Unity's "N Tests M Failures 0 Ignored" line so that
 * scripts/run-tests.sh can count it with the rest.
 * Built by scripts/cross.sh embedded; see docs/embedded.md. */
#include "cylinder_isect.h"

/* The wrappers of embedded/configs.c, one per configuration (float). */
#define CFG_DECL(name) int cfgf_##name(const cylf_ray *ray, const cylf_cylinder *cyl, cylf_hit hits[2]);
CFG_DECL(open)
CFG_DECL(capped)
CFG_DECL(all)
CFG_DECL(occluded)
CFG_DECL(occl_caps)
CFG_DECL(no_terr)
CFG_DECL(no_normal)
CFG_DECL(trusted)
CFG_DECL(minimal)
CFG_DECL(precise)
CFG_DECL(runtime)
CFG_DECL(rt_noprec)
CFG_DECL(every_f)

unsigned cfg_runtime_opts = 0u;
int cfg_runtime_entry = 0;

/* ---- the Linux system-call ABI, as qemu user mode provides it ---- */
#if defined(__riscv)
static long sys_call3(long n, long a, long b, long c)
{
    register long a7 __asm__("a7") = n;
    register long a0 __asm__("a0") = a;
    register long a1 __asm__("a1") = b;
    register long a2 __asm__("a2") = c;
    __asm__ volatile("ecall" : "+r"(a0) : "r"(a7), "r"(a1), "r"(a2) : "memory");
    return a0;
}
#define SYS_WRITE 64
#define SYS_EXIT 93
/* The global pointer must be set before any C code addresses small data. */
__asm__(".text\n.global _start\n_start:\n.option push\n.option norelax\n"
        "la gp, __global_pointer$\n.option pop\ncall smoke_main\n1: j 1b\n");
#elif defined(__arm__)
static long sys_call3(long n, long a, long b, long c)
{
    register long r7 __asm__("r7") = n;
    register long r0 __asm__("r0") = a;
    register long r1 __asm__("r1") = b;
    register long r2 __asm__("r2") = c;
    __asm__ volatile("svc 0" : "+r"(r0) : "r"(r7), "r"(r1), "r"(r2) : "memory");
    return r0;
}
#define SYS_WRITE 4
#define SYS_EXIT 1
void _start(void);
void smoke_main(void);
void _start(void) { smoke_main(); }
#else
#error "mcu_smoke.c: RISC-V or Arm only"
#endif

static void put(const char *s)
{
    long n = 0;
    while (s[n] != '\0') n++;
    (void)sys_call3(SYS_WRITE, 1, (long)s, n);
}

static void put_int(long v)
{
    char buf[24];
    int i = 22;
    int neg = v < 0;
    unsigned long u = neg ? 0ul - (unsigned long)v : (unsigned long)v;
    buf[23] = '\0';
    do {
        buf[i--] = (char)('0' + (int)(u % 10ul));
        u /= 10ul;
    } while (u != 0ul && i > 0);
    if (neg) buf[i--] = '-';
    put(&buf[i + 1]);
}

/* ---- checks ---- */
static long n_checks, n_fail;

static void check(int ok, const char *what, int line)
{
    n_checks++;
    if (!ok) {
        n_fail++;
        put("mcu_smoke.c:");
        put_int(line);
        put(":FAIL: ");
        put(what);
        put("\n");
    }
}
#define CHECK(cond) check((cond) ? 1 : 0, #cond, __LINE__)

/* The scenes are exact in binary: t, n and v are the closest floats to the true values, and the
 * library's float path is accurate to a few ulps there, so 2^-18 relative is a loose bound that
 * still catches a wrong root, a wrong sign or an unscaled direction. */
#define T_TOL (1.0f / 262144.0f)
static int near(float x, float want) { return x - want <= T_TOL * (1.0f + (want < 0 ? -want : want)) && want - x <= T_TOL * (1.0f + (want < 0 ? -want : want)); }
/* The bound must hold and must not be useless: the scenes are well conditioned, so t_err is a
 * few ulps of t; 2^-12 of t would mean the bound lost its meaning. */
#define T_ERR_MAX (1.0f / 4096.0f)
static int err_ok(const cylf_hit *h, float want)
{
    float d = h->t > want ? h->t - want : want - h->t;
    return h->t_err >= 0.0f && h->t_err <= T_ERR_MAX * (h->t > 0 ? h->t : -h->t) + T_TOL && d <= h->t_err + T_TOL * want;
}

typedef int (*cfg_fn)(const cylf_ray *, const cylf_cylinder *, cylf_hit[2]);

static void set_ray(cylf_ray *r, float ox, float oy, float oz, float dx, float dy, float dz)
{
    r->o[0] = ox; r->o[1] = oy; r->o[2] = oz;
    r->d[0] = dx; r->d[1] = dy; r->d[2] = dz;
    r->tmin = 0.0f;
    r->tmax = 100.0f;
}

static void set_cyl(cylf_cylinder *c, float ax, float ay, float az, float r, float h)
{
    c->c[0] = 0.0f; c->c[1] = 0.0f; c->c[2] = 0.0f;
    c->a[0] = ax; c->a[1] = ay; c->a[2] = az;
    c->r = r;
    c->h = h;
}

static void clear(cylf_hit h[2])
{
    int i, k;
    for (i = 0; i < 2; i++) {
        h[i].t = -1.0f; h[i].t_err = -1.0f; h[i].v = -1.0f; h[i].part = -1; h[i].flags = 0xffu;
        for (k = 0; k < 3; k++) h[i].n[k] = -1.0f;
    }
}

void smoke_main(void)
{
    /* Every configuration whose entry is cylf_intersect with the open tube (but the precise
     * tier where the header compiles it out of a float-only build: v2's CYL_NO_DOUBLE defines
     * CYL_NO_PRECISE, and the bit is then refused with CYL_E_OPTION). */
    static const cfg_fn nearest[] = { cfgf_open, cfgf_no_terr, cfgf_no_normal, cfgf_trusted,
                                      cfgf_minimal,
#ifndef CYL_NO_PRECISE
                                      cfgf_precise,
#endif
                                      cfgf_runtime, cfgf_rt_noprec, cfgf_every_f, cfgf_capped };
    unsigned i;
    cylf_ray ray;
    cylf_cylinder cyl;
    cylf_hit h[2];

    /* Scene 1: unit tube along z, h = 2, ray along +x from x = -5 through the axis:
     * wall at t = 4 (entry) and t = 6 (exit), v = 0, ray-facing normal (-1, 0, 0). */
    set_cyl(&cyl, 0.0f, 0.0f, 1.0f, 1.0f, 2.0f);
    set_ray(&ray, -5.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f);
    for (i = 0; i < sizeof nearest / sizeof nearest[0]; i++) {
        clear(h);
        CHECK(nearest[i](&ray, &cyl, h) == CYL_HIT);
        CHECK(near(h[0].t, 4.0f));
        CHECK(h[0].part == CYL_SIDE);
        CHECK((h[0].flags & (CYL_F_INSIDE | CYL_F_PARALLEL)) == 0u);
        CHECK(near(h[0].v, 0.0f));
    }
    clear(h);
    CHECK(cfgf_open(&ray, &cyl, h) == CYL_HIT);
    CHECK(near(h[0].n[0], -1.0f) && near(h[0].n[1], 0.0f) && near(h[0].n[2], 0.0f));
    CHECK(err_ok(&h[0], 4.0f));
    clear(h);
#ifdef CYL_NO_PRECISE
    CHECK(cfgf_precise(&ray, &cyl, h) == CYL_E_OPTION && h[0].part == -1);
#else
    CHECK(cfgf_precise(&ray, &cyl, h) == CYL_HIT && err_ok(&h[0], 4.0f));
#endif
    /* The options leave out exactly what they say: t_err = +inf, n = 0 (== is the point). */
    clear(h);
    CHECK(cfgf_no_terr(&ray, &cyl, h) == CYL_HIT);
    CHECK(h[0].t_err > 3.0e38f);
    CHECK(near(h[0].n[0], -1.0f));
    clear(h);
    CHECK(cfgf_no_normal(&ray, &cyl, h) == CYL_HIT);
    CHECK(!(h[0].n[0] < 0.0f || h[0].n[0] > 0.0f || h[0].n[1] < 0.0f || h[0].n[1] > 0.0f || h[0].n[2] < 0.0f || h[0].n[2] > 0.0f));
    CHECK(err_ok(&h[0], 4.0f));
    clear(h);
    CHECK(cfgf_all(&ray, &cyl, h) == 2);
    CHECK(near(h[0].t, 4.0f) && near(h[1].t, 6.0f));
    CHECK((h[0].flags & CYL_F_INSIDE) == 0u && (h[1].flags & CYL_F_INSIDE) != 0u);
    CHECK(near(h[1].n[0], -1.0f));  /* ray-facing at the exit too */
    CHECK(cfgf_occluded(&ray, &cyl, h) == 1);
    CHECK(cfgf_occl_caps(&ray, &cyl, h) == 1);

    /* Scene 2: the same tube, ray up the axis from z = -5: no wall hit (parallel); the capped
     * solid is entered through the low cap at t = 4 with normal (0, 0, -1), v = -1. */
    set_ray(&ray, 0.0f, 0.0f, -5.0f, 0.0f, 0.0f, 1.0f);
    clear(h);
    CHECK(cfgf_open(&ray, &cyl, h) == CYL_MISS);
    CHECK(h[0].part == -1); /* untouched on a miss */
    CHECK(cfgf_occluded(&ray, &cyl, h) == 0);
    clear(h);
    CHECK(cfgf_capped(&ray, &cyl, h) == CYL_HIT);
    CHECK(near(h[0].t, 4.0f) && h[0].part == CYL_CAP_LOW && near(h[0].v, -1.0f));
    CHECK(near(h[0].n[2], -1.0f) && near(h[0].n[0], 0.0f) && near(h[0].n[1], 0.0f));
    CHECK((h[0].flags & CYL_F_PARALLEL) != 0u);
    CHECK(err_ok(&h[0], 4.0f));
    CHECK(cfgf_occl_caps(&ray, &cyl, h) == 1);

    /* Scene 3: a ray passing at distance 2 from the axis misses everything. */
    set_ray(&ray, -5.0f, 2.0f, 0.0f, 1.0f, 0.0f, 0.0f);
    for (i = 0; i < sizeof nearest / sizeof nearest[0]; i++) CHECK(nearest[i](&ray, &cyl, h) == CYL_MISS);
    CHECK(cfgf_all(&ray, &cyl, h) == 0);
    CHECK(cfgf_occluded(&ray, &cyl, h) == 0 && cfgf_occl_caps(&ray, &cyl, h) == 0);

    /* Scene 4: only directions count: axis (0, 0, 3), direction (0, 2, 0) from y = -5, radius
     * 0.5: wall at y = -0.5, t = 4.5 / 2 = 2.25. */
    set_cyl(&cyl, 0.0f, 0.0f, 3.0f, 0.5f, 2.0f);
    set_ray(&ray, 0.0f, -5.0f, 0.5f, 0.0f, 2.0f, 0.0f);
    for (i = 0; i < sizeof nearest / sizeof nearest[0]; i++) {
        clear(h);
        CHECK(nearest[i](&ray, &cyl, h) == CYL_HIT && near(h[0].t, 2.25f) && near(h[0].v, 0.5f));
    }

    /* Scene 5: a tilted axis (1, 1, 0): the ray from (3, -3, 0) along (-1, 1, 0) meets the axis
     * line at t = 3 and the wall of radius sqrt(2) at t = 2 and 4. */
    set_cyl(&cyl, 1.0f, 1.0f, 0.0f, 1.41421356f, 4.0f);
    set_ray(&ray, 3.0f, -3.0f, 0.0f, -1.0f, 1.0f, 0.0f);
    clear(h);
    CHECK(cfgf_all(&ray, &cyl, h) == 2 && near(h[0].t, 2.0f) && near(h[1].t, 4.0f));

    /* Scene 6: validation in the configurations that keep it. */
    set_cyl(&cyl, 0.0f, 0.0f, 1.0f, -1.0f, 2.0f);
    set_ray(&ray, -5.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f);
    CHECK(cfgf_open(&ray, &cyl, h) == CYL_E_RADIUS);
    CHECK(cfgf_occluded(&ray, &cyl, h) == CYL_E_RADIUS);
    set_cyl(&cyl, 0.0f, 0.0f, 0.0f, 1.0f, 2.0f);
    CHECK(cfgf_open(&ray, &cyl, h) == CYL_E_ZERO_AXIS);
    set_cyl(&cyl, 0.0f, 0.0f, 1.0f, 1.0f, 2.0f);
    ray.tmin = 5.0f; ray.tmax = 1.0f;
    CHECK(cfgf_capped(&ray, &cyl, h) == CYL_E_TRANGE);

    /* Scene 7: options at run time; the precise tier compiled out answers CYL_E_OPTION. */
    set_ray(&ray, -5.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f);
    cfg_runtime_opts = CYL_PRECISE;
    clear(h);
#ifdef CYL_NO_PRECISE
    CHECK(cfgf_runtime(&ray, &cyl, h) == CYL_E_OPTION && h[0].part == -1);
#else
    CHECK(cfgf_runtime(&ray, &cyl, h) == CYL_HIT && near(h[0].t, 4.0f));
#endif
    CHECK(cfgf_rt_noprec(&ray, &cyl, h) == CYL_E_OPTION);
    cfg_runtime_opts = CYL_CAPS;
    cfg_runtime_entry = 1; /* intersect_all */
    clear(h);
    CHECK(cfgf_every_f(&ray, &cyl, h) == 2 && near(h[1].t, 6.0f));
    cfg_runtime_entry = 2; /* occluded */
    CHECK(cfgf_every_f(&ray, &cyl, h) == 1);

    put_int(n_checks);
    put(" Tests ");
    put_int(n_fail);
    put(" Failures 0 Ignored\n");
    put(n_fail == 0 ? "OK\n" : "FAIL\n");
    (void)sys_call3(SYS_EXIT, n_fail == 0 ? 0 : 1, 0, 0);
    for (;;) {
    }
}
