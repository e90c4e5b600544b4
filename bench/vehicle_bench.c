/*
 * The vehicle's workload: a car of four wheels driving along a road at 1 kHz, every
 * wheel's contact point looked up at every step through the classic OpenCRG C API, as
 * a vehicle or tire model calls it. Links against any library offering that API (this
 * project's or the reference's, built with the same compiler).
 *
 * usage: vehicle_bench FILE [STEPS]
 *
 * The car is that of car.h: a compact car weaving along the reference line, its
 * wheels' x/y from crgEvaluv2xy. Every pass drives a stretch
 * of road no earlier pass drove (the odometer runs on across passes and cases), after
 * 64 MB were read to push the road out of the caches: each wheel meets cold road, as
 * in a simulation that drives a road once. The wheel positions themselves are read into
 * the caches block by block (1024 steps) before they are driven, untimed: in a vehicle
 * model they come from its own state.
 *
 * Cases: the calls xy2z, xy2uv, xy2pk and uv2z at 1, 5, 30 and 50 m/s, with a contact
 * point per wheel ("own") and one shared by the four ("shared"), STEPS steps of 1 ms
 * (default 50000: four times as many calls); then 8 and 16 threads, each driving a car
 * of its own (contact points per wheel) at 30 m/s.
 * Environment: VB_CALLS, VB_SPEEDS, VB_MODES, VB_THREADS (comma-separated lists) choose
 * the cases; VB_PASSES (default 3) sets the timed passes per case.
 *
 * Output: "cpu MODEL", then per case
 *   case CALL SPEED MODE THREADS ns N p50 N p99 N p999 N max N
 * ns: nanoseconds per call (time in the calls over a whole pass, the median of the
 * passes; with threads: the time from the first car's start to the last car's end,
 * reading the inputs included, over all threads' calls, i.e. the inverse of the
 * throughput); p50..max: the latency of single calls in nanoseconds, from one more pass
 * timed call by call (the timer's own cost subtracted).
 */
#define _GNU_SOURCE
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__x86_64__)
#include <x86intrin.h>
#endif
#include "crgBaseLib.h"
#include "car.h"

enum Call { XY2Z, XY2UV, XY2PK, UV2Z };
static const char *call_names[] = { "xy2z", "xy2uv", "xy2pk", "uv2z" };

static int g_data;
static struct Road g_road;
static long g_steps;
static int g_passes;
/* The distance the car has driven so far, over every pass and case. */
static double g_odometer;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Ticks of the call-by-call timer, and nanoseconds per tick. */
static double g_ns_per_tick = 1.0;
static inline uint64_t tick(void)
{
#if defined(__x86_64__)
    _mm_lfence();
    uint64_t t = __rdtsc();
    _mm_lfence();
    return t;
#else
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (uint64_t)t.tv_sec * 1000000000u + (uint64_t)t.tv_nsec;
#endif
}

static void calibrate_ticks(void)
{
#if defined(__x86_64__)
    double t0 = now();
    uint64_t k0 = tick();
    while (now() - t0 < 0.1)
        ;
    g_ns_per_tick = (now() - t0) * 1e9 / (double)(tick() - k0);
#endif
}

static void print_cpu(void)
{
    char line[512], model[256] = "unknown";
    FILE *f = fopen("/proc/cpuinfo", "r");
    while (f && fgets(line, sizeof line, f)) {
        char *colon = strchr(line, ':');
        if (colon && (!strncmp(line, "model name", 10) || !strncmp(line, "Model", 5))) {
            snprintf(model, sizeof model, "%s", colon + 2);
            model[strcspn(model, "\n")] = 0;
            break;
        }
    }
    if (f)
        fclose(f);
    printf("cpu %s\n", model);
}

/* Reads 64 MB, more than the last-level caches of the machines this runs on hold. */
static volatile unsigned char g_flush_sink;
static void flush_caches(void)
{
    static unsigned char *buf;
    const size_t size = 64u << 20;
    if (!buf) {
        buf = malloc(size);
        memset(buf, 1, size);
    }
    unsigned char acc = 0;
    for (size_t i = 0; i < size; i += 64)
        acc += buf[i];
    g_flush_sink = acc;
}

