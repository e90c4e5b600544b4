/*
 * Two or more libraries offering the classic OpenCRG C API, loaded into one process and
 * driven in turn along the car's path of car.h: the way to tell which of two builds is
 * faster on a shared, noisy machine. The path is cut into chunks of 2000 steps (8000
 * calls); round after round every library drives the same chunk, in turns whose order
 * flips each round, so a slow spell of the machine hits all of them alike; each round
 * gives a ratio per library. Separate processes timed minutes apart differ by up to 30 %
 * on such a machine; the ratios of one round spread by a few per cent.
 *
 * The chunks lie on road the libraries have driven before (the round's first turn brings
 * it into the caches for the others; the order flips, so no library always pays for it):
 * the figure is the cost of the calls themselves, not of cold road. bench/vehicle_bench.c
 * measures the road driven once.
 *
 * usage: vehicle_ab ROAD LIB.so [LIB.so ...]
 * Environment: AB_CALLS (xy2z,xy2uv,xy2pk,uv2z), AB_SPEEDS (1,5,30,50), AB_ROUNDS
 * (default 61), AB_MODES (own,shared: a contact point per wheel, one for the four),
 * AB_IN_PLACE (a value of OPENCRG_IN_PLACE per library, comma-separated, set while that
 * library opens the road: one build read in place against itself in memory, the same
 * library named twice), AB_WARM (1: every library drives the whole path once before the
 * rounds, so that a road read in place has every tile of it decoded, at 1 and 5 m/s too).
 * Output per case and library:
 *   ab CALL SPEED MODE LIB[:in_place=VALUE] ns MEDIAN min MIN max MAX ratio MEDIAN q1 Q1 q3 Q3
 * ns: nanoseconds per call (median, smallest and largest over the rounds); ratio: the
 * first library's time over this one's, per round: its median and quartiles (above 1:
 * this library is faster).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "car.h"
#include "dl_road.h"

#define CHUNK 2000
#define MAX_LIBS 8

typedef int (*Eval1)(int, double, double, double *);
typedef int (*Eval2)(int, double, double, double *, double *);

struct Lib {
    const char *path;
    /* The path, with the OPENCRG_IN_PLACE value it opened the road with, if set. */
    char label[512];
    int data, cp[WHEELS];
    struct Road road;
    Eval1 uv2z, xy2z;
    Eval2 xy2uv, xy2pk, uv2xy;
};

enum Call { XY2Z, XY2UV, XY2PK, UV2Z };
static const char *call_names[] = { "xy2z", "xy2uv", "xy2pk", "uv2z" };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void load(struct Lib *l, const char *road)
{
    void *h = dl_library(l->path, RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND);
    l->data = dl_open_road(h, l->path, road, &l->road, l->cp);
    l->uv2z = (Eval1)dl_symbol(h, "crgEvaluv2z");
    l->xy2z = (Eval1)dl_symbol(h, "crgEvalxy2z");
    l->xy2uv = (Eval2)dl_symbol(h, "crgEvalxy2uv");
    l->xy2pk = (Eval2)dl_symbol(h, "crgEvalxy2pk");
    l->uv2xy = (Eval2)dl_symbol(h, "crgEvaluv2xy");
}

static volatile double g_sink;

/* Sets OPENCRG_IN_PLACE to the `n`-th comma-separated value of AB_IN_PLACE, if any (the
 * same library named twice opens the road twice, once each way). */
static void set_in_place(int n)
{
    const char *list = getenv("AB_IN_PLACE");
    for (int k = 0; list && k < n; k++) {
        list = strchr(list, ',');
        if (list)
            list++;
    }
    if (!list || !*list)
        return;
    char value[64];
    snprintf(value, sizeof value, "%.*s", (int)strcspn(list, ","), list);
    setenv("OPENCRG_IN_PLACE", value, 1);
}

/* Drives steps k0..k1 of `p` with call `c` on `l`'s contact points (all on the first
 * when `shared`): ns per call. */
