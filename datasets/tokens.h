/*
 * tokens.h -- the text tokens the point readers share (datasets.c's .xyz
 * and .off, readers.c's .ply and .obj): blanks, real numbers and counts,
 * in the C locale.  A token ends at white space or the end of the line;
 * each parser advances *pp past its token only when it succeeds.
 */
#ifndef DD_TOKENS_H
#define DD_TOKENS_H

#include <ctype.h>
#include <stdint.h>
#include <stdlib.h>

static inline int ends_token(char c)
{
    return c == '\0' || isspace((unsigned char)c);
}

static inline const char *skip_blank(const char *p)
{
    while (*p != '\0' && isspace((unsigned char)*p)) p++;
    return p;
}

/* One number token (strtod's syntax). */
static inline int parse_number(const char **pp, double *v)
{
    const char *p = skip_blank(*pp);
    if (*p == '\0') return 0;
    char *end;
    *v = strtod(p, &end);
    if (end == p || !ends_token(*end)) return 0;
    *pp = end;
    return 1;
}

/* One non-negative decimal integer token, with a leading '+' where
 * `plus` allows it (.ply's counts; .off's are digits only).              */
static inline int parse_count_tok(const char **pp, uint64_t *v, int plus)
{
    const char *p = skip_blank(*pp);
    if (plus && *p == '+') p++;
    if (!isdigit((unsigned char)*p)) return 0;
    uint64_t x = 0;
    for (; isdigit((unsigned char)*p); p++) {
        if (x > (UINT64_MAX - 9) / 10) return 0;
        x = 10 * x + (uint64_t)(*p - '0');
    }
    if (!ends_token(*p)) return 0;
    *v = x;
    *pp = p;
    return 1;
}

#endif
