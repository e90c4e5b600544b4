/*
 * What the vehicle benchmarks (bench/vehicle_bench.c, bench/vehicle_ab.c) share: the car, a
 * compact car (wheelbase 2.64 m, track 1.55 m, the VW Golf's) whose rear axle drives
 * along the reference line at a constant speed, weaving 0.3 m to either side over 60 m,
 * in steps of 1 ms; at the road's end it starts over at its beginning. The wheels' u/v
 * follow from that, their x/y from the library's u/v to x/y.
 */
#ifndef OPENCRG_BENCH_CAR_H
#define OPENCRG_BENCH_CAR_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WHEELBASE 2.64
#define TRACK 1.55
#define DT 0.001
#define WEAVE 0.3
#define WEAVE_LENGTH 60.0
#define MARGIN 1.0
#define WHEELS 4

/* Where each wheel is at each step: u/v and x/y. */
struct Path {
    double *u, *v, *x, *y; /* [step * WHEELS + wheel] */
};

/* The road's u range. */
struct Road {
    double umin, umax;
};

/* u/v to x/y on a contact point: crgEvaluv2xy or a pointer to it. */
typedef int (*Uv2xy)(int, double, double, double *, double *);

static inline double weave(double u) { return WEAVE * sin(2.0 * M_PI * u / WEAVE_LENGTH); }

/* The u of the rear axle after driving `s` metres from the road's start (laps). */
static inline double rear_u(const struct Road *r, double s)
{
    double drivable = r->umax - r->umin - WHEELBASE - 2 * MARGIN;
    return r->umin + MARGIN + fmod(s, drivable);
}

/* Fills `p` with `steps` steps at `speed` from odometer reading `s0`. */
static inline void drive(const struct Road *r, struct Path *p, double s0, double speed, long steps, Uv2xy uv2xy, int cp)
{
    for (long k = 0; k < steps; k++) {
        double ur = rear_u(r, s0 + speed * DT * (double)k), uf = ur + WHEELBASE;
        double u[WHEELS] = { uf, uf, ur, ur };
        double v[WHEELS] = { weave(uf) + TRACK / 2, weave(uf) - TRACK / 2, weave(ur) + TRACK / 2, weave(ur) - TRACK / 2 };
        for (int w = 0; w < WHEELS; w++) {
            long i = k * WHEELS + w;
            p->u[i] = u[w];
            p->v[i] = v[w];
            uv2xy(cp, u[w], v[w], &p->x[i], &p->y[i]);
        }
    }
}

static inline void path_alloc(struct Path *p, long steps)
{
    size_t n = (size_t)steps * WHEELS;
    p->u = malloc(n * sizeof(double));
    p->v = malloc(n * sizeof(double));
    p->x = malloc(n * sizeof(double));
    p->y = malloc(n * sizeof(double));
}

static inline void path_free(struct Path *p)
{
    free(p->u);
    free(p->v);
    free(p->x);
    free(p->y);
}

/* Order of doubles, for qsort. */
static inline int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Whether `word` is one of the comma-separated words of the environment variable `var`
 * (every word when it is not set): how the programs' cases are chosen. */
static inline int chosen(const char *var, const char *word)
{
    const char *list = getenv(var);
    if (!list)
        return 1;
    size_t len = strlen(word);
    for (const char *p = list; *p;) {
        size_t n = strcspn(p, ",");
        if (n == len && !strncmp(p, word, n))
            return 1;
        p += n + (p[n] == ',');
    }
    return 0;
}

/* `chosen` for a number, written as printf's %g writes it. */
static inline int number_chosen(const char *var, double number)
{
    char word[32];
    snprintf(word, sizeof word, "%g", number);
    return chosen(var, word);
}

/* The speeds the programs drive at (m/s). */
#define CAR_SPEEDS 4
static const double car_speeds[CAR_SPEEDS] = { 1, 5, 30, 50 };
#endif
