/*
 * Benchmark of the classic OpenCRG C API, to be linked against any library that
 * offers it (this project's or the reference's, built with the same compiler).
 *
 * usage: crg_bench load FILE             load time and peak memory (one load per process)
 *        crg_bench eval FILE N THREADS   queries per second of every call
 * With THREADS > 1 every figure is also measured on THREADS threads at once, each
 * with a contact point of its own (figure name suffixed _<THREADS>threads).
 * CRG_BENCH_ONLY=uv2z_random,xy2z_path (say) measures only the figures named
 * ("threads" names every multi-thread figure). CRG_BENCH_PAD (default 0.2) sets how far
 * beyond the road the x/y box of the xy2uv_box figures reaches, in road sizes.
 * Prints one "name value unit" line per figure.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <math.h>
#include "crgBaseLib.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static long peak_kb(void)
{
    struct rusage r;
    getrusage(RUSAGE_SELF, &r);
    return r.ru_maxrss;
}

/* A small deterministic generator, so both libraries get the same points. */
static unsigned long long g_state = 88172645463325252ULL;
static double rnd(void)
{
    g_state ^= g_state << 13;
    g_state ^= g_state >> 7;
    g_state ^= g_state << 17;
    return (g_state >> 11) * (1.0 / 9007199254740992.0);
}

static double uMin, uMax, vMin, vMax;
static int g_id;
static long g_n;
static double *g_u, *g_v, *g_x, *g_y;
/* Each thread accumulates into its own sink, so threads share no written memory. */
static __thread double g_sink;
static volatile double g_keep;

typedef int (*Query)(int cp, long i);
static const char *g_only;
/* Whether the figure `name` is measured: CRG_BENCH_ONLY unset, or naming it in its
 * comma-separated list (the word "threads" names every multi-thread figure). */
static int wanted(const char *name)
{
    if (!g_only)
        return 1;
    size_t len = strlen(name);
    int threaded = strstr(name, "threads") != NULL;
    for (const char *p = g_only; *p;) {
        size_t n = strcspn(p, ",");
        if ((n == len && !strncmp(p, name, n)) || (threaded && n == 7 && !strncmp(p, "threads", 7)))
            return 1;
        p += n + (p[n] == ',');
    }
    return 0;
}

static int q_uv2z(int cp, long i) { double z; int r = crgEvaluv2z(cp, g_u[i], g_v[i], &z); g_sink += z; return r; }
static int q_uv2pk(int cp, long i) { double p, k; int r = crgEvaluv2pk(cp, g_u[i], g_v[i], &p, &k); g_sink += p + k; return r; }
static int q_uv2xy(int cp, long i) { double x, y; int r = crgEvaluv2xy(cp, g_u[i], g_v[i], &x, &y); g_sink += x + y; return r; }
static int q_xy2uv(int cp, long i) { double u, v; int r = crgEvalxy2uv(cp, g_x[i], g_y[i], &u, &v); g_sink += u + v; return r; }
static int q_xy2z(int cp, long i) { double z; int r = crgEvalxy2z(cp, g_x[i], g_y[i], &z); g_sink += z; return r; }

/* Best of three passes: this machine's timing noise only ever slows a pass down. */
static double run(Query q, int cp, long n)
{
    double best = 0.0;
    for (int pass = 0; pass < 3; pass++) {
        double t0 = now();
        for (long i = 0; i < n; i++)
            q(cp, i);
        double qps = n / (now() - t0);
        if (qps > best)
            best = qps;
    }
    g_keep = g_sink;
    return best;
}

struct Job { Query q; int cp; long n; double qps; };
static void *thread_main(void *arg)
{
    struct Job *j = arg;
    j->qps = run(j->q, j->cp, j->n);
    return NULL;
}

/* The sum of the rates of `threads` threads, each with a contact point of its own
 * (all created before any thread starts; history < 0 keeps the default history). */
static double run_threads(Query q, long n, int threads, int history)
{
    pthread_t t[64];
    struct Job jobs[64];
    double total = 0;
    for (int k = 0; k < threads; k++) {
        jobs[k] = (struct Job){ q, crgContactPointCreate(g_id), n, 0.0 };
        if (history >= 0)
            crgContactPointSetHistory(jobs[k].cp, history);
    }
    for (int k = 0; k < threads; k++)
        pthread_create(&t[k], NULL, thread_main, &jobs[k]);
    for (int k = 0; k < threads; k++) {
        pthread_join(t[k], NULL);
        total += jobs[k].qps;
    }
    for (int k = 0; k < threads; k++)
        crgContactPointDelete(jobs[k].cp);
    return total;
}

