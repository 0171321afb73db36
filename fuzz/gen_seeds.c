/* gen_seeds.c: writes the seed corpus for fuzz_isect: meaningful cases of every kind (hits,
 * misses, tangent, parallel, origin inside or on the wall, caps and rims, clipping by tmin/tmax,
 * extreme scales, every error code), in both precisions, under several option sets and all
 * functions. `make fuzz-seeds` runs it; libFuzzer's -merge=1 then keeps the ones that add
 * coverage (`make fuzz-merge`).
 *
 *   build/fuzz/gen_seeds OUTDIR [GRIDDIR]
 * GRIDDIR receives the cases whose numbers are all small integers times powers of two, in
 * fuzz_grid's encoding.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_check.h"

typedef struct seed_case {
  const char *name;
  double o[3], d[3], tmin, tmax, c[3], a[3], r, h;
} seed_case;

#define INF HUGE_VAL

static const seed_case cases[] = {
  /* unit cylinder: c = 0, axis z, r = 1, h = 2 */
  {"center", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"offset", {-5, 0.5, 0.25}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"miss", {-5, 2, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"tangent", {-5, 1, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"near-tangent-in", {-5, 0.99999, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"near-tangent-out", {-5, 1.00001, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"parallel-in", {0.5, 0, -5}, {0, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"parallel-out", {2, 0, -5}, {0, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"parallel-on-wall", {1, 0, -5}, {0, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"near-parallel", {0.5, 0, -5}, {1e-7, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"near-parallel-d", {0.5, 0, -5}, {1e-12, 1e-13, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"inside", {0, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"inside-oblique", {0.2, 0.1, 0.3}, {1, 2, 3}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"on-wall-in", {1, 0, 0}, {-1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"on-wall-out", {1, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"on-cap", {0, 0, 1}, {0, 0.5, -1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"rim", {-5, 0, -4}, {5, 0, 5}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"rim-graze", {-5, 0, 1}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"through-caps", {0.1, 0.2, -5}, {0.01, 0.02, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"cap-then-wall", {0, 0, -3}, {0.5, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"above", {-5, 0, 3}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"behind", {5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"tmax-clip", {-5, 0, 0}, {1, 0, 0}, 0, 3.5, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"tmax-at-hit", {-5, 0, 0}, {1, 0, 0}, 0, 4, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"tmin-at-hit", {-5, 0, 0}, {1, 0, 0}, 4, 6, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"tmin-between", {-5, 0, 0}, {1, 0, 0}, 5, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"negative-range", {-5, 0, 0}, {1, 0, 0}, -INF, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"point-range", {-5, 0, 0}, {1, 0, 0}, 4, 4, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"infinite-tube", {-5, 0, 100}, {1, 0, 0.5}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, INF},
  {"infinite-parallel", {0.5, 0, 0}, {0, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, INF},
  /* general position */
  {"tilted", {3, -2, 1}, {-1, 0.7, -0.2}, 0, INF, {0.5, 0.25, -0.125}, {1, 2, 3}, 0.75, 3},
  {"tilted-long-d", {3, -2, 1}, {-1000, 700, -200}, 0, INF, {0.5, 0.25, -0.125}, {1, 2, 3}, 0.75, 3},
  {"tilted-short-a", {3, -2, 1}, {-1, 0.7, -0.2}, 0, INF, {0.5, 0.25, -0.125}, {1e-20, 2e-20, 3e-20}, 0.75, 3},
  {"negative-axis", {-5, 0.5, 0.5}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, -1}, 1, 2},
  {"thin-long", {-5, 1e-4, 3}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1e-3, 1e4},
  {"flat-disk", {0.3, 0.2, -5}, {0.1, 0, 1}, 0, INF, {0, 0, 0}, {0, 0, 1}, 10, 1e-3},
  /* far and extreme scales */
  {"far-small", {1e6, 0, 0}, {-1, 1e-10, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1e-3, 1},
  {"far-origin", {1e7, 1e7, 1e7}, {-1, -1, -1}, 0, INF, {0, 0, 0}, {1, -1, 0}, 1, 2},
  {"far-center", {1e7, 0, 0}, {0, 1, 0}, -INF, INF, {1e7, 5, 0}, {0, 0, 1}, 1, 2},
  {"huge", {-5e30, 0, 0}, {1e30, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1e30}, 1e30, 2e30},
  {"tiny", {-5e-30, 0, 0}, {1e-30, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1e-30}, 1e-30, 2e-30},
  {"subnormal-d", {-5, 0.5, 0}, {1e-40, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"subnormal-r", {-5e-40, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1e-40, 2e-40},
  {"huge-t", {-1e30, 0.5, 0}, {1e-8, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"max-coords", {-3e38, 0, 0}, {1, 0, 0}, 0, INF, {3e38, 0, 0}, {0, 0, 1}, 1e38, 2e38},
  {"negative-zero", {-5, -0.0, -0.0}, {1, -0.0, 0}, -0.0, INF, {-0.0, 0, -0.0}, {-0.0, 0, 1}, 1, 2},
  /* every error */
  {"err-nan-o", {NAN, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"err-inf-d", {0, 0, 0}, {INF, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"err-inf-c", {0, 0, 0}, {1, 0, 0}, 0, INF, {0, -INF, 0}, {0, 0, 1}, 1, 2},
  {"err-nan-a", {0, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, NAN}, 1, 2},
  {"err-zero-d", {-5, 0, 0}, {0, -0.0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"err-zero-a", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 0}, 1, 2},
  {"err-r-zero", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 0, 2},
  {"err-r-neg", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, -1, 2},
  {"err-r-nan", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, NAN, 2},
  {"err-r-inf", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, INF, 2},
  {"err-h-zero", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, 0},
  {"err-h-nan", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, NAN},
  {"err-h-neg", {-5, 0, 0}, {1, 0, 0}, 0, INF, {0, 0, 0}, {0, 0, 1}, 1, -INF},
  {"err-trange", {-5, 0, 0}, {1, 0, 0}, 2, 1, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"err-tmin-nan", {-5, 0, 0}, {1, 0, 0}, NAN, 1, {0, 0, 0}, {0, 0, 1}, 1, 2},
  {"err-tmax-nan", {-5, 0, 0}, {1, 0, 0}, 0, NAN, {0, 0, 0}, {0, 0, 1}, 1, 2},
};

/* Option sets: each seed case is written under all of them. */
static const unsigned optsets[] = {
  0, CYL_CAPS, CYL_CAPS | CYL_OUTWARD, CYL_NO_TANGENT, CYL_PRECISE, CYL_CAPS | CYL_PRECISE,
  CYL_NO_NORMAL | CYL_NO_ERRBOUND, CYL_TRUSTED | CYL_CAPS, CYL_OUTWARD | CYL_NO_TANGENT | CYL_PRECISE,
};

static int nwritten, ngrid;

/* x as m * 2^k with |m| <= 127 (fuzz_grid.h), or a special code; 0 if x has no such form. */
static int grid_code(double x, unsigned char *mk)
{
  int k;
  if (isnan(x)) { mk[0] = 0, mk[1] = 127; return 1; }
  if (isinf(x)) { mk[0] = x > 0 ? 1 : 2, mk[1] = 127; return 1; }
  if (!(x < 0) && !(x > 0)) { /* zero (exactly): -0 has its own code */
    if (signbit(x)) mk[0] = 3, mk[1] = 127;
    else mk[0] = 0, mk[1] = 0;
    return 1;
  }
  for (k = -100; k <= 100; k++) {
    double m = ldexp(x, -k);
    if (fabs(m) <= 127 && !(m > floor(m))) { /* an exact integer */
      mk[0] = (unsigned char)(signed char)m;
      mk[1] = (unsigned char)(signed char)k;
      return 1;
    }
  }
  return 0;
}

static void put_grid(const char *dir, const char *name, const fz_input *in)
{
  unsigned char buf[FZ_HEADER_BYTES + 2 * FZ_NUMS], raw[FZ_HEADER_BYTES + FZ_NUMS * 8];
  char path[1024];
  FILE *f;
  int i;
  if (!dir) return;
  fz_encode(in, raw, sizeof raw);
  memcpy(buf, raw, FZ_HEADER_BYTES);
  for (i = 0; i < FZ_NUMS; i++)
    if (!grid_code(in->d[i], buf + FZ_HEADER_BYTES + 2 * i)) return;
  snprintf(path, sizeof path, "%s/%s-%s-f%d-o%02x", dir, name, in->dbl ? "d" : "f", in->func, in->opts);
  f = fopen(path, "wb");
  if (!f) {
    perror(path);
    return;
  }
  fwrite(buf, 1, sizeof buf, f);
  fclose(f);
  ngrid++;
}

static void put(const char *dir, const char *name, const fz_input *in)
{
  unsigned char buf[FZ_HEADER_BYTES + FZ_NUMS * 8];
  char path[1024];
  size_t n = fz_encode(in, buf, sizeof buf);
  FILE *f;
  snprintf(path, sizeof path, "%s/%s-%s-f%d-o%02x", dir, name, in->dbl ? "d" : "f", in->func, in->opts);
  f = fopen(path, "wb");
  if (!f) {
    perror(path);
    return;
  }
  fwrite(buf, 1, n, f);
  fclose(f);
  nwritten++;
}

static void fill(fz_input *in, const seed_case *c)
{
  double v[FZ_NUMS];
  int i;
  for (i = 0; i < 3; i++) {
    v[FZ_O + i] = c->o[i];
    v[FZ_D + i] = c->d[i];
    v[FZ_C + i] = c->c[i];
    v[FZ_A + i] = c->a[i];
  }
  v[FZ_TMIN] = c->tmin;
  v[FZ_TMAX] = c->tmax;
  v[FZ_R] = c->r;
  v[FZ_H] = c->h;
  for (i = 0; i < FZ_NUMS; i++) {
    in->d[i] = v[i];
    /* out-of-range values become infinities explicitly (the conversion would be UB) */
    in->f[i] = fabs(v[i]) > (double)FLT_MAX ? (v[i] > 0 ? INFINITY : -INFINITY) : (float)v[i];
  }
}

int main(int argc, char **argv)
{
  const char *dir = argc > 1 ? argv[1] : ".";
  const char *gdir = argc > 2 ? argv[2] : NULL;
  size_t k, j;
  int prec, func;
  fz_input in;
  for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    int is_err = strncmp(cases[k].name, "err-", 4) == 0;
    for (prec = 0; prec < 2; prec++) {
      memset(&in, 0, sizeof in);
      in.dbl = prec;
      fill(&in, &cases[k]);
      for (j = 0; j < sizeof optsets / sizeof optsets[0]; j++) {
        if (is_err && j > 0) break;
        in.opts = optsets[j];
        for (func = 0; func < 3; func++) {
          /* errors under every function; geometry under intersect_all (it checks the others) */
          if (!is_err && func != 1 && j > 1) continue;
          in.func = func;
          put(dir, cases[k].name, &in);
          if (j < 3) put_grid(gdir, cases[k].name, &in);
        }
      }
      /* the segment form: p0 = c - a, p1 = c + a */
      if (!is_err) {
        fz_input s = in;
        int i;
        s.func = 3;
        s.opts = CYL_CAPS;
        for (i = 0; i < 3; i++) {
          double p0 = cases[k].c[i] - cases[k].a[i], p1 = cases[k].c[i] + cases[k].a[i];
          s.d[FZ_C + i] = p0, s.d[FZ_A + i] = p1;
          s.f[FZ_C + i] = (float)p0, s.f[FZ_A + i] = (float)p1;
        }
        put(dir, cases[k].name, &s);
      }
    }
  }
  /* NULL pointers, unknown option bits, strerror codes */
  memset(&in, 0, sizeof in);
  fill(&in, &cases[0]);
  for (prec = 0; prec < 2; prec++) {
    in.dbl = prec;
    for (func = 0; func < 3; func++) {
      int ns;
      in.func = func;
      for (ns = 1; ns <= 3; ns++) {
        in.nullsel = ns;
        put(dir, ns == 1 ? "null-ray" : ns == 2 ? "null-cyl" : "null-hit", &in);
      }
      in.nullsel = 0;
      if (func == 0) { /* from_segment with a NULL end (p0, then p1) */
        fz_input sg = in;
        sg.func = 3;
        sg.nullsel = 1;
        put(dir, "null-seg-p0", &sg);
        sg.nullsel = 2;
        put(dir, "null-seg-p1", &sg);
      }
      in.opts = 0x80;
      put(dir, "unknown-opt-7", &in);
      in.opts = 0x80000000u | CYL_CAPS;
      put(dir, "unknown-opt-31", &in);
      in.opts = 0;
    }
  }
  for (k = 0; k < 4; k++) {
    static const int codes[4] = {-9, 2, 100, -128};
    in.errcode = codes[k];
    in.func = 0;
    put(dir, k == 0 ? "strerror-m9" : k == 1 ? "strerror-2" : k == 2 ? "strerror-100" : "strerror-m128", &in);
  }
  printf("%d seeds written to %s, %d grid seeds to %s\n", nwritten, dir, ngrid, gdir ? gdir : "(none)");
  return 0;
}
