/* viewer.c: a CPU ray tracer of cylinders that shows what cylinder_isect does.
 *
 *   viewer [options] [scene.txt]          (default scene: examples/scenes/molecule.txt)
 *
 * Every pixel is traced on the CPU with the library, on all cores (pthreads), and shown in a
 * GLFW window as a texture. Rays test only the cylinders that their cell of a frustum grid
 * lists (see "culling" below) and that pass a bounding-tube pretest. Scenes are text files,
 * one cylinder per line (see examples/scenes/make_scenes.py or docs/examples.md).
 *
 * Mouse: drag to orbit, scroll to zoom.
 * Keys:  F float/double   C caps (scene, all open, all capped)   P CYL_PRECISE
 *        S shadows (cylf_occluded)   N normals view   E error view   V split view
 *        R reset camera   Q/Esc quit
 * Error view: each pixel is coloured by |t_float - t_double| / t_err of the float path, where
 * the double path intersects the same float inputs widened exactly to double: dark blue is far
 * inside the bound, yellow is at the bound, red is outside it (a broken bound), magenta is a
 * float hit the double path does not confirm.
 * Split view: left half the library, right half the exercise's literal formulation
 * (bench/alt_formulations.h), on the same pixels and in the same precision.
 *
 * Options:
 *   --headless          render once without a window or OpenGL, write --out (PNG)
 *   --out FILE          PNG to write (headless), default viewer.png
 *   --size WxH          image size, default 640x480
 *   --bench [N]         render N frames (default 60) headless, print frames and rays per second
 *   --double  --caps scene|open|capped  --precise  --no-shadows  --split
 *   --view shade|normals|error
 *   --threads N         default: all online cores
 *   --no-cull           test every cylinder for every ray (the culled image must be the same)
 *   --frames N          windowed: render N frames (continuously), print the rate, quit
 *   --readback FILE     windowed: read the last frame back with glReadPixels into FILE (PNG)
 * Exit codes: 0 ok, 1 usage or scene error, 2 no window could be opened.
 */
#define _POSIX_C_SOURCE 200809L
#include "cylinder_isect.h"
#include "bench/alt_formulations.h"
#include "png_io.h"

#include <GLFW/glfw3.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_THREADS 64
#define PI 3.14159265358979323846
/* Shadow rays start off the surface along the ray-facing normal by this fraction of the
   cylinder's radius, plus this many float roundings of the point's largest coordinate: the
   computed hit point is only that close to the surface. */
#define SHADOW_OFFSET_R 1e-3
#define SHADOW_OFFSET_ULPS (8.0 * 0x1p-24)
/* Error view: ratios below 2^-ERR_LOG2_RANGE of t_err get the darkest colour. */
#define ERR_LOG2_RANGE 24.0

/* ------------------------------------------------------------------ scene */
/* The per-ray pretest (tube_may_hit) widens each radius by this fraction: far more than the
   library's tangent tolerance (hits up to a relative 2^-17 outside r). */
#define TUBE_PAD_REL 0x1p-10

typedef struct object {
    cylf_cylinder cf; /* the float path traces this one */
    cyld_cylinder cd; /* the double path traces this one (parsed in double) */
    int capped;
    double rgb[3];
    double tube_c[2][3], tube_a[2][3], tube_r2[2]; /* float [0] and double [1] copies for
                                                      tube_may_hit: center, unit axis, r² */
} object;

typedef struct camera { double target[3], yaw, pitch, dist, fov; } camera;

typedef struct grid {
    int gx, gy, cap_cells, cap_items;
    int *first;   /* cell k lists item[first[k]] .. item[first[k + 1] - 1] */
    int *item;
    double *dmin; /* per item: no point of the widened cylinder is nearer the apex */
} grid;

typedef struct scene {
    object *obj;
    int n, *all;   /* all[i] = i: the list of an unculled ray */
    double *zero;  /* n zeros: its distance bounds */
    double light[3];
    camera cam;
    grid cam_grid, light_grid[6]; /* culling (see grid_build) */
    int *light_order;             /* the cylinders nearest the light first ... */
    double *light_dmin;           /* ... and their distance bounds from it */
    double light_shift;
} scene;

static int light_build(scene *s);

static void grid_free(grid *g)
{
    free(g->first);
    free(g->item);
    free(g->dmin);
    memset(g, 0, sizeof *g);
}

/* One line of a scene file (format: examples/scenes/make_scenes.py). Returns 0, or -1 after a message. */
static int parse_line(scene *s, const char *line, int lineno, const char *path)
{
    char kind[16], cap[16];
    double v[8] = {0, 0, 0, 0, 0, 0, 0, 0}, rgb[3];
    object o;
    int i, j, ok = 0;
    memset(&o, 0, sizeof o);
    if (sscanf(line, "%15s", kind) != 1 || kind[0] == '#') return 0;
    if (!strcmp(kind, "camera")) {
        camera *c = &s->cam;
        if (sscanf(line, "%*s %lf %lf %lf %lf %lf %lf %lf", &c->target[0], &c->target[1],
                   &c->target[2], &c->yaw, &c->pitch, &c->dist, &c->fov) == 7) return 0;
    } else if (!strcmp(kind, "light")) {
        if (sscanf(line, "%*s %lf %lf %lf", &s->light[0], &s->light[1], &s->light[2]) == 3)
            return 0;
    } else if (!strcmp(kind, "cyl")) { /* center, axis, radius, height: the library's terms */
        ok = sscanf(line, "%*s %lf %lf %lf %lf %lf %lf %lf %lf %15s %lf %lf %lf", &v[0], &v[1],
                    &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], cap, &rgb[0], &rgb[1],
                    &rgb[2]) == 12;
        for (i = 0; i < 3; i++) {
            o.cd.c[i] = v[i], o.cd.a[i] = v[3 + i];
            o.cf.c[i] = (float)v[i], o.cf.a[i] = (float)v[3 + i];
        }
        o.cd.r = v[6], o.cd.h = v[7];
        o.cf.r = (float)v[6], o.cf.h = (float)v[7];
    } else if (!strcmp(kind, "seg")) { /* two end points and a radius, via from_segment */
        float p0[3], p1[3];
        ok = sscanf(line, "%*s %lf %lf %lf %lf %lf %lf %lf %15s %lf %lf %lf", &v[0], &v[1],
                    &v[2], &v[3], &v[4], &v[5], &v[6], cap, &rgb[0], &rgb[1], &rgb[2]) == 11;
        for (i = 0; i < 3; i++) p0[i] = (float)v[i], p1[i] = (float)v[3 + i];
        o.cf = cylf_from_segment(p0, p1, (float)v[6]);
        o.cd = cyld_from_segment(v, v + 3, v[6]);
    }
    if (!ok || (strcmp(cap, "capped") && strcmp(cap, "open"))) {
        fprintf(stderr, "%s:%d: cannot read: %s", path, lineno, line);
        return -1;
    }
    o.capped = cap[0] == 'c';
    for (i = 0; i < 3; i++) o.rgb[i] = rgb[i];
    { /* the library validates the cylinder, tried with a harmless ray */
        cylf_ray rf = {{0, 0, 0}, {1, 0, 0}, 0, 1};
        cyld_ray rd = {{0, 0, 0}, {1, 0, 0}, 0, 1};
        int rc = cylf_occluded(&rf, &o.cf, 0);
        if (rc >= 0) rc = cyld_occluded(&rd, &o.cd, 0);
        if (rc < 0) {
            fprintf(stderr, "%s:%d: %s\n", path, lineno, cyl_strerror(rc));
            return -1;
        }
    }
    for (i = 0; i < 2; i++) { /* the pretest's copies of the float and double cylinders */
        double a[3] = {i ? o.cd.a[0] : (double)o.cf.a[0], i ? o.cd.a[1] : (double)o.cf.a[1],
                       i ? o.cd.a[2] : (double)o.cf.a[2]};
        double len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        double r = (i ? o.cd.r : (double)o.cf.r) * (1 + TUBE_PAD_REL);
        for (j = 0; j < 3; j++) {
            o.tube_a[i][j] = a[j] / len;
            o.tube_c[i][j] = i ? o.cd.c[j] : (double)o.cf.c[j];
        }
        o.tube_r2[i] = r * r;
    }
    s->obj = (object *)realloc(s->obj, (size_t)(s->n + 1) * sizeof *s->obj);
    if (!s->obj) return -1;
    s->obj[s->n++] = o;
    return 0;
}

