/*
 * fuzz_ops.c -- libFuzzer driver of the operation interpreter (`make
 * fuzz`): create / delete / insert / move / delete_set / reinsert on
 * integer grid points, the grid scaled to the ends of the double range,
 * and any finite doubles, unweighted or (inputs starting with 'W')
 * weighted in both hidden modes with move_weighted too, each step
 * validated and compared with a build from scratch.  The entry point is in fuzz_entry.h, which test_fuzz_replay.c
 * replays in `make test`.
 */
#include "fuzz_entry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t n);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t n)
{
    if (dd_fuzz_ops(data, n)) abort();
    return 0;
}
