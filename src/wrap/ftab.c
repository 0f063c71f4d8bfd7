/*
 * ftab.c -- the facet table of the gift wrap (docs/gift-wrap.md §11): an
 * oriented triangle of local numbers -> its facet record, and the keys
 * that name a triangle by the set of its corners.
 *
 * Owns: the table (open addressing, linear probing, emptied in O(1) by
 * generation stamps), its growth, and the keys' words: bit k below 64
 * local numbers, from 64 on the BCH code words of dd_wrap_code_words,
 * made once and kept across deletions.  The probes are inline in
 * wrap_int.h (w_fkey, w_fprobe, w_fslot_of, w_reserve_recs).
 *
 * Invariant: the table is at most a quarter full and every record has its
 * entry (it grows with the records and takes them again); two distinct
 * sets of three local numbers below DD_WRAP_CODE_LEN have distinct keys
 * (wrap.h).  A key is the exclusive or of the corners' words: symmetric,
 * so no sorting of the corners and one 64-bit compare a probe.  The
 * facet of a cell opposite vertex j has the cell's four words with word
 * j xored out again (w_close_or_open, run.c).
 */
#include "wrap/wrap_int.h"

#define W_CODE_M 21
#define W_CODE_POLY ((1u << W_CODE_M) | (1u << 2) | 1u)   /* x^21 + x^2 + 1 */
_Static_assert(DD_WRAP_CODE_LEN == (1u << W_CODE_M) - 1, "wrap: the code's length");

/* x times alpha^times in GF(2^21): shift, and reduce by x^21 + x^2 + 1. */
static inline uint32_t w_gf_times_alpha(uint32_t x, int times)
{
    for (int i = 0; i < times; i++) {
        x <<= 1;
        if (x >> W_CODE_M) x ^= W_CODE_POLY;
    }
    return x;
}

/* Word k (see wrap.h) is (alpha^k, alpha^3k, alpha^5k), 21 bits each,
 * alpha a root of x^21 + x^2 + 1 in GF(2^21); gf holds alpha^from,
 * alpha^3from, alpha^5from ({1, 1, 1} for from = 0), and then those of
 * count.                                                                */
void dd_wrap_code_words(uint64_t *code, uint32_t from, uint32_t count, uint32_t gf[3])
{
    for (uint32_t k = from; k < count; k++) {
        code[k] = (uint64_t)gf[0] | (uint64_t)gf[1] << W_CODE_M | (uint64_t)gf[2] << (2 * W_CODE_M);
        gf[0] = w_gf_times_alpha(gf[0], 1);
        gf[1] = w_gf_times_alpha(gf[1], 3);
        gf[2] = w_gf_times_alpha(gf[2], 5);
    }
}

/* The code words of local numbers below count (< DD_WRAP_CODE_LEN), made
 * once: the wrap keeps them for the next deletions.  O(count) the first
 * time, O(1) after.                                                     */
dd_status w_code_reserve(struct dd_wrap *w, uint32_t count)
{
    if (count <= w->ncode) return DD_OK;
    if (dd_grow(&w->code, count, sizeof *w->code)) return DD_ERR_NOMEM;
    if (w->ncode == 0) w->gf[0] = w->gf[1] = w->gf[2] = 1;
    dd_wrap_code_words(w->code, w->ncode, count, w->gf);
    w->ncode = count;
    return DD_OK;
}

/* The words below 64 neighbours: bit k. */
static const uint64_t w_bit_words[64] = {
#define W_B4(k) 1ull << (k), 1ull << ((k) + 1), 1ull << ((k) + 2), 1ull << ((k) + 3)
#define W_B16(k) W_B4(k), W_B4((k) + 4), W_B4((k) + 8), W_B4((k) + 12)
    W_B16(0), W_B16(16), W_B16(32), W_B16(48)
#undef W_B16
#undef W_B4
};

/* Empties the table, sized for about `expect` records at most a quarter
 * full (a probe then nearly always stops at its first slot: the exit of
 * its loop is a branch no processor predicts), and picks the keys' words
 * for this cavity's n + 1 local numbers.  O(1) but for a larger table.  */
dd_status w_ftab_reset(struct dd_wrap *w, size_t expect)
{
    void *fs = w->fs;
    dd_status s = dd_gen_table_reset(&fs, &w->fs_alloc, &w->fs_gen, &w->fs_mask, 4 * expect, sizeof *w->fs);
    w->fs = fs;
    w->fs_shift = 64u - (uint32_t)__builtin_popcount(w->fs_mask);
    w->kword = w->n < 64 ? w_bit_words : w->code;   /* made for n + 1 (dd_wrap_fill) */
    return s;
}

/* Grows the table fourfold (w_ftab_reset sizes it for 4 (mask + 1)
 * records at a quarter full) and enters the records again:
 * O(records).                                                           */
static dd_status w_ftab_grow(struct dd_wrap *w)
{
    dd_status s = w_ftab_reset(w, w->fs_mask + 1);
    for (uint32_t r = 0; s == DD_OK && r < w->nrec; r++) {
        uint64_t k = w_fkey(w, w->tri[r][0], w->tri[r][1], w->tri[r][2]);
        *w_fprobe(w, k) = (struct w_fslot){k, r, w->fs_gen};
    }
    return s;
}

/* Room for `more` more records: the record arrays doubled as needed,
 * then the table grown until it is at most a quarter full, as
 * w_reserve_recs requires.                                             */
dd_status w_grow_recs(struct dd_wrap *w, size_t more)
{
    if (w->nrec + more > w->cap_rec) {
        uint32_t cap = w->cap_rec ? w->cap_rec : 256;
        while (cap < w->nrec + more) cap *= 2;
        if (dd_grow(&w->tri, cap, sizeof *w->tri) || dd_grow(&w->own, cap, sizeof *w->own) ||
            dd_grow(&w->out, cap, sizeof *w->out) || dd_grow(&w->closed, cap, sizeof *w->closed) ||
            dd_grow(&w->stack, cap, sizeof *w->stack))
            return DD_ERR_NOMEM;
        w->cap_rec = cap;
    }
    dd_status s = DD_OK;
    while (s == DD_OK && 4 * (w->nrec + more) > w->fs_mask + 1) s = w_ftab_grow(w);
    return s;
}