static int scene_load(scene *s, const char *path)
{
    char line[512];
    int lineno = 0, i;
    FILE *f = fopen(path, "r");
    memset(s, 0, sizeof *s);
    s->cam.dist = 10;
    s->cam.fov = 45;
    s->light[2] = 100;
    if (!f) {
        perror(path);
        return -1;
    }
    while (fgets(line, sizeof line, f))
        if (parse_line(s, line, ++lineno, path)) {
            fclose(f);
            return -1;
        }
    fclose(f);
    if (!s->n) {
        fprintf(stderr, "%s: no cylinders\n", path);
        return -1;
    }
    s->all = (int *)malloc(sizeof *s->all * (size_t)s->n);
    s->light_order = (int *)malloc(sizeof *s->light_order * (size_t)s->n);
    s->zero = (double *)calloc((size_t)s->n, sizeof *s->zero);
    s->light_dmin = (double *)malloc(sizeof *s->light_dmin * (size_t)s->n);
    if (!s->all || !s->light_order || !s->zero || !s->light_dmin) return -1;
    for (i = 0; i < s->n; i++) s->all[i] = i;
    return light_build(s);
}

static void scene_free(scene *s)
{
    int f;
    grid_free(&s->cam_grid);
    for (f = 0; f < 6; f++) grid_free(&s->light_grid[f]);
    free(s->obj);
    free(s->all);
    free(s->zero);
    free(s->light_order);
    free(s->light_dmin);
}

/* ------------------------------------------------------------------ tracing */
enum { VIEW_SHADE, VIEW_NORMALS, VIEW_ERROR };
enum { CAPS_SCENE, CAPS_NONE, CAPS_ALL };
static const char *const caps_name[] = {"scene", "open", "capped"};
static const char *const view_name[] = {"shade", "normals", "error"};

typedef struct settings { int use_double, caps, precise, shadows, view, split, nocull; } settings;

typedef struct hitinfo { double t, t_err, n[3]; int obj, part; unsigned flags; } hitinfo;

typedef struct stats {
    long rays, calls, errors, hits, over_bound, unconfirmed;
    double max_ratio; /* error view: largest |t_f - t_d| / t_err over the pixels */
} stats;

static unsigned object_opts(const scene *s, int i, const settings *st)
{
    int capped = st->caps == CAPS_ALL || (st->caps == CAPS_SCENE && s->obj[i].capped);
    /* CYL_TRUSTED: the scene was validated when loaded and no ray direction is zero */
    return (capped ? (unsigned)CYL_CAPS : 0u) | (st->precise ? (unsigned)CYL_PRECISE : 0u) |
           (unsigned)CYL_TRUSTED;
}

/* One cylinder, in the precision of the settings, with the library or the literal formulation
   (alt). The ray is held in double; in float mode its values are already floats. */
static int hit_one(const scene *s, int i, int dbl, int alt, unsigned opts, const double o[3],
                   const double d[3], double tmax, hitinfo *h)
{
    int rc, k;
    if (dbl) {
        cyld_ray r;
        cyld_hit x;
        for (k = 0; k < 3; k++) r.o[k] = o[k], r.d[k] = d[k];
        r.tmin = 0;
        r.tmax = tmax;
        rc = alt ? altd_literal_intersect(&r, &s->obj[i].cd, opts, &x)
                 : cyld_intersect(&r, &s->obj[i].cd, opts, &x);
        if (rc != CYL_HIT) return rc;
        h->t = x.t, h->t_err = x.t_err, h->flags = x.flags, h->part = x.part;
        for (k = 0; k < 3; k++) h->n[k] = x.n[k];
    } else {
        cylf_ray r;
        cylf_hit x;
        for (k = 0; k < 3; k++) r.o[k] = (float)o[k], r.d[k] = (float)d[k];
        r.tmin = 0;
        r.tmax = (float)tmax;
        rc = alt ? altf_literal_intersect(&r, &s->obj[i].cf, opts, &x)
                 : cylf_intersect(&r, &s->obj[i].cf, opts, &x);
        if (rc != CYL_HIT) return rc;
        h->t = (double)x.t, h->t_err = (double)x.t_err, h->flags = x.flags, h->part = x.part;
        for (k = 0; k < 3; k++) h->n[k] = (double)x.n[k];
    }
    h->obj = i;
    return CYL_HIT;
}

static int occluded_one(const scene *s, int i, int dbl, unsigned opts, const double o[3],
                        const double d[3], double tmax)
{
    int k;
    if (dbl) {
        cyld_ray r;
        for (k = 0; k < 3; k++) r.o[k] = o[k], r.d[k] = d[k];
        r.tmin = 0;
        r.tmax = tmax;
        return cyld_occluded(&r, &s->obj[i].cd, opts);
    } else {
        cylf_ray r;
        for (k = 0; k < 3; k++) r.o[k] = (float)o[k], r.d[k] = (float)d[k];
        r.tmin = 0;
        r.tmax = (float)tmax;
        return cylf_occluded(&r, &s->obj[i].cf, opts);
    }
}

typedef struct view {
    double eye[3], fwd[3], right[3], up[3]; /* right and up scaled to the image plane at 1 */
} view;

