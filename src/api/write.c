/*
 * write.c -- dd_write: the triangulation as a mesh file that ParaView,
 * Gmsh, Medit and meshio open.  The finite cells only, the live vertices
 * numbered in input index order (0-based in .vtu, 1-based in .mesh), the
 * input index kept in .vtu as point data.  Both formats take a
 * tetrahedron (a, b, c, d) with (b - a) x (c - a) . (d - a) > 0, which is
 * our positive orientation (CGAL's orientation sign, mesh.h): cells are
 * written in their own vertex order.  Read-only.
 *
 * A .vtu is binary unless asked for ASCII (DD_WRITE_ASCII, or a name
 * ending in .ascii.vtu): VTK's appended raw data, a UInt64 byte count
 * before each array, in the machine's byte order, which the header names.
 * The integer arrays are Int32 when every value fits, else Int64; points
 * are Float64, their bits as they are.  Every allocation comes before the
 * file is opened, so DD_ERR_NOMEM leaves no file.
 */
#include "dtdel.h"
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

typedef enum { FMT_VTU, FMT_VTU_ASCII, FMT_MESH, FMT_NONE } mesh_format;

static mesh_format format_of(const char *path)
{
    static const char ascii[] = ".ascii.vtu";
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return FMT_NONE;
    if (!strcasecmp(dot, ".mesh")) return FMT_MESH;
    if (strcasecmp(dot, ".vtu")) return FMT_NONE;
    const char *name = slash ? slash + 1 : path;
    const size_t len = strlen(name), la = sizeof ascii - 1;
    return len > la && !strcasecmp(name + len - la, ascii) ? FMT_VTU_ASCII : FMT_VTU;
}

/* number[i] for each input index i that is a vertex: its point's
 * position in the file (input index order); returns how many.          */
static uint32_t number_points(const dd_tri *t, uint32_t *number)
{
    uint32_t k = 0;
    for (uint32_t i = 0; i < t->np; i++) {
        const uint32_t v = t->in2v[i];
        number[i] = t->v2in[v] == i && t->vcell[v] != DD_NONE ? k++ : UINT32_MAX;
    }
    return k;
}

/* The points (x y z, then " 0" in .mesh), in input index order. */
static void write_points(FILE *f, const dd_tri *t, const uint32_t *number, const char *tail)
{
    for (uint32_t i = 0; i < t->np; i++) {
        if (number[i] == UINT32_MAX) continue;
        const double *x = dd_pt(t, t->in2v[i]);
        fprintf(f, "%.17g %.17g %.17g%s\n", x[0], x[1], x[2], tail);
    }
}

/* The finite cells, as point numbers plus `base`, then tail. */
static void write_cells(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t base, const char *tail)
{
    for (uint32_t c = 0; c < t->ncell; c++) {
        const uint32_t *v = dd_tv(t, c);
        if (v[0] == DD_DEAD || dd_is_infinite_cell(t, c)) continue;
        fprintf(f, "%u %u %u %u%s\n", number[t->v2in[v[0]]] + base, number[t->v2in[v[1]]] + base,
                number[t->v2in[v[2]]] + base, number[t->v2in[v[3]]] + base, tail);
    }
}

