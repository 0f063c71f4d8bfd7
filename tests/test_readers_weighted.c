/*
 * test_readers_weighted.c -- weighted points in and out (datasets/):
 * .xyzw, .xyzr and .ply with a `weight` or `radius` property read back
 * the doubles written (ascii, binary little- and big-endian), the
 * unweighted readers still read the same files, bad weights get their
 * exact status and a message naming the file and line (or byte), and the
 * weighted datasets are deterministic, finite and what they say (the
 * wuniform family from few to most hidden, by CGAL's regular
 * triangulation; wgrid's equal positions; molecule's radii).
 */
#include "testlib.h"
#include "dtdel.h"
#include "cgal/cgal_regular.h"
#include "../datasets/datasets.h"
#include "../datasets/readers.h"

#include <math.h>
#include <unistd.h>

static tl_state st;
static char dir[64];

static void path_of(char *out, size_t len, const char *file) { snprintf(out, len, "%s/%s", dir, file); }

static int write_file(const char *file, const void *data, size_t n)
{
    char p[256];
    path_of(p, sizeof p, file);
    FILE *f = fopen(p, "wb");
    if (!f) return -1;
    size_t w = fwrite(data, 1, n, f);
    return fclose(f) == 0 && w == n ? 0 : -1;
}

/* n bytes of v in byte order `big` (the host is little-endian: x86). */
static void put_ord(FILE *f, const void *v, size_t n, int big)
{
    unsigned char t[8];
    memcpy(t, v, n);
    for (size_t i = 0; big && i < n / 2; i++) {
        unsigned char x = t[i];
        t[i] = t[n - 1 - i];
        t[n - 1 - i] = x;
    }
    fwrite(t, 1, n, f);
}

/* Reads FILE weighted: status, and whether xyz and w are the ones given
 * (w NULL: expects no weights).                                          */
static void expect_read(const char *name, const char *file, const double *xyz, const double *w, uint32_t n)
{
    char p[256], msg[512] = "";
    path_of(p, sizeof p, file);
    double *gx = NULL, *gw = NULL;
    uint32_t gn = 0;
    dd_status s = dd_read_weighted(p, &gx, &gw, &gn, msg, sizeof msg);
    int ok = s == DD_OK && gn == n && memcmp(gx, xyz, 3 * (size_t)n * sizeof *xyz) == 0;
    if (ok && w) ok = gw != NULL && memcmp(gw, w, n * sizeof *w) == 0;
    if (ok && !w) ok = gw == NULL;
    tl_check(&st, ok, name, "%s: %s (%u points)", dd_status_name(s), msg, gn);
    free(gx);
    free(gw);
}

/* FILE holds `text`; reading it weighted gives status want and a message
 * holding both `where` and `what`.                                       */
static void expect_bad(const char *file, const void *text, size_t len, dd_status want, const char *where,
                       const char *what)
{
    char p[256], msg[512] = "", name[128];
    snprintf(name, sizeof name, "wreaders/bad/%s", file);
    if (write_file(file, text, len)) {
        tl_check(&st, 0, name, "cannot write");
        return;
    }
    path_of(p, sizeof p, file);
    double *xyz = NULL, *w = NULL;
    uint32_t n = 7;
    dd_status s = dd_read_weighted(p, &xyz, &w, &n, msg, sizeof msg);
    tl_check(&st, s == want && strstr(msg, where) && strstr(msg, what) && !xyz && !w && n == 0, name,
             "%s (want %s): '%s'", dd_status_name(s), dd_status_name(want), msg);
    free(xyz);
    free(w);
}