static void make_view(const camera *c, double aspect, view *v)
{
    double y = c->yaw * PI / 180, p = c->pitch * PI / 180, tf = tan(c->fov * PI / 360), l;
    int k;
    v->fwd[0] = -cos(p) * cos(y), v->fwd[1] = -cos(p) * sin(y), v->fwd[2] = -sin(p);
    for (k = 0; k < 3; k++) v->eye[k] = c->target[k] - c->dist * v->fwd[k];
    v->right[0] = v->fwd[1], v->right[1] = -v->fwd[0], v->right[2] = 0; /* fwd x z */
    l = sqrt(v->right[0] * v->right[0] + v->right[1] * v->right[1]);
    for (k = 0; k < 3; k++) v->right[k] *= tf * aspect / l;
    v->up[0] = (v->right[1] * v->fwd[2] - v->right[2] * v->fwd[1]) / aspect;
    v->up[1] = (v->right[2] * v->fwd[0] - v->right[0] * v->fwd[2]) / aspect;
    v->up[2] = (v->right[0] * v->fwd[1] - v->right[1] * v->fwd[0]) / aspect;
}

/* ------------------------------------------------------------------ culling */
/* Frustum grids. From an apex E, the rays E + t (F + x R + y U), t > 0, with (x, y) in one cell
 * [x0, x1] x [y0, y1] of a grid form a convex cone. Each cell lists the cylinders that may meet
 * its cone, nearest first, each with a lower bound of its distance from E. A cylinder is left
 * out of a cell only when a plane through E separates the two:
 *  - one of the cell's four side planes, with the cylinder wholly outside it (the cylinder's
 *    support function, its largest n.(x - E), is negative), or
 *  - one of the two planes through E that contain the axis direction and touch the cylinder's
 *    infinite tube, with the cell's four corner rays wholly beyond it. No side plane alone ever
 *    separates an infinite tube (nor, often, a long pipe): this test is what culls them.
 * Primary rays use one grid of TILE x TILE pixel tiles from the eye, built every frame; shadow
 * rays use a cube of six grids around the light, built once (the "light buffer" of Haines and
 * Greenberg, IEEE CG&A 6(9), 1986).
 * Culling must never drop a hit, so each cylinder is widened by CULL_PAD_REL of its radius and
 * half height (far more than the library's tangent tolerance, a relative 2^-17 of r, and than
 * the t error of grazing hits) plus CULL_PAD_ABS of the largest coordinate of the apex and of
 * the center (far more than the float copy's roundings, and than any ray origin's distance
 * from the apex: the eye rounded to float, or a shadow ray's end, which light_list checks).
 * test_examples compares culled renders with --no-cull ones pixel for pixel. */
#define TILE 8                /* pixels on a side of a camera grid cell */
#define LIGHT_CELLS 32        /* cells on a side of each face of the light cube */
#define CULL_PAD_REL 0x1p-10
#define CULL_PAD_ABS 0x1p-16
/* Cells are widened by this (in x, y units) so that rounding in a lookup's division never
   sends a ray to a cell whose cone misses it. */
#define CELL_PAD 0x1p-30

/* One cylinder as seen from an apex, widened. */
typedef struct cull {
    double w[3], a[3], r, H, dmin; /* w = center - apex, a unit axis, H half height (or inf) */
    double m[2][3];                /* outward normals of the two tangent planes through apex */
    int everywhere, tangent;       /* apex within its bounding volume; tangent planes exist */
} cull;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double maxabs3(const double a[3])
{
    double m = fabs(a[0]);
    if (fabs(a[1]) > m) m = fabs(a[1]);
    return fabs(a[2]) > m ? fabs(a[2]) : m;
}

static void cull_prepare(const cyld_cylinder *c, const double apex[3], cull *k)
{
    double len = sqrt(dot3(c->a, c->a)), H = 0.5 * c->h, hfin = isinf(H) ? 0 : H;
    double pad = CULL_PAD_REL * (c->r + hfin) + CULL_PAD_ABS * (maxabs3(apex) + maxabs3(c->c));
    double wa, e1[3], e2[3], rho, s, co;
    int i;
    k->r = c->r + pad;
    k->H = H + pad;
    for (i = 0; i < 3; i++) k->w[i] = c->c[i] - apex[i], k->a[i] = c->a[i] / len;
    wa = dot3(k->w, k->a);
    for (i = 0; i < 3; i++) e1[i] = k->w[i] - wa * k->a[i]; /* apex to axis, across it */
    rho = sqrt(dot3(e1, e1));
    k->dmin = rho - k->r; /* distance to the infinite tube, then to the bounding sphere */
    if (!isinf(H)) {
        double sphere = sqrt(dot3(k->w, k->w)) - sqrt(k->r * k->r + k->H * k->H);
        if (sphere > k->dmin) k->dmin = sphere;
    }
    k->everywhere = !(k->dmin > 0);
    k->tangent = rho > k->r;
    if (!k->tangent) return;
    /* In the plane across the axis the tube is a disk at distance rho in direction e1; the
       tangent lines from the apex leave e1 at the angle whose sine is r / rho. */
    s = k->r / rho;
    co = sqrt(1 - s * s);
    for (i = 0; i < 3; i++) e1[i] /= rho;
    cross3(k->a, e1, e2);
    for (i = 0; i < 3; i++) {
        k->m[0][i] = -s * e1[i] + co * e2[i];
        k->m[1][i] = -s * e1[i] - co * e2[i];
    }
}

/* The largest n.(x - apex) over the widened cylinder: n.w + H |n.a| + r |n x a|. */
static double support(const cull *k, const double n[3])
{
    double na = fabs(dot3(n, k->a)), across = dot3(n, n) - na * na;
    return dot3(n, k->w) + (na > 0 ? k->H * na : 0) + k->r * sqrt(across > 0 ? across : 0);
}

/* The culls of every cylinder from an apex, and the cylinders sorted nearest first. */
static void cull_all(const object *obj, int n, const double apex[3], cull *k, int *order)
{
    int i, j;
    for (i = 0; i < n; i++) {
        cull_prepare(&obj[i].cd, apex, &k[i]);
        for (j = i; j > 0 && k[order[j - 1]].dmin > k[i].dmin; j--) order[j] = order[j - 1];
        order[j] = i;
    }
}

/* Builds g for the cells between the edges xe[0..gx] and ye[0..gy] (ascending) of the apex's
   rays F + x R + y U, from the n culls visited in `order` (so every list is nearest first). */
