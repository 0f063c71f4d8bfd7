/*
 * fuzz_readers.c -- libFuzzer driver of the point-file readers (`make
 * fuzz`); the entry point is in fuzz_entry.h, which test_fuzz_replay.c
 * replays in `make test`.
 */
#include "fuzz_entry.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t n);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t n)
{
    if (dd_fuzz_readers(data, n)) abort();
    return 0;
}
