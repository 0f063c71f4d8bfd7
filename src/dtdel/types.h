/*
 * dtdel/types.h -- the types the public header (dtdel.h) shares with every
 * layer of the engine: the status every call returns, and the opaque
 * triangulation.  Part of the public interface: dtdel.h includes it, and
 * it is installed beside dtdel.h as dtdel/types.h.  Users include dtdel.h,
 * not this.  The engine includes this instead of dtdel.h, so that no
 * layer below the API includes the API's header (docs/architecture.md).
 */
#ifndef DTDEL_TYPES_H
#define DTDEL_TYPES_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum dd_status {
    DD_OK = 0,
    DD_ERR_NOMEM,          /* out of memory                                  */
    DD_ERR_IO,             /* a file cannot be opened or read                */
    DD_ERR_PARSE,          /* a malformed line or header in an input file    */
    DD_ERR_NAN,            /* a coordinate is NaN                            */
    DD_ERR_INFINITE,       /* a coordinate is +inf or -inf                   */
    DD_ERR_TOO_FEW,        /* fewer than 4 distinct points                   */
    DD_ERR_COLLINEAR,      /* all points on one line                         */
    DD_ERR_COPLANAR,       /* all points in one plane                        */
    DD_ERR_UNKNOWN_VERTEX, /* the index names no vertex of the triangulation */
    DD_ERR_UNKNOWN_VARIANT,/* no deletion strategy has that name             */
    DD_ERR_DUPLICATE,      /* an inserted point equals an existing vertex    */
    DD_ERR_DIMENSION,      /* deletion would leave fewer than 4 or only
                              coplanar points (dimension drop unsupported)   */
    DD_ERR_INTERNAL,       /* an invariant broke: a bug, please report it    */
    DD_ERR_ARG,            /* a bad argument: unknown flag bits, an index
                              listed twice in a set                         */
    DD_ERR_UNSUPPORTED,    /* a feature not supported yet (weights)         */
    DD_ERR_UNKNOWN_CELL,   /* the id names no live cell (dd_cell_alive)      */
    DD_ERR_UNKNOWN_FORMAT, /* a file name's extension names no format we write */
    DD_NUM_STATUS
} dd_status;

/* A triangulation (defined in src/mesh/mesh.h; opaque to users). */
typedef struct dd_tri dd_tri;

#ifdef __cplusplus
}
#endif
#endif
