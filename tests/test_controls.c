/*
 * test_controls.c -- dd_test_control (dtdel_stats.h) returns the value a
 * control had, for every control: those of a triangulation and the
 * process-wide one (DD_TEST_EXP_PLAIN), which takes t = NULL too.  Test
 * builds only: a release build has no controls and says so in one line.
 */
#include "testlib.h"
#include "dtdel_stats.h"

#ifdef DD_TEST_BUILD
/* Sets control ctl of t to 0 (returning v0), a, b and 0 again: each call
 * must return the value before it.  0 when one does not.               */
static int returns_previous(dd_tri *t, dd_test_ctl ctl, long v0, long a, long b, char *why, size_t nwhy)
{
    const long set[4] = {0, a, b, 0}, had[4] = {v0, 0, a, b};
    for (int k = 0; k < 4; k++) {
        long was = dd_test_control(t, ctl, set[k]);
        if (was != had[k]) {
            snprintf(why, nwhy, "setting %ld returned %ld, the value before was %ld", set[k], was, had[k]);
            return 0;
        }
    }
    return 1;
}
#endif

int main(void)
{
    tl_state st = {0, 0};
#ifdef DD_TEST_BUILD
    static const double cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    char msg[256], name[64], why[160] = "";
    dd_tri *t = NULL;
    if (dd_create(&t, &cube[0][0], 8, msg, sizeof msg) != DD_OK) {
        tl_check(&st, 0, "controls/setup", "dd_create: %s", msg);
        return tl_finish(&st);
    }
    for (int c = 0; c < DD_TEST_NCTL; c++) {
        dd_test_ctl ctl = (dd_test_ctl)c;
        snprintf(name, sizeof name, "controls/%d/returns-previous", c);
        /* values a control may take (a deletion number, a course, a
         * switch); none acts here: nothing is deleted or allocated.  The
         * allocation count starts at what dd_create left: zeroed first. */
        if (ctl == DD_TEST_ALLOC_COUNT) dd_test_control(t, ctl, 0);
        tl_check(&st, returns_previous(t, ctl, 0, 1, 2, why, sizeof why), name, "%s", why);
    }
    /* the process-wide control without a triangulation, and after a
     * value set through one                                             */
    dd_test_control(t, DD_TEST_EXP_PLAIN, 5);
    tl_check(&st, returns_previous(NULL, DD_TEST_EXP_PLAIN, 5, 1, 7, why, sizeof why), "controls/exp-plain/no-tri",
             "%s", why);
    /* the controls of a triangulation belong to it */
    dd_tri *u = NULL;
    int own = dd_create(&u, &cube[0][0], 8, msg, sizeof msg) == DD_OK;
    dd_test_control(t, DD_TEST_SCALAR, 3);
    own = own && dd_test_control(u, DD_TEST_SCALAR, 0) == 0 && dd_test_control(t, DD_TEST_SCALAR, 0) == 3;
    tl_check(&st, own, "controls/per-triangulation", "a control set on one triangulation shows on another");
    dd_free(u);
    /* the allocation controls are process-wide: no triangulation needed,
     * and a refused allocation is one of those counted                  */
    dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
    dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 3);
    int32_t *tets = NULL;
    size_t n = 0;
    dd_status s1 = dd_canonical(t, &tets, &n);   /* two allocations: not refused */
    free(tets);
    long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 1);   /* 1 left; now the next */
    dd_status s2 = dd_canonical(t, &tets, &n);   /* refused at its first */
    long after = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0), count = dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
    tl_check(&st, s1 == DD_OK && left == 1 && s2 == DD_ERR_NOMEM && after == 0 && count == 3, "controls/alloc-fail",
             "statuses %s %s, left %ld then %ld, count %ld", dd_status_name(s1), dd_status_name(s2), left, after,
             count);
    dd_free(t);
#else
    tl_check(&st, 1, "controls/release-has-none", "%s", "");
#endif
    return tl_finish(&st);
}
