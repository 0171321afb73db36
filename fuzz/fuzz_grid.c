/* fuzz_grid.c: libFuzzer harness on a coarse grid of values. Raw bits (fuzz_isect.c) rarely
 * produce the exact coincidences where geometry is hardest: a ray exactly tangent, exactly
 * through the rim, exactly parallel, an origin exactly on the wall. Here every number is a small
 * integer times a power of two, so those coincidences are common; the input is re-encoded into
 * fuzz_isect's raw layout and checked by the same fz_one.
 *
 * Input: the same 4 header bytes, then 2 bytes per number: m (signed mantissa), k (signed
 * exponent); value = m * 2^k for |k| <= 100, special values for k = 127 (see fz_grid_value).
 *   build/fuzz/fuzz_grid -max_total_time=60 build/fuzz/work/fuzz_grid fuzz/corpus_grid
 */
#include <stddef.h>
#include <stdint.h>

#include "fuzz_check.h"
#include "fuzz_grid.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  unsigned char raw[FZ_HEADER_BYTES + FZ_NUMS * 8];
  size_t n = fz_grid_to_raw(data, size, raw, sizeof raw);
  fz_one(raw, n);
  return 0;
}
