/*
 * Where the time of u/v to z goes, call by call: the car of car.h driven along a road with
 * every call timed alone (x86-64: the time-stamp counter read with rdtscp before and
 * after), three passes over the same path, the last one counted (the first reads the
 * road, the second warms the caches). Prints the counter cycles a call, how the calls
 * spread over bands of cycles, and each wheel's mean; with DUMP=FILE also "step wheel
 * cycles" for the counted pass's first 40,000 steps, to be laid beside another run.
 * The timer itself costs some tens of cycles a call: compare runs, not absolute figures.
 * Run it once with OPENCRG_IN_PLACE=never and once with =always to see what reading in
 * place costs, and where.
 *
 * usage: call_cycles ROAD LIB.so SPEED shared|own [STEPS]
 *   cc -O2 -Wall -Wextra -Iinclude bench/call_cycles.c -ldl -lm -o target/call_cycles
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "car.h"
#include "dl_road.h"
#if defined(__x86_64__)
#include <x86intrin.h>

#define BANDS 9
static const long band_top[BANDS] = { 20, 40, 60, 80, 120, 200, 400, 1000, -1 };

typedef int (*Eval1)(int, double, double, double *);

static int band(long cycles)
{
    int b = 0;
    while (band_top[b] >= 0 && cycles >= band_top[b])
        b++;
    return b;
}

int main(int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: call_cycles ROAD LIB.so SPEED shared|own [STEPS]\n");
        return 2;
    }
    double speed = atof(argv[3]);
    int shared = !strcmp(argv[4], "shared");
    char *end = "";
    long steps = argc > 5 ? strtol(argv[5], &end, 10) : 100000;
    if (*end || !(speed > 0 && speed <= 1000) || (!shared && strcmp(argv[4], "own")) || steps < 1 || steps > 10000000) {
        fprintf(stderr, "call_cycles: SPEED is m/s above 0 and at most 1000, then shared or own, STEPS 1 to 10000000\n");
        return 2;
    }
    void *h = dl_library(argv[2], RTLD_NOW | RTLD_LOCAL);
    struct Road road;
    int cp[WHEELS];
    dl_open_road(h, argv[2], argv[1], &road, cp);
    Eval1 uv2z = (Eval1)dl_symbol(h, "crgEvaluv2z");
    struct Path p;
    path_alloc(&p, steps);
    drive(&road, &p, 0.0, speed, steps, (Uv2xy)dl_symbol(h, "crgEvaluv2xy"), cp[0]);
    const char *dump_path = getenv("DUMP");
    FILE *dump = dump_path ? fopen(dump_path, "w") : NULL;
    long count[BANDS] = { 0 };
    double cycles[BANDS] = { 0 }, wheel[WHEELS] = { 0 }, total = 0, sum = 0;
    for (int pass = 0; pass < 3; pass++)
        for (long k = 0; k < steps; k++)
            for (int w = 0; w < WHEELS; w++) {
                long i = k * WHEELS + w;
                double z = 0;
                unsigned aux;
                unsigned long long t0 = __rdtscp(&aux);
                uv2z(cp[shared ? 0 : w], p.u[i], p.v[i], &z);
                unsigned long long t1 = __rdtscp(&aux);
                sum += z;
                if (pass < 2)
                    continue;
                long d = (long)(t1 - t0);
                int b = band(d);
                count[b]++;
                cycles[b] += (double)d;
                wheel[w] += (double)d;
                total += (double)d;
                if (dump && k < 40000)
                    fprintf(dump, "%ld %d %ld\n", k, w, d);
            }
    if (dump)
        fclose(dump);
    double calls = (double)steps * WHEELS;
    printf("cycles a call %.1f (sum of heights %g)\n", total / calls, sum);
    for (int b = 0; b < BANDS; b++) {
        char name[32];
        if (band_top[b] >= 0)
            snprintf(name, sizeof name, "< %ld", band_top[b]);
        else
            snprintf(name, sizeof name, ">= %ld", band_top[b - 1]);
        printf("  %-8s %9ld calls (%6.3f %%), %6.2f cycles a call of all\n", name, count[b], 100.0 * (double)count[b] / calls,
               cycles[b] / calls);
    }
    for (int w = 0; w < WHEELS; w++)
        printf("  wheel %d: %.1f cycles a call\n", w, wheel[w] / (double)steps);
    path_free(&p);
    return 0;
}
#else
int main(void)
{
    fprintf(stderr, "call_cycles: x86-64 only (the time-stamp counter)\n");
    return 2;
}
#endif
