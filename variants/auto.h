/*
 * auto.h -- what gift_wrap.c borrows from auto.c: its course with the
 * wide guess's degree bound as a parameter.
 */
#ifndef DD_AUTO_H
#define DD_AUTO_H

#include "delete/delete.h"

/* Gift wrapping (wrap.h; wide_below as in dd_wrap_fill), or where it
 * declines, auto's conflict DT: below degree 40 the compact one,
 * nearest neighbours first; from 40 on, GRR with the link vertex of
 * least degree deleted first (grr-neighbor's guides).  On a weighted
 * t (fill_weighted) the same courses, the star's hidden points among
 * the sites.                                                          */
dd_status dd_auto_wrap_first(dd_del *d, uint32_t wide_below);

#endif