/* One call at path index i on contact point cp; adds its answers to the sink. */
#define CALL_XY2Z(cp, p, i, sink) do { double z_ = 0; crgEvalxy2z(cp, (p)->x[i], (p)->y[i], &z_); sink += z_; } while (0)
#define CALL_XY2UV(cp, p, i, sink) do { double u_ = 0, v_ = 0; crgEvalxy2uv(cp, (p)->x[i], (p)->y[i], &u_, &v_); sink += u_ + v_; } while (0)
#define CALL_XY2PK(cp, p, i, sink) do { double f_ = 0, k_ = 0; crgEvalxy2pk(cp, (p)->x[i], (p)->y[i], &f_, &k_); sink += f_ + k_; } while (0)
#define CALL_UV2Z(cp, p, i, sink) do { double z_ = 0; crgEvaluv2z(cp, (p)->u[i], (p)->v[i], &z_); sink += z_; } while (0)

/* Steps whose inputs are brought into the caches before they are driven: the wheel
 * positions come from the vehicle model's own (hot) state, only the road is cold. */
#define BLOCK 1024

static volatile double g_touch_sink;
static void touch_inputs(const struct Path *p, long k0, long k1)
{
    double acc = 0;
    for (long i = k0 * WHEELS; i < k1 * WHEELS; i++)
        acc += p->u[i] + p->v[i] + p->x[i] + p->y[i];
    g_touch_sink = acc;
}

/* For every call, a function driving the steps k0..k1 (every wheel on its contact point),
 * and one timing each call into `ticks`. */
#define DRIVERS(NAME, CALL)                                                                        \
    static double drive_##NAME(const int *cps, const struct Path *p, long k0, long k1)             \
    {                                                                                              \
        double sink = 0;                                                                           \
        for (long k = k0; k < k1; k++)                                                             \
            for (int w = 0; w < WHEELS; w++)                                                       \
                CALL(cps[w], p, k * WHEELS + w, sink);                                             \
        return sink;                                                                               \
    }                                                                                              \
    static double timed_##NAME(const int *cps, const struct Path *p, long k0, long k1, uint32_t *ticks) \
    {                                                                                              \
        double sink = 0;                                                                           \
        for (long k = k0; k < k1; k++)                                                             \
            for (int w = 0; w < WHEELS; w++) {                                                     \
                long i = k * WHEELS + w;                                                           \
                uint64_t t0 = tick();                                                              \
                CALL(cps[w], p, i, sink);                                                          \
                uint64_t t1 = tick();                                                              \
                ticks[i] = (uint32_t)(t1 - t0 > UINT32_MAX ? UINT32_MAX : t1 - t0);                \
            }                                                                                      \
        return sink;                                                                               \
    }
DRIVERS(xy2z, CALL_XY2Z)
DRIVERS(xy2uv, CALL_XY2UV)
DRIVERS(xy2pk, CALL_XY2PK)
DRIVERS(uv2z, CALL_UV2Z)

typedef double (*Driver)(const int *, const struct Path *, long, long);
typedef double (*TimedDriver)(const int *, const struct Path *, long, long, uint32_t *);
static const Driver drivers[] = { drive_xy2z, drive_xy2uv, drive_xy2pk, drive_uv2z };
static const TimedDriver timed_drivers[] = { timed_xy2z, timed_xy2uv, timed_xy2pk, timed_uv2z };

/* Drives the whole path, block by block; returns the seconds spent in the calls. */
static double run_path(enum Call c, const int *cps, const struct Path *p, long steps, double *sink)
{
    double spent = 0;
    for (long k0 = 0; k0 < steps; k0 += BLOCK) {
        long k1 = k0 + BLOCK < steps ? k0 + BLOCK : steps;
        touch_inputs(p, k0, k1);
        double t0 = now();
        *sink += drivers[c](cps, p, k0, k1);
        spent += now() - t0;
    }
    return spent;
}