static double run(const struct Lib *l, enum Call c, int shared, const struct Path *p, long k0, long k1)
{
    double sum = 0, t0 = now();
    for (long k = k0; k < k1; k++)
        for (int w = 0; w < WHEELS; w++) {
            long i = k * WHEELS + w;
            int cp = l->cp[shared ? 0 : w];
            double a = 0, b = 0;
            switch (c) {
            case XY2Z: l->xy2z(cp, p->x[i], p->y[i], &a); break;
            case XY2UV: l->xy2uv(cp, p->x[i], p->y[i], &a, &b); break;
            case XY2PK: l->xy2pk(cp, p->x[i], p->y[i], &a, &b); break;
            case UV2Z: l->uv2z(cp, p->u[i], p->v[i], &a); break;
            }
            sum += a + b;
        }
    double t = now() - t0;
    g_sink = sum;
    return t * 1e9 / ((double)(k1 - k0) * WHEELS);
}

static double at(double *sorted, int n, double q) { return sorted[(int)(q * (n - 1) + 0.5)]; }

/* One case: every library drives the path's first chunk (the whole path with AB_WARM),
 * then the rounds in turns (the order flipping each round); prints each library's times
 * and ratios. */
static void one_case(const struct Lib *libs, int nl, enum Call c, double speed, int shared, const struct Path *p, int rounds)
{
    double *t = malloc(sizeof(double) * rounds * nl), *sorted = malloc(sizeof(double) * rounds);
    long warm = getenv("AB_WARM") && atoi(getenv("AB_WARM")) ? (long)rounds * CHUNK : CHUNK;
    for (int l = 0; l < nl; l++)
        run(&libs[l], c, shared, p, 0, warm);
    for (int r = 0; r < rounds; r++)
        for (int k = 0; k < nl; k++) {
            int l = (r & 1) ? nl - 1 - k : k;
            t[l * rounds + r] = run(&libs[l], c, shared, p, (long)r * CHUNK, (long)(r + 1) * CHUNK);
        }
    for (int l = 0; l < nl; l++) {
        memcpy(sorted, t + l * rounds, sizeof(double) * rounds);
        qsort(sorted, rounds, sizeof(double), cmp_double);
        double med = at(sorted, rounds, 0.5), lo = sorted[0], hi = sorted[rounds - 1];
        for (int r = 0; r < rounds; r++)
            sorted[r] = t[r] / t[l * rounds + r];
        qsort(sorted, rounds, sizeof(double), cmp_double);
        printf("ab %s %g %s %s ns %.2f min %.2f max %.2f ratio %.3f q1 %.3f q3 %.3f\n", call_names[c], speed,
               shared ? "shared" : "own", libs[l].label, med, lo, hi, at(sorted, rounds, 0.5), at(sorted, rounds, 0.25),
               at(sorted, rounds, 0.75));
    }
    free(t);
    free(sorted);
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc - 2 > MAX_LIBS) {
        fprintf(stderr, "usage: vehicle_ab ROAD LIB.so [LIB.so ...] (at most %d)\n", MAX_LIBS);
        return 2;
    }
    int nl = argc - 2, rounds = getenv("AB_ROUNDS") ? atoi(getenv("AB_ROUNDS")) : 61;
    if (rounds < 3)
        rounds = 3;
    struct Lib libs[MAX_LIBS];
    for (int l = 0; l < nl; l++) {
        libs[l].path = argv[2 + l];
        set_in_place(l);
        const char *mode = getenv("OPENCRG_IN_PLACE");
        snprintf(libs[l].label, sizeof libs[l].label, "%s%s%s", libs[l].path, mode ? ":in_place=" : "", mode ? mode : "");
        load(&libs[l], argv[1]);
    }
    long steps = (long)rounds * CHUNK;
    for (int c = XY2Z; c <= UV2Z; c++) {
        if (!chosen("AB_CALLS", call_names[c]))
            continue;
        for (int s = 0; s < CAR_SPEEDS; s++) {
            if (!number_chosen("AB_SPEEDS", car_speeds[s]))
                continue;
            struct Path p;
            path_alloc(&p, steps);
            drive(&libs[0].road, &p, 0.0, car_speeds[s], steps, libs[0].uv2xy, libs[0].cp[0]);
            for (int shared = 0; shared < 2; shared++)
                if (chosen("AB_MODES", shared ? "shared" : "own"))
                    one_case(libs, nl, (enum Call)c, car_speeds[s], shared, &p, rounds);
            path_free(&p);
        }
    }
    return 0;
}