static void test_round_trip(void)
{
    const uint32_t n = 300;
    double *xyz, *w;
    uint32_t np;
    char msg[256];
    if (dd_gen_weighted("molecule", n, 3, &xyz, &w, &np, msg, sizeof msg) != DD_OK) {
        tl_check(&st, 0, "wreaders/gen", "%s", msg);
        return;
    }
    /* .xyzw and .xyzr as text */
    char p[256];
    path_of(p, sizeof p, "m.xyzw");
    FILE *f = fopen(p, "w");
    fprintf(f, "# atoms\n");
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%.17g %.17g %.17g %.17g\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], w[i]);
    fclose(f);
    expect_read("wreaders/xyzw", "m.xyzw", xyz, w, n);
    double *r = malloc(n * sizeof *r), *rw = malloc(n * sizeof *rw);
    for (uint32_t i = 0; i < n; i++) {
        r[i] = sqrt(w[i]);
        rw[i] = r[i] * r[i];
    }
    path_of(p, sizeof p, "m.xyzr");
    f = fopen(p, "w");
    for (uint32_t i = 0; i < n; i++)
        fprintf(f, "%.17g %.17g %.17g %.17g\r\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], r[i]);
    fclose(f);
    expect_read("wreaders/xyzr", "m.xyzr", xyz, rw, n);
    /* the unweighted reader reads the same files, points only */
    double *ux = NULL;
    uint32_t un = 0;
    dd_status s = dd_read_points(p, &ux, &un, msg, sizeof msg);
    tl_check(&st, s == DD_OK && un == n && !memcmp(ux, xyz, 3 * (size_t)n * sizeof *ux), "wreaders/xyzr-unweighted",
             "%s: %s", dd_status_name(s), msg);
    free(ux);
    /* .ply: ascii `weight`; binary little-endian double `radius`, a face
     * element after it; big-endian float weight among other properties */
    path_of(p, sizeof p, "a.ply");
    f = fopen(p, "w");
    fprintf(f, "ply\nformat ascii 1.0\nelement vertex %u\nproperty double x\nproperty double y\n"
               "property double weight\nproperty double z\nend_header\n", n);
    for (uint32_t i = 0; i < n; i++) fprintf(f, "%.17g %.17g %.17g %.17g\n", xyz[3 * i], xyz[3 * i + 1], w[i], xyz[3 * i + 2]);
    fclose(f);
    expect_read("wreaders/ply-ascii-weight", "a.ply", xyz, w, n);
    path_of(p, sizeof p, "le.ply");
    f = fopen(p, "wb");
    fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %u\nproperty double x\nproperty double y\n"
               "property double z\nproperty double radius\nelement face 1\nproperty list uchar int vertex_indices\n"
               "end_header\n", n);
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) put_ord(f, &xyz[3 * i + k], 8, 0);
        put_ord(f, &r[i], 8, 0);
    }
    unsigned char three = 3;
    fwrite(&three, 1, 1, f);
    for (int32_t k = 0; k < 3; k++) put_ord(f, &k, 4, 0);
    fclose(f);
    expect_read("wreaders/ply-le-radius", "le.ply", xyz, rw, n);
    float *fx = malloc(3 * n * sizeof *fx);
    double *dx = malloc(3 * n * sizeof *dx), *dw = malloc(n * sizeof *dw);
    path_of(p, sizeof p, "be.ply");
    f = fopen(p, "wb");
    fprintf(f, "ply\nformat binary_big_endian 1.0\nelement vertex %u\nproperty uchar red\nproperty float x\n"
               "property float y\nproperty float z\nproperty float weight\nend_header\n", n);
    for (uint32_t i = 0; i < n; i++) {
        unsigned char red = 7;
        fwrite(&red, 1, 1, f);
        for (int k = 0; k < 3; k++) {
            fx[3 * i + k] = (float)xyz[3 * i + k];
            dx[3 * i + k] = fx[3 * i + k];
            put_ord(f, &fx[3 * i + k], 4, 1);
        }
        float fw = (float)-w[i];             /* negative weights are fine */
        dw[i] = fw;
        put_ord(f, &fw, 4, 1);
    }
    fclose(f);
    expect_read("wreaders/ply-be-float-weight", "be.ply", dx, dw, n);
    /* a .ply and an .xyz without weights: w NULL */
    path_of(p, sizeof p, "plain.ply");
    f = fopen(p, "w");
    fprintf(f, "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
    fclose(f);
    const double tet[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    expect_read("wreaders/ply-no-weights", "plain.ply", tet, NULL, 4);
    static const char plain[] = "0 0 0 5\n1 0 0\n0 1 0\n0 0 1\n";
    write_file("plain.xyz", plain, sizeof plain - 1);
    expect_read("wreaders/xyz-no-weights", "plain.xyz", tet, NULL, 4);
    free(fx); free(dx); free(dw);
    free(r); free(rw);
    free(xyz); free(w);
}

static void test_bad(void)
{
    static const char miss[] = "0 0 0 1\n# c\n1 0 0 2\n0 1 0\n";
    expect_bad("miss.xyzw", miss, sizeof miss - 1, DD_ERR_PARSE, "miss.xyzw:4:", "missing weight");
    static const char missr[] = "0 0 0 1\n1 0 0\n";
    expect_bad("miss.xyzr", missr, sizeof missr - 1, DD_ERR_PARSE, "miss.xyzr:2:", "missing radius");
    static const char word[] = "0 0 0 heavy\n";
    expect_bad("word.xyzw", word, sizeof word - 1, DD_ERR_PARSE, "word.xyzw:1:", "missing weight");
    static const char tail[] = "0 0 0 1 2 x\n";
    expect_bad("tail.xyzw", tail, sizeof tail - 1, DD_ERR_PARSE, "tail.xyzw:1:", "expected numbers after");
    static const char nanw[] = "0 0 0 1\n1 0 0 nan\n";
    expect_bad("nan.xyzw", nanw, sizeof nanw - 1, DD_ERR_NAN, "nan.xyzw:2:", "weight is NaN");
    static const char infw[] = "0 0 0 -inf\n";
    expect_bad("inf.xyzw", infw, sizeof infw - 1, DD_ERR_INFINITE, "inf.xyzw:1:", "weight is infinite");
    static const char negr[] = "0 0 0 1\n1 0 0 1\n0 1 0 -0.5\n";
    expect_bad("neg.xyzr", negr, sizeof negr - 1, DD_ERR_PARSE, "neg.xyzr:3:", "negative radius -0.5");
    static const char bigr[] = "0 0 0 1e200\n";
    expect_bad("big.xyzr", bigr, sizeof bigr - 1, DD_ERR_INFINITE, "big.xyzr:1:", "square overflows");
    static const char nanc[] = "0 nan 0 1\n";
    expect_bad("nanc.xyzw", nanc, sizeof nanc - 1, DD_ERR_NAN, "nanc.xyzw:1:", "coordinate is NaN");
    static const char plyneg[] = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                                 "property float z\nproperty float radius\nend_header\n0 0 0 1\n1 1 1 -2\n";
    expect_bad("neg.ply", plyneg, sizeof plyneg - 1, DD_ERR_PARSE, "neg.ply:10:", "vertex 1: negative radius -2");
    static const char both[] = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nproperty float radius\nproperty float weight\nend_header\n0 0 0 1 1\n";
    expect_bad("both.ply", both, sizeof both - 1, DD_ERR_PARSE, "both.ply:3:", "both 'weight' and 'radius'");
    static const char list[] = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nproperty list uchar float weight\nend_header\n0 0 0 1 1\n";
    expect_bad("list.ply", list, sizeof list - 1, DD_ERR_PARSE, "list.ply:3:", "must be a scalar");
    /* binary: a NaN weight at its byte offset */
    char hdr[] = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                 "property double z\nproperty double weight\nend_header\n";
    unsigned char b[sizeof hdr - 1 + 64];
    memcpy(b, hdr, sizeof hdr - 1);
    double v[8] = {0, 0, 0, 1, 1, 1, 1, NAN};
    memcpy(b + sizeof hdr - 1, v, sizeof v);
    char where[64];
    snprintf(where, sizeof where, "nanw.ply: byte %zu:", sizeof hdr - 1 + 56);
    expect_bad("nanw.ply", b, sizeof b, DD_ERR_NAN, where, "vertex 1: weight is NaN");
}

/* Hidden points of CGAL's regular triangulation of a dataset. */
static size_t cgal_hidden(const double *xyz, const double *w, uint32_t n)
{
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, n, 0);
    uint32_t *h = NULL;
    size_t nh = 0;
    if (c == NULL || dd_cgal_rt_hidden(c, &h, &nh)) nh = (size_t)-1;
    free(h);
    dd_cgal_rt_free(c);
    return nh;
}

