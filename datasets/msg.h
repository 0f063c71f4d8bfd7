/*
 * msg.h -- the datasets' and readers' one way to write an error message:
 * into msg (msglen bytes, terminated), or nowhere when msg is NULL.
 */
#ifndef DD_DATASETS_MSG_H
#define DD_DATASETS_MSG_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __GNUC__
__attribute__((format(printf, 3, 4)))
#endif
static inline void set_msg(char *msg, size_t msglen, const char *fmt, ...)
{
    if (msg == NULL || msglen == 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, msglen, fmt, ap);
    va_end(ap);
}

#endif