static int grid_build(grid *g, const cull *k, const int *order, int n, const double F[3],
                      const double R[3], const double U[3], const double *xe, int gx,
                      const double *ye, int gy)
{
    int cells = gx * gy, pass, oi, ix, iy, i, total = 0;
    double (*nx)[3] = (double (*)[3])malloc(sizeof *nx * (size_t)(2 * (gx + gy)));
    double (*ny)[3] = nx + 2 * gx;
    unsigned char *colok = (unsigned char *)malloc((size_t)(gx + gy)), *rowok = colok + gx;
    int *at = (int *)malloc(sizeof *at * (size_t)cells);
    if (!nx || !colok || !at) goto fail;
    if (cells + 1 > g->cap_cells) {
        free(g->first);
        g->cap_cells = cells + 1;
        if (!(g->first = (int *)malloc(sizeof *g->first * (size_t)g->cap_cells))) goto fail;
    }
    g->gx = gx, g->gy = gy;
    /* Inward normals of every cell's side planes: n.(F + x R + y U) grows with x on the left
       side (normal (F + x0 R) x U), shrinks with x on the right side; the same for y. */
    for (ix = 0; ix < 2 * gx; ix++) {
        double x = ix < gx ? xe[ix] - CELL_PAD : xe[ix - gx + 1] + CELL_PAD, v[3];
        for (i = 0; i < 3; i++) v[i] = F[i] + x * R[i];
        cross3(v, U, nx[ix]);
        if ((dot3(nx[ix], R) < 0) == (ix < gx))
            for (i = 0; i < 3; i++) nx[ix][i] = -nx[ix][i];
    }
    for (iy = 0; iy < 2 * gy; iy++) {
        double y = iy < gy ? ye[iy] - CELL_PAD : ye[iy - gy + 1] + CELL_PAD, v[3];
        for (i = 0; i < 3; i++) v[i] = F[i] + y * U[i];
        cross3(R, v, ny[iy]);
        if ((dot3(ny[iy], U) < 0) == (iy < gy))
            for (i = 0; i < 3; i++) ny[iy][i] = -ny[iy][i];
    }
    for (pass = 0; pass < 2; pass++) {
        if (pass == 0) memset(at, 0, sizeof *at * (size_t)cells);
        for (oi = 0; oi < n; oi++) {
            const cull *c = &k[order[oi]];
            double mf[2], mr[2], mu[2];
            for (i = 0; i < 2; i++)
                mf[i] = dot3(c->m[i], F), mr[i] = dot3(c->m[i], R), mu[i] = dot3(c->m[i], U);
            for (ix = 0; ix < gx; ix++)
                colok[ix] = c->everywhere || (support(c, nx[ix]) >= 0 && support(c, nx[gx + ix]) >= 0);
            for (iy = 0; iy < gy; iy++)
                rowok[iy] = c->everywhere || (support(c, ny[iy]) >= 0 && support(c, ny[gy + iy]) >= 0);
            for (iy = 0; iy < gy; iy++) {
                if (!rowok[iy]) continue;
                for (ix = 0; ix < gx; ix++) {
                    int beyond = 0, cell = iy * gx + ix;
                    if (!colok[ix]) continue;
                    for (i = 0; i < 2 && c->tangent && !c->everywhere && !beyond; i++) {
                        /* all four corner rays on the far side of tangent plane i */
                        double base0 = mf[i] + (xe[ix] - CELL_PAD) * mr[i];
                        double base1 = mf[i] + (xe[ix + 1] + CELL_PAD) * mr[i];
                        double y0 = ye[iy] - CELL_PAD, y1 = ye[iy + 1] + CELL_PAD;
                        beyond = base0 + y0 * mu[i] > 0 && base0 + y1 * mu[i] > 0 &&
                                 base1 + y0 * mu[i] > 0 && base1 + y1 * mu[i] > 0;
                    }
                    if (beyond) continue;
                    if (pass == 0) {
                        at[cell]++;
                    } else {
                        g->item[at[cell]] = order[oi];
                        g->dmin[at[cell]++] = c->dmin;
                    }
                }
            }
        }
        if (pass == 0) { /* counts to starts */
            for (i = 0; i < cells; i++) {
                g->first[i] = total;
                total += at[i];
                at[i] = g->first[i];
            }
            g->first[cells] = total;
            if (total > g->cap_items) {
                free(g->item);
                free(g->dmin);
                g->cap_items = total;
                g->item = (int *)malloc(sizeof *g->item * (size_t)total);
                g->dmin = (double *)malloc(sizeof *g->dmin * (size_t)total);
                if (!g->item || !g->dmin) goto fail;
            }
        }
    }
    free(nx);
    free(colok);
    free(at);
    return 0;
fail:
    free(nx);
    free(colok);
    free(at);
    g->cap_cells = g->cap_items = 0;
    return -1;
}

/* The six faces of the light cube: face 2k + 1 looks along -e_k; R and U are the next axes. */
static int light_build(scene *s)
{
    double edge[LIGHT_CELLS + 1];
    cull *k = (cull *)malloc(sizeof *k * (size_t)s->n);
    int f, i, rc = 0;
    if (!k) return -1;
    for (i = 0; i <= LIGHT_CELLS; i++) edge[i] = -1 + 2.0 * i / LIGHT_CELLS;
    cull_all(s->obj, s->n, s->light, k, s->light_order);
    for (i = 0; i < s->n; i++) s->light_dmin[i] = k[s->light_order[i]].dmin;
    for (f = 0; f < 6 && !rc; f++) {
        double F[3] = {0, 0, 0}, R[3] = {0, 0, 0}, U[3] = {0, 0, 0};
        F[f / 2] = f % 2 ? -1 : 1;
        R[(f / 2 + 1) % 3] = 1;
        U[(f / 2 + 2) % 3] = 1;
        rc = grid_build(&s->light_grid[f], k, s->light_order, s->n, F, R, U, edge,
                        LIGHT_CELLS, edge, LIGHT_CELLS);
    }
    /* A shadow ray may end this far from the light (each coordinate) and keep its cell. */
    s->light_shift = 0.5 * CULL_PAD_ABS * maxabs3(s->light);
    free(k);
    return rc;
}

/* The camera grid of one frame: TILE x TILE pixel tiles; y grows down the image. */
static int camera_build(scene *s, const view *v, int w, int h)
{
    int gx = (w + TILE - 1) / TILE, gy = (h + TILE - 1) / TILE, i, rc = -1;
    double *xe = (double *)malloc(sizeof *xe * (size_t)(gx + gy + 2)), *ye = xe + gx + 1;
    double down[3];
    cull *k = (cull *)malloc(sizeof *k * (size_t)s->n);
    int *order = (int *)malloc(sizeof *order * (size_t)s->n);
    if (xe && k && order) {
        for (i = 0; i <= gx; i++) xe[i] = 2.0 * (i * TILE < w ? i * TILE : w) / w - 1;
        for (i = 0; i <= gy; i++) ye[i] = 2.0 * (i * TILE < h ? i * TILE : h) / h - 1;
        for (i = 0; i < 3; i++) down[i] = -v->up[i];
        cull_all(s->obj, s->n, v->eye, k, order);
        rc = grid_build(&s->cam_grid, k, order, s->n, v->fwd, v->right, down, xe, gx, ye, gy);
    }
    free(xe);
    free(k);
    free(order);
    return rc;
}