/* Prints the figure `name`: one thread on `cp`, then (with threads > 1) the same
 * queries on `threads` threads at once. */
static void measure(const char *name, Query q, int cp, long n, int threads, int history)
{
    char threaded[96];
    snprintf(threaded, sizeof threaded, "%s_%dthreads", name, threads);
    if (wanted(name))
        printf("%s %.0f q/s\n", name, run(q, cp, n));
    if (threads > 1 && wanted(threaded))
        printf("%s %.0f q/s\n", threaded, run_threads(q, n, threads, history));
    fflush(stdout);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: crg_bench load FILE | eval FILE N THREADS\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    g_only = getenv("CRG_BENCH_ONLY");
    long before = peak_kb();
    double t0 = now();
    g_id = crgLoaderReadFile(argv[2]);
    if (g_id <= 0) {
        fprintf(stderr, "cannot load %s\n", argv[2]);
        return 1;
    }
    crgDataSetModifiersApply(g_id);
    double t_load = now() - t0;
    if (!strcmp(argv[1], "load")) {
        printf("load_s %.3f s\npeak_rss_mb %.1f MB\nrss_before_mb %.1f MB\n", t_load, peak_kb() / 1024.0, before / 1024.0);
        return 0;
    }
    g_n = argc > 3 ? atol(argv[3]) : 1000000;
    int threads = argc > 4 ? atoi(argv[4]) : 1;
    if (threads < 1) threads = 1;
    if (threads > 64) threads = 64;
    crgDataSetGetURange(g_id, &uMin, &uMax);
    crgDataSetGetVRange(g_id, &vMin, &vMax);
    g_u = malloc(sizeof(double) * g_n); g_v = malloc(sizeof(double) * g_n);
    g_x = malloc(sizeof(double) * g_n); g_y = malloc(sizeof(double) * g_n);
    int cp = crgContactPointCreate(g_id);
    for (long i = 0; i < g_n; i++) {
        g_u[i] = uMin + (uMax - uMin) * rnd();
        g_v[i] = vMin + (vMax - vMin) * rnd();
        crgEvaluv2xy(cp, g_u[i], g_v[i], &g_x[i], &g_y[i]);
    }
    measure("uv2z_random", q_uv2z, cp, g_n, threads, -1);
    measure("uv2pk_random", q_uv2pk, cp, g_n, threads, -1);
    measure("uv2xy_random", q_uv2xy, cp, g_n, threads, -1);
    /* x/y to u/v on random points with no history: every query searches afresh */
    int cp0 = crgContactPointCreate(g_id);
    crgContactPointSetHistory(cp0, 0);
    measure("xy2uv_random_nohistory", q_xy2uv, cp0, g_n / 100, threads, 0);
    /* x/y anywhere in the road's bounding box grown by a fifth on every side (points
     * off the road and far from the reference line too), no history */
    {
        double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
        for (long i = 0; i < g_n; i++) {
            xmin = fmin(xmin, g_x[i]); xmax = fmax(xmax, g_x[i]);
            ymin = fmin(ymin, g_y[i]); ymax = fmax(ymax, g_y[i]);
        }
        double w = xmax - xmin, h = ymax - ymin, pad = (getenv("CRG_BENCH_PAD") ? atof(getenv("CRG_BENCH_PAD")) : 0.2) * fmax(w, h);
        for (long i = 0; i < g_n; i++) {
            g_x[i] = xmin - pad + (w + 2 * pad) * rnd();
            g_y[i] = ymin - pad + (h + 2 * pad) * rnd();
        }
        measure("xy2uv_box_nohistory", q_xy2uv, cp0, g_n / 100, threads, 0);
        /* the same with the default history (50 entries), as a client that never sets it */
        int cph = crgContactPointCreate(g_id);
        measure("xy2uv_box_defaulthistory", q_xy2uv, cph, g_n / 100, threads, -1);
    }
    /* a vehicle path: u increasing, v weaving, x/y looked up with history */
    for (long i = 0; i < g_n; i++) {
        double u = uMin + (uMax - uMin) * i / g_n, v = 0.4 * (vMax - vMin) * sin(i * 1e-3);
        crgEvaluv2xy(cp, u, v, &g_x[i], &g_y[i]);
    }
    measure("xy2z_path", q_xy2z, cp, g_n, threads, -1);
    crgMemRelease();
    return 0;
}
