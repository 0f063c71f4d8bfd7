/*
 * python.c -- the README's Python table: OUTDIR/python.txt (scripts/
 * pybench.py, the package against scipy.spatial.Delaunay in the same
 * run) as rows, then one note of the binding's overhead (each array
 * call's whole time from Python over its C call's) and of two threads'
 * constructions against one after the other.  Nothing without the file.
 */
#include "summarize.h"

#include <stdlib.h>
#include <string.h>

/* Seconds with three or four significant digits. */
static const char *fmt_secs(double v, char buf[40])
{
    if (v >= 100) return fmt_int((long long)(v + 0.5), buf);
    snprintf(buf, 40, v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f", v);
    return buf;
}

void readme_python(const ctx *c, FILE *out)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/python.txt", c->outdir);
    FILE *f = fopen(path, "r");
    if (!f) return;
    char *line = NULL, what[256], vers[128] = "", threads[256] = "";
    size_t cap = 0;
    int rows = 0, calls = 0;
    double ours, theirs, r, lo = 0, hi = 0, seq, par;
    long long n, ncall = 0;
    while (read_line(f, &line, &cap) == 1) {
        const char *note = strstr(line, "; scipy timed on");
        if (sscanf(line, "python: dtdel %*s scipy %127[^,]", vers) == 1) continue;
        if (sscanf(line, "python: %255[^:]: dtdel %lf s, scipy %lf s (%lfx)", what, &ours, &theirs, &r) == 4) {
            if (!rows++)
                fprintf(out, "\n| Python: `dtdel.Delaunay` against `scipy.spatial.Delaunay`%s%s | dtdel s | scipy s "
                             "| ratio |\n|---|---:|---:|---:|\n", *vers ? " " : "", vers);
            char b1[40], b2[40];
            fprintf(out, "| %s%s | %s | %s | %.*f× |\n", what, note ? " (scipy: a sample, scaled)" : "",
                    fmt_secs(ours, b1), fmt_secs(theirs, b2), r >= 100 ? 0 : 1, r);
        } else if (sscanf(line, "python overhead: %255[^:]: whole call %*f ms, C call %*f ms (%lfx)", what, &r) == 2) {
            const char *on = strstr(what, " on ");
            if (on) sscanf(on, " on %lld points", &ncall);
            lo = calls && lo < r ? lo : r;
            hi = calls && hi > r ? hi : r;
            calls++;
        } else if (sscanf(line, "python threads: two constructions of %lld points: one after the other %lf s, in two "
                                "threads %lf s", &n, &seq, &par) == 3) {
            char b[40];
            snprintf(threads, sizeof threads, " Two threads build two triangulations of %s points each %.2f× "
                     "faster than one after the other.", fmt_int(n, b), seq / par);
        }
    }
    free(line);
    fclose(f);
    if (calls || *threads) {
        fprintf(out, "\n");
        char b[40];
        if (calls)
            fprintf(out, "An array call from Python takes %.3f–%.3f× its C call's own time (%d calls on %s "
                         "points, `scripts/pybench.py`).", lo, hi, calls, fmt_int(ncall, b));
        fprintf(out, "%s\n", threads);
    }
}
