/*
 * write.c -- dd_write: the triangulation as a mesh file that ParaView,
 * Gmsh, Medit and meshio open.  The finite cells only, the live vertices
 * numbered in input index order (0-based in .vtu, 1-based in .mesh), the
 * input index kept in .vtu as point data.  Both formats take a
 * tetrahedron (a, b, c, d) with (b - a) x (c - a) . (d - a) > 0, which is
 * our positive orientation (CGAL's orientation sign, mesh.h): cells are
 * written in their own vertex order.  Read-only.
 */
#include "dtdel.h"
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <stdio.h>
#include <stdlib.h>
#include <strings.h>

typedef enum { FMT_VTU, FMT_MESH, FMT_NONE } mesh_format;

static mesh_format format_of(const char *path)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (!dot || (slash && dot < slash)) return FMT_NONE;
    if (!strcasecmp(dot, ".vtu")) return FMT_VTU;
    if (!strcasecmp(dot, ".mesh")) return FMT_MESH;
    return FMT_NONE;
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

static void write_vtu(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t npts)
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

static void write_medit(FILE *f, const dd_tri *t, const uint32_t *number, uint32_t npts)
{
    fprintf(f, "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n%u\n", npts);
    write_points(f, t, number, " 0");
    fprintf(f, "\nTetrahedra\n%u\n", t->nfinite);
    write_cells(f, t, number, 1, " 0");
    fprintf(f, "\nEnd\n");
}

dd_status dd_write(const dd_tri *t, const char *path)
{
    const mesh_format fmt = format_of(path);
    if (fmt == FMT_NONE) return DD_ERR_UNKNOWN_FORMAT;
    uint32_t *number = dd_malloc(((size_t)t->np + 1) * sizeof *number);
    if (!number) return DD_ERR_NOMEM;
    FILE *f = fopen(path, "w");
    if (!f) {
        dd_mfree(number);
        return DD_ERR_IO;
    }
    const uint32_t npts = number_points(t, number);
    if (fmt == FMT_VTU) write_vtu(f, t, number, npts);
    else write_medit(f, t, number, npts);
    dd_mfree(number);
    const int bad = ferror(f);
    return fclose(f) != 0 || bad ? DD_ERR_IO : DD_OK;
}
