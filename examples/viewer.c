/* viewer.c: a CPU ray tracer of cylinders that shows what cylinder_isect does.
 *
 *   viewer [options] [scene.txt]          (default scene: examples/scenes/molecule.txt)
 *
 * Every pixel is traced on the CPU with the library, on all cores (pthreads), and shown in a
 * GLFW window as a texture. Scenes are text files, one cylinder per line (see
 * examples/scenes/make_scenes.py or docs/examples.md).
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
 *   --frames N          windowed: quit after N frames
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
typedef struct object {
    cylf_cylinder cf; /* the float path traces this one */
    cyld_cylinder cd; /* the double path traces this one (parsed in double) */
    int capped;
    double rgb[3];
} object;

typedef struct bvh_node { double lo[3], hi[3]; int first, count, right; } bvh_node;

typedef struct camera { double target[3], yaw, pitch, dist, fov; } camera;

typedef struct scene {
    object *obj;
    int n, nnodes, *order;
    bvh_node *node;
    double light[3];
    camera cam;
} scene;

/* One line of a scene file (format: examples/scenes/make_scenes.py). Returns 0, or -1 after a message. */
static int parse_line(scene *s, const char *line, int lineno, const char *path)
{
    char kind[16], cap[16];
    double v[8] = {0, 0, 0, 0, 0, 0, 0, 0}, rgb[3];
    object o;
    int i, ok = 0;
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
    s->obj = (object *)realloc(s->obj, (size_t)(s->n + 1) * sizeof *s->obj);
    if (!s->obj) return -1;
    s->obj[s->n++] = o;
    return 0;
}

/* Axis-aligned box of a cylinder: along coordinate k it reaches |â_k| H + r sqrt(1 - â_k²). */
static void object_box(const cyld_cylinder *c, double lo[3], double hi[3])
{
    double len = sqrt(c->a[0] * c->a[0] + c->a[1] * c->a[1] + c->a[2] * c->a[2]);
    int k;
    for (k = 0; k < 3; k++) {
        double ak = fabs(c->a[k]) / len, e = c->r * sqrt(fmax(0.0, 1.0 - ak * ak));
        if (ak > 0) e += ak * 0.5 * c->h; /* h may be +inf: the box is then unbounded */
        e += 1e-5 * (e + fabs(c->c[k]));   /* covers the float copy's roundings */
        lo[k] = c->c[k] - e;
        hi[k] = c->c[k] + e;
    }
}

