/*
 * Batch calls (crgEval...N, an extension of this library) against the classic loop of
 * single calls, on the same points, in one run: 5 passes alternating classic and batch,
 * the median rate of each and the median of the per-pass ratios.
 *
 * usage: batch_bench FILE N THREADS
 * Prints "call threads classic_q/s batch_q/s ratio" lines; BATCH_ONLY=uv2z (say)
 * measures that call alone.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>
#include "crgBaseLib.h"

#define PASSES 5
#define CHUNK 4096

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static unsigned long long g_state = 88172645463325252ULL;
static double rnd(void)
{
    g_state ^= g_state << 13;
    g_state ^= g_state >> 7;
    g_state ^= g_state << 17;
    return (g_state >> 11) * (1.0 / 9007199254740992.0);
}

static int g_id;
static long g_n;
static double *g_in1, *g_in2;

enum Call { UV2Z, UV2XY, UV2PK, XY2UV, XY2Z, XY2PK, CALLS };
static const char *kNames[CALLS] = { "uv2z", "uv2xy", "uv2pk", "xy2uv", "xy2z", "xy2pk" };

/* One pass of `call` over the points, single calls or batches; its rate. */
static double pass(enum Call call, int batch, int cp, double *o1, double *o2)
{
    double t0 = now();
    long n = g_n;
    if (batch) {
        for (long i = 0; i < n; i += CHUNK) {
            int m = (int)(n - i < CHUNK ? n - i : CHUNK);
            const double *a = g_in1 + i, *b = g_in2 + i;
            switch (call) {
            case UV2Z: crgEvaluv2zN(cp, m, a, b, o1 + i); break;
            case UV2XY: crgEvaluv2xyN(cp, m, a, b, o1 + i, o2 + i); break;
            case UV2PK: crgEvaluv2pkN(cp, m, a, b, o1 + i, o2 + i); break;
            case XY2UV: crgEvalxy2uvN(cp, m, a, b, o1 + i, o2 + i); break;
            case XY2Z: crgEvalxy2zN(cp, m, a, b, o1 + i); break;
            default: crgEvalxy2pkN(cp, m, a, b, o1 + i, o2 + i); break;
            }
        }
    } else {
        for (long i = 0; i < n; i++) {
            double a = g_in1[i], b = g_in2[i];
            switch (call) {
            case UV2Z: crgEvaluv2z(cp, a, b, o1 + i); break;
            case UV2XY: crgEvaluv2xy(cp, a, b, o1 + i, o2 + i); break;
            case UV2PK: crgEvaluv2pk(cp, a, b, o1 + i, o2 + i); break;
            case XY2UV: crgEvalxy2uv(cp, a, b, o1 + i, o2 + i); break;
            case XY2Z: crgEvalxy2z(cp, a, b, o1 + i); break;
            default: crgEvalxy2pk(cp, a, b, o1 + i, o2 + i); break;
            }
        }
    }
    return n / (now() - t0);
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v)
{
    qsort(v, PASSES, sizeof *v, cmp);
    return v[PASSES / 2];
}

struct Job { enum Call call; int batch; int cp; double rate; };
static void *worker(void *arg)
{
    struct Job *j = arg;
    double *o1 = malloc(sizeof(double) * g_n), *o2 = malloc(sizeof(double) * g_n);
    j->rate = pass(j->call, j->batch, j->cp, o1, o2);
    free(o1);
    free(o2);
    return NULL;
}

/* The summed rate of `threads` threads, each with its own contact point. */
static double threaded(enum Call call, int batch, int threads)
{
    pthread_t t[16];
    struct Job jobs[16];
    double total = 0;
    for (int k = 0; k < threads; k++)
        jobs[k] = (struct Job){ call, batch, crgContactPointCreate(g_id), 0.0 };
    for (int k = 0; k < threads; k++)
        pthread_create(&t[k], NULL, worker, &jobs[k]);
    for (int k = 0; k < threads; k++) {
        pthread_join(t[k], NULL);
        total += jobs[k].rate;
        crgContactPointDelete(jobs[k].cp);
    }
    return total;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: batch_bench FILE [N] [THREADS]\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    g_id = crgLoaderReadFile(argv[1]);
    if (g_id <= 0)
        return 1;
    crgDataSetModifiersApply(g_id);
    g_n = argc > 2 ? atol(argv[2]) : 1000000;
    int max_threads = argc > 3 ? atoi(argv[3]) : 2;
    if (max_threads < 1) max_threads = 1;
    if (max_threads > 16) max_threads = 16;
    double u0, u1, v0, v1;
    crgDataSetGetURange(g_id, &u0, &u1);
    crgDataSetGetVRange(g_id, &v0, &v1);
    double *u = malloc(sizeof(double) * g_n), *v = malloc(sizeof(double) * g_n);
    double *x = malloc(sizeof(double) * g_n), *y = malloc(sizeof(double) * g_n);
    int cp = crgContactPointCreate(g_id);
    for (long i = 0; i < g_n; i++) {
        u[i] = u0 + (u1 - u0) * rnd();
        v[i] = v0 + (v1 - v0) * rnd();
        crgEvaluv2xy(cp, u[i], v[i], &x[i], &y[i]);
    }
    printf("%-6s %7s %14s %14s %7s\n", "call", "threads", "classic q/s", "batch q/s", "ratio");
    for (int threads = 1; threads <= max_threads; threads *= 2) {
        for (int c = 0; c < CALLS; c++) {
            enum Call call = (enum Call)c;
            if (getenv("BATCH_ONLY") && strcmp(getenv("BATCH_ONLY"), kNames[c]))
                continue;
            int xy = call >= XY2UV;
            g_in1 = xy ? x : u;
            g_in2 = xy ? y : v;
            double classic[PASSES], batch[PASSES], ratio[PASSES];
            for (int p = 0; p < PASSES; p++) {
                classic[p] = threaded(call, 0, threads);
                batch[p] = threaded(call, 1, threads);
                ratio[p] = batch[p] / classic[p];
            }
            printf("%-6s %7d %14.0f %14.0f %7.2f\n", kNames[c], threads, median(classic), median(batch), median(ratio));
            fflush(stdout);
        }
    }
    crgMemRelease();
    return 0;
}