/* The list of a camera grid cell, or every cylinder (--no-cull). */
typedef struct list { const int *item; const double *dmin; int n; } list;

static list cell_list(const grid *g, int cell)
{
    list l;
    l.item = g->item + g->first[cell];
    l.dmin = g->dmin + g->first[cell];
    l.n = g->first[cell + 1] - g->first[cell];
    return l;
}

static list all_list(const scene *s)
{
    list l;
    l.item = s->all, l.dmin = s->zero, l.n = s->n;
    return l;
}

/* The cylinders a shadow ray from p to p + l (l reaches the light) may meet: its light cube
   cell, or all of them, nearest the light first, when the ray's end is too far from the light
   for the cube's widening to cover it (a far origin rounded to float) or culling is off. */
static list light_list(const scene *s, const settings *st, const double p[3], const double l[3])
{
    double q[3], x, y, off = 0;
    int k, ix, iy, f;
    list all;
    all.item = s->light_order, all.dmin = s->light_dmin, all.n = s->n;
    for (k = 0; k < 3; k++) {
        double e = fabs(p[k] + l[k] - s->light[k]);
        off = e > off ? e : off;
        q[k] = -l[k]; /* from the light towards p */
    }
    k = fabs(q[0]) >= fabs(q[1]) ? (fabs(q[0]) >= fabs(q[2]) ? 0 : 2)
                                 : (fabs(q[1]) >= fabs(q[2]) ? 1 : 2);
    if (st->nocull) return all_list(s);
    if (off > s->light_shift || !(fabs(q[k]) > 0)) return all;
    f = 2 * k + (q[k] < 0);
    x = q[(k + 1) % 3] / fabs(q[k]);
    y = q[(k + 2) % 3] / fabs(q[k]);
    ix = (int)((x + 1) * (0.5 * LIGHT_CELLS));
    iy = (int)((y + 1) * (0.5 * LIGHT_CELLS));
    ix = ix < 0 ? 0 : ix >= LIGHT_CELLS ? LIGHT_CELLS - 1 : ix;
    iy = iy < 0 ? 0 : iy >= LIGHT_CELLS ? LIGHT_CELLS - 1 : iy;
    return cell_list(&s->light_grid[f], iy * LIGHT_CELLS + ix);
}

/* Can the line o + t d meet the (widened) infinite tube of cylinder ob? Its distance from the
   axis line is |w.n| / |n| with w = o - c and n = a x d; the comparison is widened by a
   relative 2^-40 against the roundings of n when d is nearly parallel to the axis. Rejects
   most of the cylinders a cell lists before the library is called. */
static int tube_may_hit(const object *ob, int dbl, const double o[3], const double d[3])
{
    double w[3], n[3], wn, nn, ww, dd;
    int k;
    for (k = 0; k < 3; k++) w[k] = o[k] - ob->tube_c[dbl][k];
    cross3(ob->tube_a[dbl], d, n);
    wn = dot3(w, n), nn = dot3(n, n), ww = dot3(w, w), dd = dot3(d, d);
    return wn * wn <= ob->tube_r2[dbl] * nn + 0x1p-40 * (ww + ob->tube_r2[dbl]) * dd;
}

/* Nearest hit along o + t d, t >= 0, among a list (nearest first): the walk stops at the first
   cylinder no point of which can be reached before the nearest hit so far. */
static int nearest(const scene *s, const settings *st, int dbl, int alt, unsigned extra,
                   const double o[3], const double d[3], list l, hitinfo *best, stats *sum)
{
    double dlen = sqrt(dot3(d, d)) * (1 + 0x1p-40); /* an upper bound of |d| */
    int i, found = 0;
    sum->rays++;
    best->t = HUGE_VAL;
    for (i = 0; i < l.n && !(l.dmin[i] > best->t * dlen); i++) {
        int ob = l.item[i], rc;
        if (!st->nocull && !tube_may_hit(&s->obj[ob], dbl, o, d)) continue;
        sum->calls++;
        rc = hit_one(s, ob, dbl, alt, object_opts(s, ob, st) | extra, o, d, best->t, best);
        if (rc < 0) sum->errors++;
        if (rc > 0) found = 1;
    }
    return found;
}

/* Is the segment o + t l, t in [0, 1], blocked by a cylinder of the list (nearest the segment's
   end first) other than skip? The blocker goes into *who. */
static int blocked(const scene *s, const settings *st, int dbl, const double o[3],
                   const double l[3], list li, int skip, int *who, stats *sum)
{
    double len = sqrt(dot3(l, l)) * (1 + 0x1p-40);
    const unsigned extras = CYL_NO_NORMAL | CYL_NO_ERRBOUND;
    int i;
    sum->rays++;
    for (i = 0; i < li.n && !(li.dmin[i] > len); i++) {
        int ob = li.item[i], rc;
        if (ob == skip || (!st->nocull && !tube_may_hit(&s->obj[ob], dbl, o, l))) continue;
        sum->calls++;
        rc = occluded_one(s, ob, dbl, object_opts(s, ob, st) | extras, o, l, 1.0);
        if (rc < 0) sum->errors++;
        if (rc > 0) {
            *who = ob;
            return 1;
        }
    }
    return 0;
}

/* Colour for the error view: how far the float answer is from the double path's answer for
   the same (widened) inputs, in units of the library's float t_err. On the literal half of the
   split view the literal formulation's t is measured against the library's bound instead. */
static void error_colour(const scene *s, const settings *st, int alt, const double o[3],
                         const double d[3], const hitinfo *hf, double rgb[3], stats *sum)
{
    const cylf_cylinder *cf = &s->obj[hf->obj].cf;
    unsigned opts = object_opts(s, hf->obj, st);
    cyld_cylinder cw;
    cyld_ray rw;
    cyld_hit hd[2];
    int k, n, pick = -1;
    double diff, bound = hf->t_err, ratio, x;
    for (k = 0; k < 3; k++) { /* the same float inputs, widened exactly */
        cw.c[k] = (double)cf->c[k];
        cw.a[k] = (double)cf->a[k];
        rw.o[k] = o[k];
        rw.d[k] = d[k];
    }
    cw.r = (double)cf->r;
    cw.h = (double)cf->h;
    rw.tmin = -HUGE_VAL;
    rw.tmax = HUGE_VAL;
    n = cyld_intersect_all(&rw, &cw, opts, hd);
    /* the double crossing of the same kind: same part, both entries or both exits */
    for (k = 0; k < n; k++)
        if (hd[k].part == hf->part && (hd[k].flags & CYL_F_INSIDE) == (hf->flags & CYL_F_INSIDE) &&
            (pick < 0 || fabs(hd[k].t - hf->t) < fabs(hd[pick].t - hf->t))) pick = k;
    if (alt) { /* the library's float bound for the same pixel and cylinder */
        hitinfo lib;
        bound = HUGE_VAL;
        if (hit_one(s, hf->obj, 0, 0, opts, o, d, HUGE_VAL, &lib) == CYL_HIT) bound = lib.t_err;
    }
    if (pick < 0) {
        if (!alt) sum->unconfirmed++;
        rgb[0] = 1, rgb[1] = 0, rgb[2] = 1;
        return;
    }
    diff = fabs(hf->t - hd[pick].t);
    /* Both bounds are rigorous, so the two answers can differ by at most their sum. */
    if (diff > bound + hd[pick].t_err) {
        if (!alt) sum->over_bound++;
        rgb[0] = 1, rgb[1] = 0, rgb[2] = 0;
        return;
    }
    ratio = bound > 0 ? diff / bound : 0;
    if (!alt && ratio > sum->max_ratio) sum->max_ratio = ratio;
    x = ratio > 0 ? fmin(1.0, fmax(0.0, 1.0 + log2(ratio) / ERR_LOG2_RANGE)) : 0;
    if (x < 0.5) { /* dark blue -> teal -> yellow */
        rgb[0] = 0.05, rgb[1] = 0.05 + 1.1 * x, rgb[2] = 0.35 + 0.5 * x;
    } else {
        rgb[0] = 0.05 + 1.9 * (x - 0.5), rgb[1] = 0.6 + 0.7 * (x - 0.5);
        rgb[2] = 0.6 - 1.1 * (x - 0.5);
    }
}

