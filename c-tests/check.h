/* A minimal assertion helper for the C tests. */
#ifndef OPENCRG_CHECK_H
#define OPENCRG_CHECK_H
#include <math.h>
#include <stdio.h>

static int g_checks, g_failures;

#define CHECK(cond)                                                                 \
    do {                                                                            \
        g_checks++;                                                                 \
        if (!(cond)) {                                                              \
            g_failures++;                                                           \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                           \
    } while (0)

#define CHECK_NEAR(a, b, tol) CHECK(fabs((a) - (b)) <= (tol))

static int check_summary(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, g_checks - g_failures, g_failures);
    return g_failures ? 1 : 0;
}
#endif
