/* fuzz_isect.c: libFuzzer harness for cylinder_isect.h. Every input goes through fz_one
 * (fuzz_check.h): the first bytes pick precision, function, NULL pointers and option bits, the
 * rest becomes the numbers bit for bit; any broken invariant aborts, and libFuzzer keeps the
 * input.
 *
 *   make fuzz                       each harness for FUZZ_SECONDS (default 60)
 *   build/fuzz/fuzz_isect -max_total_time=60 build/fuzz/work/fuzz_isect fuzz/corpus
 *   build/fuzz/fuzz_isect crash-<sha1>     replay one input
 */
#include <stddef.h>
#include <stdint.h>

#include "fuzz_check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  fz_one(data, size);
  return 0;
}
