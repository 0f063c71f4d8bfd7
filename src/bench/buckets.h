/*
 * buckets.h -- the degree buckets of the bench's tables (summarize) and of
 * its sample (dtdel bench tops up the sparse ones): one definition.
 *
 * [0,4) [4,8), then two buckets per power of two, [2^k, 1.5*2^k) and
 * [1.5*2^k, 2^(k+1)) for k >= 3, i.e.
 *   [8,12) [12,16) [16,24) [24,32) [32,48) [48,64) [64,96) [96,128)
 *   [128,192) [192,256) [256,384) [384,512) [512,768) [768,1024) ...
 * so each is a half or a third of its lower bound wide: nearly even steps
 * on the log axis, about 6.6 buckets per decade of degree, with the
 * paper's 64, 128 and 256 as boundaries.
 */
#ifndef DD_BUCKETS_H
#define DD_BUCKETS_H

/* Bucket index of a degree. */
static inline int dd_degree_bucket(long long d)
{
    if (d < 4) return 0;
    if (d < 8) return 1;
    int k = 3;
    while (k < 62 && (d >> (k + 1)) != 0) k++;     /* 2^k <= d < 2^(k+1) */
    int upper = d >= 3LL << (k - 1);
    return 2 + 2 * (k - 3) + upper;
}

/* Bucket b is the degrees [*lo, *hi). */
static inline void dd_bucket_bounds(int b, long long *lo, long long *hi)
{
    if (b == 0) { *lo = 0; *hi = 4; return; }
    if (b == 1) { *lo = 4; *hi = 8; return; }
    int k = 3 + (b - 2) / 2;
    if ((b - 2) % 2) { *lo = 3LL << (k - 1); *hi = 1LL << (k + 1); }
    else             { *lo = 1LL << k;       *hi = 3LL << (k - 1); }
}

#endif
