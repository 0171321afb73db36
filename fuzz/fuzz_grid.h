/* fuzz_grid.h: the grid encoding of fuzz_grid.c, shared with the replay driver. */
#ifndef FUZZ_GRID_H
#define FUZZ_GRID_H

#include <math.h>
#include <string.h>

#include "fuzz_check.h"

/* m * 2^k, or a special value when k == 127: the values raw bits reach only by luck. */
static double fz_grid_value(signed char m, signed char k)
{
  if (k == 127) {
    switch ((unsigned char)m & 7u) {
    case 0: return (double)NAN;
    case 1: return (double)INFINITY;
    case 2: return -(double)INFINITY;
    case 3: return -0.0;
    case 4: return m < 0 ? -DBL_MAX : DBL_MAX;
    case 5: return m < 0 ? -0x1p-1074 : 0x1p-1074;
    case 6: return m < 0 ? -(double)FLT_MAX : (double)FLT_MAX;
    default: return m < 0 ? -0x1p-149 : 0x1p-149;
    }
  }
  if (k > 100 || k < -100) k = (signed char)(k % 101);
  return ldexp((double)m, k);
}

static size_t fz_grid_to_raw(const unsigned char *data, size_t size, unsigned char *raw, size_t cap)
{
  fz_input in;
  unsigned char hdr[FZ_HEADER_BYTES] = {0, 0, 0, 0};
  size_t i;
  for (i = 0; i < FZ_HEADER_BYTES && i < size; i++) hdr[i] = data[i];
  fz_decode(hdr, FZ_HEADER_BYTES, &in);
  for (i = 0; i < FZ_NUMS; i++) {
    size_t at = FZ_HEADER_BYTES + 2 * i;
    signed char m = (signed char)(at < size ? data[at] : 0);
    signed char k = (signed char)(at + 1 < size ? data[at + 1] : 0);
    double x = fz_grid_value(m, k);
    in.d[i] = x;
    /* double-only values round, or go to inf explicitly (an out-of-range conversion is UB) */
    in.f[i] = fabs(x) > (double)FLT_MAX ? (x > 0 ? INFINITY : -INFINITY) : (float)x;
  }
  return fz_encode(&in, raw, cap);
}

#endif /* FUZZ_GRID_H */