/* The .vtu with ASCII data arrays. */
static void write_vtu_ascii(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t npts)
{
    const size_t ncells = t->nfinite;
    fprintf(f, "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%u\" NumberOfCells=\"%zu\">\n"
               "<PointData Scalars=\"input_index\">\n"
               "<DataArray type=\"Int32\" Name=\"input_index\" format=\"ascii\">\n",
            npts, ncells);
    for (uint32_t i = 0; i < t->np; i++)
        if (number[i] != UINT32_MAX) fprintf(f, "%u\n", i);
    fprintf(f, "</DataArray>\n</PointData>\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    write_points(f, t, number, "");
    fprintf(f, "</DataArray>\n</Points>\n<Cells>\n"
               "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    write_cells(f, t, number, 0, "");
    fprintf(f, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (size_t k = 1; k <= ncells; k++) fprintf(f, "%zu\n", 4 * k);
    fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (size_t k = 0; k < ncells; k++) fputs("10\n", f);             /* VTK_TETRA */
    fprintf(f, "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

/* ---- binary .vtu: appended raw data --------------------------------------- */

/* Bytes on their way to the file, in blocks of sizeof b. */
typedef struct {
    FILE *f;
    size_t n;
    unsigned char b[1 << 14];
} sink;

static void drain(sink *s)
{
    if (s->n) fwrite(s->b, 1, s->n, s->f);
    s->n = 0;
}

static void put(sink *s, const void *p, size_t len)
{
    if (s->n + len > sizeof s->b) drain(s);
    memcpy(s->b + s->n, p, len);
    s->n += len;
}

/* An integer as `width` bytes (4 or 8), in the machine's byte order. */
static void put_int(sink *s, uint64_t v, size_t width)
{
    if (width == 8) {
        put(s, &v, 8);
    } else {
        const uint32_t w = (uint32_t)v;
        put(s, &w, 4);
    }
}

/* The .vtu with appended raw data: input_index, points, connectivity,
 * offsets, types, each after its UInt64 byte count.                    */
static void write_vtu_binary(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t npts)
{
    const uint64_t ncells = t->nfinite;
    const uint16_t one = 1;
    const int little = *(const unsigned char *)&one == 1;
    const size_t w = t->np <= (uint32_t)INT32_MAX && 4 * ncells <= INT32_MAX ? 4 : 8;
    const char *it = w == 4 ? "Int32" : "Int64";
    const uint64_t bytes[5] = {w * npts, 24 * (uint64_t)npts, 4 * w * ncells, w * ncells, ncells};
    uint64_t at[5];
    for (int k = 0; k < 5; k++) at[k] = k ? at[k - 1] + 8 + bytes[k - 1] : 0;       /* byte offsets */
    fprintf(f, "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%u\" NumberOfCells=\"%llu\">\n"
               "<PointData Scalars=\"input_index\">\n"
               "<DataArray type=\"%s\" Name=\"input_index\" format=\"appended\" offset=\"%llu\"/>\n"
               "</PointData>\n<Points>\n"
               "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" offset=\"%llu\"/>\n"
               "</Points>\n<Cells>\n"
               "<DataArray type=\"%s\" Name=\"connectivity\" format=\"appended\" offset=\"%llu\"/>\n"
               "<DataArray type=\"%s\" Name=\"offsets\" format=\"appended\" offset=\"%llu\"/>\n"
               "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"%llu\"/>\n"
               "</Cells>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_",
            little ? "LittleEndian" : "BigEndian", npts, (unsigned long long)ncells, it,
            (unsigned long long)at[0], (unsigned long long)at[1], it, (unsigned long long)at[2], it,
            (unsigned long long)at[3], (unsigned long long)at[4]);
    sink s = {.f = f, .n = 0};
    put(&s, &bytes[0], 8);
    for (uint32_t i = 0; i < t->np; i++)
        if (number[i] != UINT32_MAX) put_int(&s, i, w);
    put(&s, &bytes[1], 8);
    for (uint32_t i = 0; i < t->np; i++)
        if (number[i] != UINT32_MAX) put(&s, dd_pt(t, t->in2v[i]), 24);
    put(&s, &bytes[2], 8);
    for (uint32_t c = 0; c < t->ncell; c++) {
        const uint32_t *v = dd_tv(t, c);
        if (v[0] == DD_DEAD || dd_is_infinite_cell(t, c)) continue;
        for (int k = 0; k < 4; k++) put_int(&s, number[t->v2in[v[k]]], w);
    }
    put(&s, &bytes[3], 8);
    for (uint64_t k = 1; k <= ncells; k++) put_int(&s, 4 * k, w);
    put(&s, &bytes[4], 8);
    for (uint64_t k = 0; k < ncells; k++) {
        const unsigned char tetra = 10;                                  /* VTK_TETRA */
        put(&s, &tetra, 1);
    }
    drain(&s);
    fputs("\n</AppendedData>\n</VTKFile>\n", f);
}

static void write_medit(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t npts)
{
    fprintf(f, "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n%u\n", npts);
    write_points(f, t, number, " 0");
    fprintf(f, "\nTetrahedra\n%u\n", t->nfinite);
    write_cells(f, t, number, 1, " 0");
    fprintf(f, "\nEnd\n");
}

dd_status dd_write_ex(const dd_tri *t, const char *path, unsigned flags)
{
    mesh_format fmt = format_of(path);
    if (fmt == FMT_NONE) return DD_ERR_UNKNOWN_FORMAT;
    if (flags & ~(unsigned)DD_WRITE_ASCII) return DD_ERR_ARG;
    if (fmt == FMT_VTU && (flags & DD_WRITE_ASCII)) fmt = FMT_VTU_ASCII;
    uint32_t *number = dd_malloc(((size_t)t->np + 1) * sizeof *number);
    if (!number) return DD_ERR_NOMEM;
    FILE *f = fopen(path, "w");
    if (!f) {
        dd_mfree(number);
        return DD_ERR_IO;
    }
    const uint32_t npts = number_points(t, number);
    if (fmt == FMT_VTU) write_vtu_binary(f, t, number, npts);
    else if (fmt == FMT_VTU_ASCII) write_vtu_ascii(f, t, number, npts);
    else write_medit(f, t, number, npts);
    dd_mfree(number);
    const int bad = ferror(f);
    return fclose(f) != 0 || bad ? DD_ERR_IO : DD_OK;
}

dd_status dd_write(const dd_tri *t, const char *path)
{
    return dd_write_ex(t, path, 0);
}