static double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

static void shade_pixel(const scene *s, const settings *st, const view *v, int x, int y,
                        int w, int h, unsigned char *out, stats *sum, int *blocker)
{
    double o[3], d[3], rgb[3], px = 2 * (x + 0.5) / w - 1, py = 1 - 2 * (y + 0.5) / h;
    int k, alt = st->split && x >= w / 2;
    int dbl = st->use_double && st->view != VIEW_ERROR;
    hitinfo hit;
    unsigned extra = st->view == VIEW_ERROR ? 0u : (unsigned)CYL_NO_ERRBOUND;
    list cands = st->nocull ? all_list(s)
                            : cell_list(&s->cam_grid, y / TILE * s->cam_grid.gx + x / TILE);
    for (k = 0; k < 3; k++) {
        o[k] = v->eye[k];
        d[k] = v->fwd[k] + px * v->right[k] + py * v->up[k];
        if (!dbl) o[k] = (double)(float)o[k], d[k] = (double)(float)d[k];
    }
    if (st->split && x == w / 2) {
        rgb[0] = rgb[1] = rgb[2] = 1;
    } else if (!nearest(s, st, dbl, alt, extra, o, d, cands, &hit, sum)) {
        double g = 0.5 + 0.5 * d[2] / sqrt(dot3(d, d));
        rgb[0] = 0.55 + 0.25 * g, rgb[1] = 0.65 + 0.25 * g, rgb[2] = 0.8 + 0.2 * g;
        if (st->view != VIEW_SHADE) rgb[0] = rgb[1] = rgb[2] = 0;
    } else if (sum->hits++, st->view == VIEW_NORMALS) {
        for (k = 0; k < 3; k++) rgb[k] = 0.5 + 0.5 * hit.n[k];
    } else if (st->view == VIEW_ERROR) {
        error_colour(s, st, alt, o, d, &hit, rgb, sum);
    } else {
        const object *ob = &s->obj[hit.obj];
        double p[3], l[3], len = 0, ndotl = 0, lit, eps, big = 0;
        for (k = 0; k < 3; k++) {
            p[k] = o[k] + hit.t * d[k];
            l[k] = s->light[k] - p[k];
            len += l[k] * l[k];
            ndotl += hit.n[k] * l[k];
            big = fabs(p[k]) > big ? fabs(p[k]) : big;
        }
        lit = ndotl > 0 ? ndotl / sqrt(len) : 0; /* the normal faces the eye: two-sided */
        if (lit > 0 && st->shadows) {
            int skip, blk = 0;
            eps = SHADOW_OFFSET_R * (dbl ? ob->cd.r : (double)ob->cf.r) + SHADOW_OFFSET_ULPS * big;
            for (k = 0; k < 3; k++) {
                p[k] += eps * hit.n[k];
                l[k] = s->light[k] - p[k]; /* t in [0, 1] reaches the light */
                if (!dbl) p[k] = (double)(float)p[k], l[k] = (double)(float)l[k];
            }
            /* A ray leaving a solid (capped) cylinder from outside cannot meet it again, and
               the previous pixel's occluder is the likeliest one: test it first. */
            skip = (object_opts(s, hit.obj, st) & CYL_CAPS) && !(hit.flags & CYL_F_INSIDE)
                       ? hit.obj : -1;
            if (*blocker >= 0 && *blocker != skip) {
                sum->calls++;
                blk = occluded_one(s, *blocker, dbl, object_opts(s, *blocker, st) |
                                   CYL_NO_NORMAL | CYL_NO_ERRBOUND, p, l, 1.0) > 0;
            }
            if (blk) sum->rays++;
            else if (!blocked(s, st, dbl, p, l, light_list(s, st, p, l), skip, blocker, sum))
                *blocker = -1;
            else blk = 1;
            if (blk) lit = 0;
        }
        for (k = 0; k < 3; k++) {
            rgb[k] = ob->rgb[k] * (0.18 + 0.82 * lit);
            if (hit.flags & CYL_F_INSIDE) rgb[k] *= 0.8; /* inner faces a little darker */
        }
    }
    for (k = 0; k < 3; k++) /* gamma 2 */
        out[k] = (unsigned char)(255.0 * sqrt(clamp01(rgb[k])) + 0.5);
}

typedef struct job {
    const scene *s;
    const settings *st;
    const view *v;
    image *img;
    int first, step;
    stats sum;
} job;

static void *render_rows(void *arg)
{
    job *j = (job *)arg;
    int x, y, blocker = -1; /* the last shadow ray's occluder */
    for (y = j->first; y < j->img->h; y += j->step)
        for (x = 0; x < j->img->w; x++)
            shade_pixel(j->s, j->st, j->v, x, y, j->img->w, j->img->h,
                        j->img->rgb + 3 * ((size_t)y * (size_t)j->img->w + (size_t)x), &j->sum, &blocker);
    return NULL;
}

