/* Contact points used from several threads at once (the reference library cannot
 * do this), and several threads loading roads at once: results must equal a
 * single-threaded run. usage: test_threads ROAD.crg */
#include <pthread.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#include "crgBaseLib.h"
#include "check.h"

#define THREADS 8
#define QUERIES 4000

static const char *g_road;
static int g_dataset;
static double g_expected[QUERIES][5];

/* The same queries every time: a wavy path along the road, x/y taken from u/v. */
static void run_queries(int cp, double out[QUERIES][5])
{
    for (int i = 0; i < QUERIES; i++) {
        double u = 120.0 * i / QUERIES, v = 2.5 * sin(i * 0.01), x, y, z, u2, v2, z2;
        crgEvaluv2xy(cp, u, v, &x, &y);
        crgEvaluv2z(cp, u, v, &z);
        crgEvalxy2uv(cp, x, y, &u2, &v2);
        crgEvalxy2z(cp, x, y, &z2);
        out[i][0] = x; out[i][1] = y; out[i][2] = z; out[i][3] = u2; out[i][4] = z2;
    }
}

static void *evaluate(void *arg)
{
    double (*out)[5] = malloc(sizeof(double) * QUERIES * 5);
    int cp = crgContactPointCreate(g_dataset), *ok = arg;
    *ok = cp >= 0 && out;
    for (int round = 0; round < 5 && *ok; round++) {
        run_queries(cp, out);
        *ok = memcmp(out, g_expected, sizeof g_expected) == 0;
    }
    crgContactPointDelete(cp);
    free(out);
    return NULL;
}

/* Threads taking turns on one contact point: each call must see the contact point
 * whole, whichever thread used it last. */
static int g_shared_cp;
static void *share(void *arg)
{
    int *ok = arg;
    *ok = 1;
    for (int i = 0; i < 20000 && *ok; i++) {
        int k = i % QUERIES;
        double u = 120.0 * k / QUERIES, v = 2.5 * sin(k * 0.01), z;
        *ok = crgEvaluv2z(g_shared_cp, u, v, &z) == 1 && z == g_expected[k][2];
        if (i % 50 == 0)
            sched_yield();
    }
    return NULL;
}

static void *load_and_evaluate(void *arg)
{
    int *ok = arg, id = crgLoaderReadFile(g_road), cp;
    double (*out)[5] = malloc(sizeof(double) * QUERIES * 5);
    *ok = id > 0 && out;
    if (*ok) {
        crgDataSetModifiersApply(id);
        cp = crgContactPointCreate(id);
        run_queries(cp, out);
        *ok = memcmp(out, g_expected, sizeof g_expected) == 0;
        crgDataSetRelease(id);
    }
    free(out);
    return NULL;
}

int main(int argc, char **argv)
{
    pthread_t threads[THREADS];
    int ok[THREADS], cp, i;

    g_road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    crgMsgSetLevel(dCrgMsgLevelWarn);
    g_dataset = crgLoaderReadFile(g_road);
    CHECK(g_dataset > 0);
    crgDataSetModifiersApply(g_dataset);
    cp = crgContactPointCreate(g_dataset);
    run_queries(cp, g_expected);
    crgContactPointDelete(cp);

    for (i = 0; i < THREADS; i++)
        CHECK(pthread_create(&threads[i], NULL, evaluate, &ok[i]) == 0);
    for (i = 0; i < THREADS; i++) {
        pthread_join(threads[i], NULL);
        CHECK(ok[i]);
    }
    g_shared_cp = crgContactPointCreate(g_dataset);
    for (i = 0; i < THREADS; i++)
        CHECK(pthread_create(&threads[i], NULL, share, &ok[i]) == 0);
    for (i = 0; i < THREADS; i++) {
        pthread_join(threads[i], NULL);
        CHECK(ok[i]);
    }
    CHECK(crgContactPointDelete(g_shared_cp) == 1);
    for (i = 0; i < THREADS; i++)
        CHECK(pthread_create(&threads[i], NULL, load_and_evaluate, &ok[i]) == 0);
    for (i = 0; i < THREADS; i++) {
        pthread_join(threads[i], NULL);
        CHECK(ok[i]);
    }
    crgMemRelease();
    return check_summary("test_threads");
}
