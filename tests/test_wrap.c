/*
 * test_wrap.c -- the keys of gift wrapping's facet table from 64
 * neighbours on (wrap.h, dd_wrap_code_words): the words are what wrap.h
 * says (alpha primitive, the second and third parts the cube and fifth
 * power of the first), and sets of three local numbers get distinct keys.
 * Deletions with 64 neighbours or more are checked against CGAL in
 * test_delete.c (moment, helix).
 */
#include "testlib.h"
#include "wrap/wrap.h"

#define M 21
#define MASK ((1u << M) - 1)

/* a * b in GF(2^21) modulo x^21 + x^2 + 1, bit by bit */
static uint32_t gf_mul(uint32_t a, uint32_t b)
{
    uint32_t r = 0;
    for (; b; b >>= 1) {
        if (b & 1) r ^= a;
        a <<= 1;
        if (a >> M) a ^= (1u << M) | (1u << 2) | 1u;
    }
    return r;
}

/* alpha^k for k < 2^21 - 1 are distinct: the first part of word k is
 * never 1 again before k = 2^21 - 1, and is 1 there (the order of alpha
 * is 2^21 - 1).  The parts of each word, for the first words and a
 * sample of the others: (x, x^3, x^5).                                  */
static void words_as_said(tl_state *st)
{
    enum { CHUNK = 1 << 16 };
    uint64_t *code = malloc(CHUNK * sizeof *code);
    uint32_t gf[3] = {1, 1, 1}, repeat = 0, badpow = 0, checked = 0;
    for (uint32_t from = 0; code && from < DD_WRAP_CODE_LEN; from += CHUNK) {
        uint32_t to = DD_WRAP_CODE_LEN - from < CHUNK ? DD_WRAP_CODE_LEN : from + CHUNK;
        dd_wrap_code_words(code, 0, to - from, gf);      /* words from .. to - 1: the state goes on */
        for (uint32_t k = from; k < to; k++) {
            const uint64_t w = code[k - from];
            const uint32_t x = (uint32_t)(w & MASK), x3 = (uint32_t)(w >> M & MASK), x5 = (uint32_t)(w >> 2 * M);
            if (k > 0 && x == 1) repeat++;
            if (k < 4096 || k % 997 == 0) {
                const uint32_t c3 = gf_mul(gf_mul(x, x), x);
                checked++;
                if (x3 != c3 || x5 != gf_mul(gf_mul(c3, x), x)) badpow++;
            }
        }
    }
    tl_check(st, code && repeat == 0 && gf[0] == 1, "wrap-code/alpha-primitive",
             "alpha^k = 1 for %u k in 1 .. 2^21 - 2; alpha^(2^21 - 1) = %u", repeat, gf[0]);
    tl_check(st, code && badpow == 0 && checked > 4096, "wrap-code/word-parts", "%u of %u words not (x, x^3, x^5)",
             badpow, checked);
    free(code);
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* Every set {a, b, c} of distinct numbers below n, keyed as the wrap does,
 * has a key of its own.                                                  */
static void keys_distinct(tl_state *st, uint32_t n)
{
    uint64_t *code = malloc(n * sizeof *code);
    uint32_t gf[3] = {1, 1, 1};
    size_t m = (size_t)n * (n - 1) * (n - 2) / 6, k = 0, dup = 0;
    uint64_t *keys = malloc(m * sizeof *keys);
    if (code && keys) {
        dd_wrap_code_words(code, 0, n, gf);
        for (uint32_t a = 0; a < n; a++)
            for (uint32_t b = a + 1; b < n; b++)
                for (uint32_t c = b + 1; c < n; c++) keys[k++] = code[a] ^ code[b] ^ code[c];
        qsort(keys, m, sizeof *keys, cmp_u64);
        for (size_t i = 1; i < m; i++) dup += keys[i] == keys[i - 1];
    }
    char name[64];
    snprintf(name, sizeof name, "wrap-code/keys-distinct-%u", n);
    tl_check(st, code && keys && k == m && dup == 0, name, "%zu equal keys among %zu sets", dup, m);
    free(keys);
    free(code);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    words_as_said(&st);
    keys_distinct(&st, small ? 100 : 240);
    return tl_finish(&st);
}