static void test_datasets(int small)
{
    const uint32_t n = small ? 500 : 3000;
    char msg[256], name[96];
    size_t hidden[3] = {0, 0, 0};
    for (size_t i = 0; dd_weighted_dataset_name(i); i++) {
        const char *ds = dd_weighted_dataset_name(i);
        double *a, *aw, *b, *bw, *c, *cw, *u;
        uint32_t na, nb, nc, nu;
        dd_status s1 = dd_gen_weighted(ds, n, 5, &a, &aw, &na, msg, sizeof msg);
        dd_status s2 = dd_gen_weighted(ds, n, 5, &b, &bw, &nb, msg, sizeof msg);
        dd_status s3 = dd_gen_weighted(ds, n, 6, &c, &cw, &nc, msg, sizeof msg);
        dd_status s4 = dd_gen(ds, n, 5, &u, &nu, msg, sizeof msg);
        int ok = s1 == DD_OK && s2 == DD_OK && s3 == DD_OK && s4 == DD_OK && na == n && nb == n && nu == n &&
                 aw && bw && dd_dataset_is_weighted(ds);
        ok = ok && !memcmp(a, b, 3 * (size_t)n * sizeof *a) && !memcmp(aw, bw, n * sizeof *aw) &&
             !memcmp(a, u, 3 * (size_t)n * sizeof *a);
        for (uint32_t k = 0; ok && k < n; k++)
            ok = isfinite(aw[k]) && isfinite(a[3 * k]) && isfinite(a[3 * k + 1]) && isfinite(a[3 * k + 2]);
        int seeded = strcmp(ds, "wmoment") && strcmp(ds, "wgrid") ? 1 : 0;
        if (ok && seeded) ok = memcmp(a, c, 3 * (size_t)n * sizeof *a) || memcmp(aw, cw, n * sizeof *aw);
        snprintf(name, sizeof name, "wdatasets/%s/deterministic", ds);
        tl_check(&st, ok, name, "%s", msg);
        if (!strcmp(ds, "molecule")) {
            int radii = 1;
            for (uint32_t k = 0; k < n; k++) radii &= aw[k] >= 1.2 * 1.2 && aw[k] <= 1.9 * 1.9;
            tl_check(&st, ok && radii, "wdatasets/molecule/radii", "a radius outside 1.2-1.9");
        }
        if (!strcmp(ds, "wgrid")) {
            int same = 0, ints = 1;
            for (uint32_t k = n - n / 8; k < n; k++)
                for (uint32_t j = 0; j < n - n / 8; j++)
                    if (!memcmp(a + 3 * k, a + 3 * j, 3 * sizeof *a)) same += aw[k] != aw[j];
            for (uint32_t k = 0; k < n; k++) ints &= aw[k] == floor(aw[k]) && aw[k] >= 0 && aw[k] <= 2;
            tl_check(&st, ok && same == (int)(n / 8) && ints, "wdatasets/wgrid/equal-positions",
                     "%d equal positions with another weight of %u", same, n / 8);
        }
        if (!strcmp(ds, "protecting")) {
            uint32_t weighted = 0;
            for (uint32_t k = 0; k < n; k++) weighted += aw[k] > 0;
            tl_check(&st, ok && weighted >= 8 && weighted <= n / 8, "wdatasets/protecting/features",
                     "%u weighted of %u", weighted, n);
        }
        for (int f = 0; f < 3; f++) {
            static const char *const fam[3] = {"wuniform-few", "wuniform", "wuniform-most"};
            if (!strcmp(ds, fam[f])) hidden[f] = cgal_hidden(a, aw, n);
        }
        free(a); free(aw); free(b); free(bw); free(c); free(cw); free(u);
    }
    tl_check(&st, hidden[0] * 50 < n && hidden[0] < hidden[1] && hidden[1] < hidden[2] && hidden[2] * 2 > n,
             "wdatasets/wuniform/few-to-most", "hidden %zu, %zu, %zu of %u", hidden[0], hidden[1], hidden[2], n);
    double *x, *w;
    uint32_t nx;
    tl_check(&st, dd_gen_weighted("uniform", 10, 1, &x, &w, &nx, msg, sizeof msg) == DD_OK && w == NULL && nx == 10,
             "wdatasets/unweighted-name", "weights for an unweighted dataset");
    free(x);
}

int main(int argc, char **argv)
{
    int small = argc > 1 && !strcmp(argv[1], "small");
    snprintf(dir, sizeof dir, "/tmp/dd-wreaders-XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_round_trip();
    test_bad();
    test_datasets(small);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "cannot remove %s\n", dir);
    return tl_finish(&st);
}