/* Traces one frame on nthreads threads (interleaved rows) and returns the summed stats. */
static stats render(scene *s, const settings *st_in, image *img, int nthreads)
{
    pthread_t th[MAX_THREADS];
    job jobs[MAX_THREADS];
    view v;
    stats sum;
    settings st_copy = *st_in, *st = &st_copy;
    int i;
    make_view(&s->cam, (double)img->w / img->h, &v);
    if (!st->nocull && camera_build(s, &v, img->w, img->h)) st->nocull = 1; /* out of memory */
    memset(&sum, 0, sizeof sum);
    for (i = 0; i < nthreads; i++) {
        jobs[i].s = s, jobs[i].st = st, jobs[i].v = &v, jobs[i].img = img;
        jobs[i].first = i, jobs[i].step = nthreads;
        memset(&jobs[i].sum, 0, sizeof jobs[i].sum);
        if (i > 0 && pthread_create(&th[i], NULL, render_rows, &jobs[i])) jobs[i].step = 0;
    }
    render_rows(&jobs[0]);
    for (i = 0; i < nthreads; i++) {
        if (i > 0 && jobs[i].step) pthread_join(th[i], NULL);
        else if (i > 0) render_rows(&jobs[i]); /* thread could not start: do its rows here */
        sum.rays += jobs[i].sum.rays, sum.calls += jobs[i].sum.calls;
        sum.errors += jobs[i].sum.errors;
        sum.hits += jobs[i].sum.hits, sum.over_bound += jobs[i].sum.over_bound;
        sum.unconfirmed += jobs[i].sum.unconfirmed;
        sum.max_ratio = fmax(sum.max_ratio, jobs[i].sum.max_ratio);
    }
    return sum;
}

static double clock_seconds(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double now(void) { return clock_seconds(CLOCK_MONOTONIC); }

static int precise_available(void)
{
    cylf_ray r = {{0, 0, -5}, {0, 0, 1}, 0, 10};
    cylf_cylinder c = {{0, 0, 0}, {1, 0, 0}, 1, 2};
    return cylf_occluded(&r, &c, CYL_PRECISE) != CYL_E_OPTION;
}

static void describe(char *buf, size_t n, const char *name, const settings *st, stats sum,
                     double secs)
{
    int len = snprintf(buf, n, "%s | %s | caps %s%s%s%s | %s%s | %.1f fps | %.2f Mrays/s",
                       name, st->use_double ? "double" : "float", caps_name[st->caps],
                       st->precise ? " | precise" : "",
                       st->shadows && st->view == VIEW_SHADE ? " | shadows" : "",
                       st->split ? " | split: library | literal" : "", view_name[st->view],
                       precise_available() ? "" : " (precise n/a)", 1 / secs,
                       1e-6 * (double)sum.rays / secs);
    if (st->view == VIEW_ERROR && len > 0 && (size_t)len < n)
        snprintf(buf + len, n - (size_t)len,
                 " | %ld hits | max %.3g t_err, %ld over bound, %ld unconfirmed", sum.hits,
                 sum.max_ratio, sum.over_bound, sum.unconfirmed);
}

/* ------------------------------------------------------------------ window */
typedef struct app {
    scene *s;
    settings st;
    camera home;
    image img;
    int dirty, dragging, precise_ok;
    double mx, my;
} app;

static void on_key(GLFWwindow *win, int key, int scancode, int action, int mods)
{
    app *a = (app *)glfwGetWindowUserPointer(win);
    (void)scancode, (void)mods;
    if (action != GLFW_PRESS) return;
    switch (key) {
    case GLFW_KEY_F: a->st.use_double = !a->st.use_double; break;
    case GLFW_KEY_C: a->st.caps = (a->st.caps + 1) % 3; break;
    case GLFW_KEY_P: a->st.precise = a->precise_ok && !a->st.precise; break;
    case GLFW_KEY_S: a->st.shadows = !a->st.shadows; break;
    case GLFW_KEY_N: a->st.view = a->st.view == VIEW_NORMALS ? VIEW_SHADE : VIEW_NORMALS; break;
    case GLFW_KEY_E: a->st.view = a->st.view == VIEW_ERROR ? VIEW_SHADE : VIEW_ERROR; break;
    case GLFW_KEY_V: a->st.split = !a->st.split; break;
    case GLFW_KEY_R: a->s->cam = a->home; break;
    case GLFW_KEY_Q:
    case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(win, 1); break;
    default: return;
    }
    a->dirty = 1;
}

static void on_button(GLFWwindow *win, int button, int action, int mods)
{
    app *a = (app *)glfwGetWindowUserPointer(win);
    (void)mods;
    if (button == GLFW_MOUSE_BUTTON_LEFT) a->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(win, &a->mx, &a->my);
}

static void on_cursor(GLFWwindow *win, double x, double y)
{
    app *a = (app *)glfwGetWindowUserPointer(win);
    if (a->dragging) {
        a->s->cam.yaw -= 0.3 * (x - a->mx);
        a->s->cam.pitch = fmax(-89.0, fmin(89.0, a->s->cam.pitch + 0.3 * (y - a->my)));
        a->dirty = 1;
    }
    a->mx = x, a->my = y;
}

static void on_scroll(GLFWwindow *win, double dx, double dy)
{
    app *a = (app *)glfwGetWindowUserPointer(win);
    (void)dx;
    a->s->cam.dist *= pow(0.9, dy);
    a->dirty = 1;
}

static int run_window(app *a, const char *name, int w, int h, int nthreads, long frames,
                      const char *readback)
{
    GLFWwindow *win;
    GLuint tex;
    long frame = 0;
    char title[256];
    double start;
    if (!glfwInit()) return 2;
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    win = glfwCreateWindow(w, h, name, NULL, NULL);
    if (!win) {
        glfwTerminate();
        return 2;
    }
    glfwMakeContextCurrent(win);
    glfwSwapInterval(0);
    glfwSetWindowUserPointer(win, a);
    glfwSetKeyCallback(win, on_key);
    glfwSetMouseButtonCallback(win, on_button);
    glfwSetCursorPosCallback(win, on_cursor);
    glfwSetScrollCallback(win, on_scroll);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glEnable(GL_TEXTURE_2D);
    a->dirty = 1;
    start = now();
    while (!glfwWindowShouldClose(win)) {
        int fw, fh;
        glfwGetFramebufferSize(win, &fw, &fh);
        if (fw > 0 && fh > 0 && (fw != a->img.w || fh != a->img.h)) { /* trace 1:1 */
            free(a->img.rgb);
            a->img.w = fw, a->img.h = fh;
            a->img.rgb = (unsigned char *)malloc((size_t)fw * (size_t)fh * 3);
            if (!a->img.rgb) break;
            a->dirty = 1;
        }
        if (a->dirty && a->img.rgb) {
            double t0 = now();
            stats sum = render(a->s, &a->st, &a->img, nthreads);
            describe(title, sizeof title, name, &a->st, sum, now() - t0);
            glfwSetWindowTitle(win, title);
            a->dirty = 0;
            glViewport(0, 0, fw, fh);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, fw, fh, 0, GL_RGB, GL_UNSIGNED_BYTE, a->img.rgb);
            glBegin(GL_QUADS); /* image row 0 is the top: flip v */
            glTexCoord2f(0, 1), glVertex2f(-1, -1);
            glTexCoord2f(1, 1), glVertex2f(1, -1);
            glTexCoord2f(1, 0), glVertex2f(1, 1);
            glTexCoord2f(0, 0), glVertex2f(-1, 1);
            glEnd();
            if (frames && ++frame >= frames) {
                if (readback) { /* what OpenGL shows, read back from the back buffer */
                    image shot;
                    int y, rc;
                    shot.w = fw, shot.h = fh;
                    shot.rgb = (unsigned char *)malloc((size_t)fw * (size_t)fh * 3);
                    if (!shot.rgb) break;
                    glReadPixels(0, 0, fw, fh, GL_RGB, GL_UNSIGNED_BYTE, shot.rgb);
                    for (y = 0; y < fh / 2; y++) { /* OpenGL rows go bottom up */
                        size_t row = (size_t)fw * 3;
                        unsigned char *p = shot.rgb + (size_t)y * row;
                        unsigned char *q = shot.rgb + (size_t)(fh - 1 - y) * row;
                        size_t i;
                        for (i = 0; i < row; i++) {
                            unsigned char t = p[i];
                            p[i] = q[i], q[i] = t;
                        }
                    }
                    rc = png_write_rgb(readback, &shot);
                    free(shot.rgb);
                    if (rc) fprintf(stderr, "cannot write %s\n", readback);
                    printf("window %dx%d read back into %s\n", fw, fh, readback);
                }
                glfwSwapBuffers(win);
                printf("window: %ld frames in %.2f s (%.1f fps with display), last: %s\n", frame,
                       now() - start, (double)frame / (now() - start), title);
                break;
            }
            glfwSwapBuffers(win);
        }
        if (frames) { /* scripted: render frame after frame until the count is reached */
            a->dirty = 1;
            glfwPollEvents();
        } else {
            glfwWaitEvents();
        }
    }
    glDeleteTextures(1, &tex);
    glfwDestroyWindow(win);
    glfwTerminate();
    return 0;
}