/* The same, timing every call; `ticks` receives steps * WHEELS durations. */
static void run_path_timed(enum Call c, const int *cps, const struct Path *p, long steps, uint32_t *ticks, double *sink)
{
    for (long k0 = 0; k0 < steps; k0 += BLOCK) {
        long k1 = k0 + BLOCK < steps ? k0 + BLOCK : steps;
        touch_inputs(p, k0, k1);
        *sink += timed_drivers[c](cps, p, k0, k1, ticks);
    }
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The timer's own cost in ticks: the median of many empty measurements. */
static uint32_t g_tick_cost;
static void measure_tick_cost(void)
{
    enum { N = 100001 };
    static uint32_t t[N];
    for (int i = 0; i < N; i++) {
        uint64_t t0 = tick();
        uint64_t t1 = tick();
        t[i] = (uint32_t)(t1 - t0);
    }
    qsort(t, N, sizeof t[0], cmp_u32);
    g_tick_cost = t[N / 2];
}

/* Latency quantiles (ns) of n sorted tick counts. */
static void quantiles(uint32_t *ticks, size_t n, double out[4])
{
    qsort(ticks, n, sizeof ticks[0], cmp_u32);
    const double q[3] = { 0.5, 0.99, 0.999 };
    for (int k = 0; k < 3; k++) {
        size_t i = (size_t)(q[k] * (double)(n - 1));
        out[k] = ((double)ticks[i] - g_tick_cost) * g_ns_per_tick;
    }
    out[3] = ((double)ticks[n - 1] - g_tick_cost) * g_ns_per_tick;
}

static volatile double g_keep;

/* The contact points of one car: one per wheel, or one shared. */
static void make_cps(int *cps, int shared)
{
    for (int w = 0; w < WHEELS; w++)
        cps[w] = (shared && w > 0) ? cps[0] : crgContactPointCreate(g_data);
}

static void delete_cps(int *cps, int shared)
{
    for (int w = 0; w < (shared ? 1 : WHEELS); w++)
        crgContactPointDelete(cps[w]);
}

/* One case on one thread. */
static void single_case(enum Call c, double speed, int shared)
{
    struct Path p;
    int cps[WHEELS], helper = crgContactPointCreate(g_data);
    double *ns = malloc(sizeof(double) * (size_t)g_passes);
    uint32_t *ticks = malloc(sizeof(uint32_t) * (size_t)g_steps * WHEELS);
    path_alloc(&p, g_steps);
    make_cps(cps, shared);
    for (int pass = 0; pass <= g_passes; pass++) {
        drive(&g_road, &p, g_odometer, speed, g_steps, crgEvaluv2xy, helper);
        g_odometer += speed * DT * (double)g_steps;
        flush_caches();
        double sink = 0;
        if (pass < g_passes)
            ns[pass] = run_path(c, cps, &p, g_steps, &sink) * 1e9 / (double)(g_steps * WHEELS);
        else
            run_path_timed(c, cps, &p, g_steps, ticks, &sink);
        g_keep = sink;
    }
    qsort(ns, (size_t)g_passes, sizeof ns[0], cmp_double);
    double lat[4];
    quantiles(ticks, (size_t)g_steps * WHEELS, lat);
    printf("case %s %g %s 1 ns %.2f p50 %.1f p99 %.1f p999 %.1f max %.1f\n", call_names[c], speed,
           shared ? "shared" : "own", ns[g_passes / 2], lat[0], lat[1], lat[2], lat[3]);
    fflush(stdout);
    delete_cps(cps, shared);
    crgContactPointDelete(helper);
    path_free(&p);
    free(ticks);
    free(ns);
}

/* A thread of a multi-thread case: its own car, its own contact points. */
struct Car {
    enum Call call;
    struct Path path;
    int cps[WHEELS];
    uint32_t *ticks;
    int timed;
    pthread_barrier_t *start;
    double t0, t1; /* when this car started and finished its calls */
};

static void *car_main(void *arg)
{
    struct Car *car = arg;
    double sink = 0;
    pthread_barrier_wait(car->start);
    car->t0 = now();
    if (car->timed)
        run_path_timed(car->call, car->cps, &car->path, g_steps, car->ticks, &sink);
    else
        run_path(car->call, car->cps, &car->path, g_steps, &sink);
    car->t1 = now();
    pthread_barrier_wait(car->start);
    g_keep = sink;
    return NULL;
}

/* One case on `threads` threads, each driving its own car from its own place on the road. */
static void threaded_case(enum Call c, double speed, int threads)
{
    struct Car *cars = calloc((size_t)threads, sizeof *cars);
    pthread_t *t = calloc((size_t)threads, sizeof *t);
    pthread_barrier_t start;
    int helper = crgContactPointCreate(g_data);
    double *ns = malloc(sizeof(double) * (size_t)g_passes);
    double lap = g_road.umax - g_road.umin;
    for (int k = 0; k < threads; k++) {
        cars[k].call = c;
        path_alloc(&cars[k].path, g_steps);
        make_cps(cars[k].cps, 0);
        cars[k].ticks = malloc(sizeof(uint32_t) * (size_t)g_steps * WHEELS);
    }
    for (int pass = 0; pass <= g_passes; pass++) {
        for (int k = 0; k < threads; k++) {
            drive(&g_road, &cars[k].path, g_odometer + lap * k / threads, speed, g_steps, crgEvaluv2xy, helper);
            cars[k].timed = pass == g_passes;
        }
        g_odometer += speed * DT * (double)g_steps;
        flush_caches();
        pthread_barrier_init(&start, NULL, (unsigned)threads + 1);
        for (int k = 0; k < threads; k++) {
            cars[k].start = &start;
            pthread_create(&t[k], NULL, car_main, &cars[k]);
        }
        pthread_barrier_wait(&start);
        pthread_barrier_wait(&start);
        for (int k = 0; k < threads; k++)
            pthread_join(t[k], NULL);
        /* From the first car's start to the last car's end, as the cars saw them: the
         * main thread may get a core only after some cars have finished. */
        double first = cars[0].t0, last = cars[0].t1;
        for (int k = 1; k < threads; k++) {
            first = cars[k].t0 < first ? cars[k].t0 : first;
            last = cars[k].t1 > last ? cars[k].t1 : last;
        }
        double elapsed = last - first;
        pthread_barrier_destroy(&start);
        if (pass < g_passes)
            ns[pass] = elapsed * 1e9 / (double)(g_steps * WHEELS * threads);
    }
    size_t per = (size_t)g_steps * WHEELS, all = per * (size_t)threads;
    uint32_t *ticks = malloc(sizeof(uint32_t) * all);
    for (int k = 0; k < threads; k++)
        memcpy(ticks + per * (size_t)k, cars[k].ticks, per * sizeof(uint32_t));
    qsort(ns, (size_t)g_passes, sizeof ns[0], cmp_double);
    double lat[4];
    quantiles(ticks, all, lat);
    printf("case %s %g own %d ns %.2f p50 %.1f p99 %.1f p999 %.1f max %.1f\n", call_names[c], speed, threads,
           ns[g_passes / 2], lat[0], lat[1], lat[2], lat[3]);
    fflush(stdout);
    for (int k = 0; k < threads; k++) {
        delete_cps(cars[k].cps, 0);
        path_free(&cars[k].path);
        free(cars[k].ticks);
    }
    crgContactPointDelete(helper);
    free(ticks);
    free(ns);
    free(t);
    free(cars);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: vehicle_bench FILE [STEPS]\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    g_data = crgLoaderReadFile(argv[1]);
    if (g_data <= 0) {
        fprintf(stderr, "cannot load %s\n", argv[1]);
        return 1;
    }
    crgDataSetModifiersApply(g_data);
    crgDataSetGetURange(g_data, &g_road.umin, &g_road.umax);
    g_steps = argc > 2 ? atol(argv[2]) : 50000;
    if (g_steps < 1)
        g_steps = 1;
    g_passes = getenv("VB_PASSES") ? atoi(getenv("VB_PASSES")) : 3;
    if (g_passes < 1)
        g_passes = 1;
    print_cpu();
    calibrate_ticks();
    measure_tick_cost();
    for (int c = XY2Z; c <= UV2Z; c++) {
        if (!chosen("VB_CALLS", call_names[c]))
            continue;
        for (int s = 0; s < CAR_SPEEDS; s++) {
            if (!number_chosen("VB_SPEEDS", car_speeds[s]))
                continue;
            for (int shared = 0; shared < 2; shared++)
                if (chosen("VB_MODES", shared ? "shared" : "own"))
                    single_case((enum Call)c, car_speeds[s], shared);
        }
    }
    const int thread_counts[] = { 8, 16 };
    for (int k = 0; k < 2; k++) {
        if (!number_chosen("VB_THREADS", thread_counts[k]))
            continue;
        for (int c = XY2Z; c <= UV2Z; c++)
            if (chosen("VB_CALLS", call_names[c]))
                threaded_case((enum Call)c, 30.0, thread_counts[k]);
    }
    crgMemRelease();
    return 0;
}
