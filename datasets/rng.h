/*
 * rng.h -- the generators' PRNG: xoshiro256** seeded by splitmix64
 * (Blackman & Vigna).  A generator keeps its state on its own stack, so
 * a dataset is a pure function of (name, n, seed).
 */
#ifndef DD_RNG_H
#define DD_RNG_H

#include <stdint.h>

typedef struct rng { uint64_t s[4]; } rng;

static inline uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static inline void seed_rng(rng *g, uint64_t seed)
{
    for (int i = 0; i < 4; i++) g->s[i] = splitmix64(&seed);
}

static inline uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static inline uint64_t next_u64(rng *g)
{
    uint64_t *s = g->s;
    uint64_t result = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

/* Uniform double in [0, 1) with 53 random bits. */
static inline double next_unit(rng *g)
{
    return (double)(next_u64(g) >> 11) * 0x1.0p-53;
}

/* Uniform integer in [0, k), k > 0, without modulo bias (rejection). */
static inline uint64_t next_below(rng *g, uint64_t k)
{
    uint64_t threshold = (0 - k) % k;   /* 2^64 mod k */
    for (;;) {
        uint64_t x = next_u64(g);
        if (x >= threshold) return x % k;
    }
}

#endif