/* ------------------------------------------------------------------ main */
static int usage(void)
{
    fprintf(stderr, "usage: viewer [--headless] [--out F.png] [--size WxH] [--bench [N]] "
                    "[--double] [--caps scene|open|capped] [--precise] [--no-shadows] "
                    "[--view shade|normals|error] [--split] [--threads N] [--frames N] "
                    "[--readback F.png] [scene.txt]\n");
    return 1;
}

static int pick(const char *arg, const char *const *names, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(arg, names[i])) return i;
    return -1;
}

int main(int argc, char **argv)
{
    const char *path = "examples/scenes/molecule.txt", *out = "viewer.png", *readback = NULL;
    const char *name;
    int headless = 0, w = 640, h = 480, i, rc = 0;
    long bench = 0, frames = 0, nthreads = sysconf(_SC_NPROCESSORS_ONLN);
    settings st = {0, CAPS_SCENE, 0, 1, VIEW_SHADE, 0, 0};
    scene s;
    app a;
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
        if (arg[0] != '-') path = arg;
        else if (!strcmp(arg, "--headless")) headless = 1;
        else if (!strcmp(arg, "--double")) st.use_double = 1;
        else if (!strcmp(arg, "--precise")) st.precise = 1;
        else if (!strcmp(arg, "--no-shadows")) st.shadows = 0;
        else if (!strcmp(arg, "--split")) st.split = 1;
        else if (!strcmp(arg, "--no-cull")) st.nocull = 1;
        else if (!strcmp(arg, "--bench")) {
            bench = 60;
            if (next && next[0] != '-' && atol(next) > 0) bench = atol(argv[++i]);
        } else if (!next) return usage();
        else if (!strcmp(arg, "--out")) out = argv[++i];
        else if (!strcmp(arg, "--readback")) readback = argv[++i];
        else if (!strcmp(arg, "--frames")) frames = atol(argv[++i]);
        else if (!strcmp(arg, "--threads")) nthreads = atol(argv[++i]);
        else if (!strcmp(arg, "--size")) {
            if (sscanf(argv[++i], "%dx%d", &w, &h) != 2 || w < 2 || h < 2) return usage();
        } else if (!strcmp(arg, "--caps")) {
            if ((st.caps = pick(argv[++i], caps_name, 3)) < 0) return usage();
        } else if (!strcmp(arg, "--view")) {
            if ((st.view = pick(argv[++i], view_name, 3)) < 0) return usage();
        } else return usage();
    }
    if (nthreads < 1) nthreads = 1;
    if (nthreads > MAX_THREADS) nthreads = MAX_THREADS;
    if (st.precise && !precise_available()) {
        fprintf(stderr, "CYL_PRECISE is compiled out of this build\n");
        return 1;
    }
    if (scene_load(&s, path)) return 1;
    name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;

    if (headless || bench) {
        image img;
        stats sum;
        double t0, secs;
        char line[256];
        img.w = w, img.h = h;
        img.rgb = (unsigned char *)malloc((size_t)w * (size_t)h * 3);
        if (!img.rgb) return 1;
        if (bench) { /* orbit a full turn so that no single view decides the figure */
            long f, rays = 0, calls = 0;
            camera home = s.cam;
            double cpu0;
            sum = render(&s, &st, &img, (int)nthreads); /* warm-up */
            t0 = now();
            cpu0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
            for (f = 0; f < bench; f++) {
                s.cam.yaw = home.yaw + 360.0 * (double)f / (double)bench;
                stats one = render(&s, &st, &img, (int)nthreads);
                rays += one.rays, calls += one.calls;
            }
            secs = (now() - t0) / (double)bench;
            cpu0 = (clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0) / (double)bench;
            sum.rays = rays / bench;
            s.cam = home;
            describe(line, sizeof line, name, &st, sum, secs);
            /* CPU time per frame says what idle cores would give on a shared, busy machine */
            printf("bench %dx%d, %ld frames, %ld threads: %s | %.2f library calls per ray | "
                   "%ld rays per frame | %.1f ms CPU per frame\n", w, h, bench, nthreads, line,
                   (double)calls / (double)rays, rays / bench, 1e3 * cpu0);
        }
        if (headless) {
            t0 = now();
            sum = render(&s, &st, &img, (int)nthreads);
            describe(line, sizeof line, name, &st, sum, now() - t0);
            if (png_write_rgb(out, &img)) {
                fprintf(stderr, "cannot write %s\n", out);
                rc = 1;
            } else {
                printf("wrote %s (%dx%d): %s\n", out, w, h, line);
            }
            if (sum.errors) printf("%ld intersection calls returned an error\n", sum.errors);
        }
        free(img.rgb);
    } else {
        memset(&a, 0, sizeof a);
        a.s = &s;
        a.st = st;
        a.home = s.cam;
        a.precise_ok = precise_available();
        rc = run_window(&a, name, w, h, (int)nthreads, frames, readback);
        if (rc == 2) fprintf(stderr, "viewer: no window could be opened (no display?)\n");
        free(a.img.rgb);
    }
    scene_free(&s);
    return rc;
}