/* Half the surface area of a box, with unbounded sides (infinite tubes) made finite. */
static double box_area(const double lo[3], const double hi[3])
{
    double e[3];
    int k;
    for (k = 0; k < 3; k++) e[k] = fmin(hi[k] - lo[k], 1e30);
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

static void box_grow(double lo[3], double hi[3], const double blo[3], const double bhi[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        lo[k] = fmin(lo[k], blo[k]);
        hi[k] = fmax(hi[k], bhi[k]);
    }
}

static void box_empty(double lo[3], double hi[3])
{
    int k;
    for (k = 0; k < 3; k++) lo[k] = HUGE_VAL, hi[k] = -HUGE_VAL;
}

static void sort_by_centre(scene *s, int first, int count, int axis)
{
    int i, j;
    for (i = first + 1; i < first + count; i++) /* insertion sort: scenes are small */
        for (j = i; j > first && s->obj[s->order[j - 1]].cd.c[axis] >
                                     s->obj[s->order[j]].cd.c[axis]; j--) {
            int t = s->order[j];
            s->order[j] = s->order[j - 1];
            s->order[j - 1] = t;
        }
}

/* A bounding volume hierarchy with one cylinder per leaf, split where the surface area
   heuristic (sum over both sides of box area times count) is lowest, over the cylinders
   sorted by centre along each axis. It puts a floor or a long pipe in a node of its own near
   the root. Nodes are stored depth first: the left child follows its parent. */
static int bvh_build(scene *s, int first, int count)
{
    int me = s->nnodes++, i, k, best_axis = 0, best_split = 1;
    double best_cost = HUGE_VAL, lo[3], hi[3], *right_area;
    bvh_node *nd = &s->node[me];
    box_empty(nd->lo, nd->hi);
    for (i = first; i < first + count; i++) {
        object_box(&s->obj[s->order[i]].cd, lo, hi);
        box_grow(nd->lo, nd->hi, lo, hi);
    }
    nd->first = first;
    nd->count = count;
    if (count == 1) return me;
    right_area = (double *)malloc((size_t)count * sizeof *right_area);
    for (k = 0; k < 3 && right_area; k++) {
        double alo[3], ahi[3];
        sort_by_centre(s, first, count, k);
        box_empty(alo, ahi);
        for (i = count - 1; i > 0; i--) { /* right_area[i]: the box of items i..count-1 */
            object_box(&s->obj[s->order[first + i]].cd, lo, hi);
            box_grow(alo, ahi, lo, hi);
            right_area[i] = box_area(alo, ahi);
        }
        box_empty(alo, ahi);
        for (i = 1; i < count; i++) {
            double cost;
            object_box(&s->obj[s->order[first + i - 1]].cd, lo, hi);
            box_grow(alo, ahi, lo, hi);
            cost = box_area(alo, ahi) * i + right_area[i] * (count - i);
            if (cost < best_cost) best_cost = cost, best_axis = k, best_split = i;
        }
    }
    free(right_area);
    sort_by_centre(s, first, count, best_axis);
    nd->count = 0;
    bvh_build(s, first, best_split);
    i = bvh_build(s, first + best_split, count - best_split);
    s->node[me].right = i;
    return me;
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
    s->order = (int *)malloc((size_t)s->n * sizeof *s->order);
    s->node = (bvh_node *)malloc((size_t)(2 * s->n) * sizeof *s->node);
    if (!s->order || !s->node) return -1;
    for (i = 0; i < s->n; i++) s->order[i] = i;
    bvh_build(s, 0, s->n);
    return 0;
}

/* ------------------------------------------------------------------ tracing */
enum { VIEW_SHADE, VIEW_NORMALS, VIEW_ERROR };
enum { CAPS_SCENE, CAPS_NONE, CAPS_ALL };
static const char *const caps_name[] = {"scene", "open", "capped"};
static const char *const view_name[] = {"shade", "normals", "error"};

typedef struct settings { int use_double, caps, precise, shadows, view, split; } settings;

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

/* Slab test; on a hit *tin is where the ray enters the box (clipped to 0). Branch free: a
   ray with d[k] = 0 has an infinite inv[k], so outside the slab both ends are the same
   infinity (a miss) and on its plane one end is a NaN, which the comparisons ignore. */
static inline int box_hit(const bvh_node *b, const double o[3], const double inv[3],
                          double tmax, double *tin)
{
    double t0 = 0, t1 = tmax;
    int k;
    for (k = 0; k < 3; k++) {
        double a = (b->lo[k] - o[k]) * inv[k], c = (b->hi[k] - o[k]) * inv[k];
        double near = a > c ? c : a, far = a > c ? a : c;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    *tin = t0;
    return t0 <= t1;
}

/* Walks the hierarchy nearer child first, skipping boxes entered beyond the nearest hit so
   far; nearest hit into *best (any_hit: stop at the first occluder, best->obj; skip: a
   cylinder not to test, or -1). */
static int trace(const scene *s, const settings *st, int dbl, int alt, int any_hit, int skip,
                 unsigned extra, const double o[3], const double d[3], double tmax,
                 hitinfo *best, stats *sum)
{
    int stack[64], sp = 0, ni = 0, found = 0, k;
    double inv[3], tin[64], t;
    for (k = 0; k < 3; k++) inv[k] = 1.0 / d[k];
    sum->rays++;
    best->t = tmax;
    if (!box_hit(&s->node[0], o, inv, tmax, &t)) return 0;
    for (;;) {
        const bvh_node *nd = &s->node[ni];
        if (nd->count && s->order[nd->first] != skip) { /* a leaf holds one cylinder */
            int ob = s->order[nd->first], rc;
            unsigned opts = object_opts(s, ob, st) | extra;
            sum->calls++;
            rc = any_hit ? occluded_one(s, ob, dbl, opts, o, d, tmax)
                         : hit_one(s, ob, dbl, alt, opts, o, d, best->t, best);
            if (rc < 0) sum->errors++;
            if (rc > 0) {
                found = 1;
                if (any_hit) {
                    best->obj = ob;
                    return 1;
                }
            }
        } else if (!nd->count) {
            int a = ni + 1, b = nd->right;
            double ta, tb;
            int ha = box_hit(&s->node[a], o, inv, best->t, &ta);
            int hb = box_hit(&s->node[b], o, inv, best->t, &tb);
            if (ha && hb) { /* go into the nearer box, keep the other for later */
                if (tb < ta) {
                    int x = a;
                    double y = ta;
                    a = b, b = x, ta = tb, tb = y;
                }
                stack[sp] = b;
                tin[sp++] = tb;
                ni = a;
                continue;
            }
            if (ha || hb) {
                ni = ha ? a : b;
                continue;
            }
        }
        do { /* next pending box that may still hold a nearer hit */
            if (!sp) return found;
            ni = stack[--sp];
        } while (tin[sp] > best->t);
    }
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

static void shade_pixel(const scene *s, const settings *st, const view *v, int x, int y,
                        int w, int h, unsigned char *out, stats *sum, int *blocker)
{
    double o[3], d[3], rgb[3], px = 2 * (x + 0.5) / w - 1, py = 1 - 2 * (y + 0.5) / h;
    int k, alt = st->split && x >= w / 2;
    int dbl = st->use_double && st->view != VIEW_ERROR;
    hitinfo hit, shadow;
    unsigned extra = st->view == VIEW_ERROR ? 0u : (unsigned)CYL_NO_ERRBOUND;
    for (k = 0; k < 3; k++) {
        o[k] = v->eye[k];
        d[k] = v->fwd[k] + px * v->right[k] + py * v->up[k];
        if (!dbl) o[k] = (double)(float)o[k], d[k] = (double)(float)d[k];
    }
    if (st->split && x == w / 2) {
        rgb[0] = rgb[1] = rgb[2] = 1;
    } else if (!trace(s, st, dbl, alt, 0, -1, extra, o, d, HUGE_VAL, &hit, sum)) {
        double g = 0.5 + 0.5 * d[2] / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        rgb[0] = 0.55 + 0.25 * g, rgb[1] = 0.65 + 0.25 * g, rgb[2] = 0.8 + 0.2 * g;
        if (st->view != VIEW_SHADE) rgb[0] = rgb[1] = rgb[2] = 0;
    } else if (sum->hits++, st->view == VIEW_NORMALS) {
        for (k = 0; k < 3; k++) rgb[k] = 0.5 + 0.5 * hit.n[k];
    } else if (st->view == VIEW_ERROR) {
        error_colour(s, st, alt, o, d, &hit, rgb, sum);
    } else {
        const object *ob = &s->obj[hit.obj];
        double p[3], l[3], len = 0, ndotl = 0, lit, eps, big = 0;
        const unsigned no_extras = CYL_NO_NORMAL | CYL_NO_ERRBOUND;
        int skip, blocked = 0;
        for (k = 0; k < 3; k++) {
            p[k] = o[k] + hit.t * d[k];
            l[k] = s->light[k] - p[k];
            len += l[k] * l[k];
            ndotl += hit.n[k] * l[k];
            big = fmax(big, fabs(p[k]));
        }
        lit = ndotl > 0 ? ndotl / sqrt(len) : 0; /* the normal faces the eye: two-sided */
        if (lit > 0 && st->shadows) {
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
                blocked = occluded_one(s, *blocker, dbl, object_opts(s, *blocker, st) |
                                       no_extras, p, l, 1.0) > 0;
            }
            if (blocked) sum->rays++;
            else
                *blocker = (blocked = trace(s, st, dbl, 0, 1, skip, no_extras, p, l, 1.0, &shadow,
                                            sum)) ? shadow.obj : -1;
            if (blocked) lit = 0;
        }
        for (k = 0; k < 3; k++) {
            rgb[k] = ob->rgb[k] * (0.18 + 0.82 * lit);
            if (hit.flags & CYL_F_INSIDE) rgb[k] *= 0.8; /* inner faces a little darker */
        }
    }
    for (k = 0; k < 3; k++) /* gamma 2 */
        out[k] = (unsigned char)(255.0 * sqrt(fmin(1.0, fmax(0.0, rgb[k]))) + 0.5);
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
static stats render(const scene *s, const settings *st, image *img, int nthreads)
{
    pthread_t th[MAX_THREADS];
    job jobs[MAX_THREADS];
    view v;
    stats sum;
    int i;
    make_view(&s->cam, (double)img->w / img->h, &v);
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

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

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
                       st->precise ? " | precise" : "", st->shadows ? " | shadows" : "",
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
                break;
            }
            glfwSwapBuffers(win);
        }
        glfwWaitEvents();
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
    settings st = {0, CAPS_SCENE, 0, 1, VIEW_SHADE, 0};
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
            sum = render(&s, &st, &img, (int)nthreads); /* warm-up */
            t0 = now();
            for (f = 0; f < bench; f++) {
                s.cam.yaw = home.yaw + 360.0 * (double)f / (double)bench;
                stats one = render(&s, &st, &img, (int)nthreads);
                rays += one.rays, calls += one.calls;
            }
            secs = (now() - t0) / (double)bench;
            sum.rays = rays / bench;
            s.cam = home;
            describe(line, sizeof line, name, &st, sum, secs);
            printf("bench %dx%d, %ld frames, %ld threads: %s | %.2f library calls per ray\n", w,
                   h, bench, nthreads, line, (double)calls / (double)rays);
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
    free(s.obj);
    free(s.order);
    free(s.node);
    return rc;
}
