/*
 * test_fuzz_replay.c -- every file of the fuzz corpus (tests/fuzz-corpus/
 * readers/ and ops/: the seeds, and each crash `make fuzz` found, kept as
 * a regression test) through the fuzz targets' own entry points
 * (tests/fuzz/fuzz_entry.h), in the normal and the sanitizer builds.
 * One ok/FAIL line per file.  Run from the repository's top directory
 * (as make test does), or with DD_FUZZ_CORPUS naming the corpus.
 */
#include "testlib.h"
#include "fuzz/fuzz_entry.h"

#include <dirent.h>

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Replays every regular file of dir through fn; returns how many. */
static int replay(tl_state *st, const char *root, const char *target, int (*fn)(const uint8_t *, size_t))
{
    char dir[512];
    snprintf(dir, sizeof dir, "%s/%s", root, target);
    DIR *d = opendir(dir);
    if (!d) {
        tl_check(st, 0, target, "cannot open the corpus %s", dir);
        return 0;
    }
    char *names[4096];
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL && n < 4096;)
        if (e->d_name[0] != '.') names[n++] = strdup(e->d_name);
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmp_names);
    for (int i = 0; i < n; i++) {
        char path[1024], name[600];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        snprintf(name, sizeof name, "fuzz-replay/%s/%s", target, names[i]);
        FILE *f = fopen(path, "rb");
        uint8_t *buf = NULL;
        size_t len = 0, cap = 0;
        if (f) {
            for (;;) {
                if (len == cap) {
                    cap = cap ? 2 * cap : 4096;
                    uint8_t *b = realloc(buf, cap);
                    if (!b) break;
                    buf = b;
                }
                size_t r = fread(buf + len, 1, cap - len, f);
                if (r == 0) break;
                len += r;
            }
            fclose(f);
        }
        tl_check(st, f && fn(buf ? buf : (const uint8_t *)"", len) == 0, name, "%s (see stderr)",
                 f ? "the entry point found a bug" : "cannot read the file");
        free(buf);
        free(names[i]);
    }
    return n;
}

int main(void)
{
    tl_state st = {0, 0};
    const char *root = getenv("DD_FUZZ_CORPUS");
    if (!root || !*root) root = "tests/fuzz-corpus";
    int a = replay(&st, root, "readers", dd_fuzz_readers);
    int b = replay(&st, root, "ops", dd_fuzz_ops);
    tl_check(&st, a >= 8 && b >= 8, "fuzz-replay/corpus-present", "%d reader and %d op inputs in %s", a, b, root);
    return tl_finish(&st);
}
