/*
 * The hot calls of the classic C API (and of crgOdr.h), each run alone so that
 * callgrind can count the instructions it executes: the guard of c-tests/instructions/run.sh
 * and the instruction comparison of two builds (bench/instructions_ab.sh).
 *
 * usage: hot_calls LIB.so CASE FILE [STEPS]
 *   LIB.so  a library offering the classic API (this project's, an earlier build of it,
 *           the reference's); the map case needs crgOdr.h's calls too
 *   CASE    xy2z-own, xy2z-shared, xy2uv-own, xy2uv-shared, xy2pk-own, uv2z-own,
 *           uv2pk-own: the car of bench/car.h driving along the CRG file FILE at 30 m/s,
 *           four wheels at 1 kHz, a contact point per wheel ("own") or one for the four
 *           ("shared"); with "-in-place" in the name (xy2z-own-in-place, ...) the road is
 *           read in place (OPENCRG_IN_PLACE=always) and the measured steps are driven once
 *           unmeasured before, so that the count is of the tiles' warm path;
 *           odr-wheels: the same car's wheels along the first road of the OpenDRIVE map FILE
 *           through crgOdrEvalxy, a probe per wheel;
 *           load: crgLoaderReadFile of the CRG file FILE
 *   STEPS   the measured steps (default 4000), after as many unmeasured ones
 *
 * Only the function `measured` is meant to be counted (callgrind --toggle-collect=measured):
 * STEPS steps of four calls (or one load). Prints "calls N": what the count is
 * divided by.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "car.h"

#define SPEED 30.0

typedef int (*Eval1)(int, double, double, double *);
typedef int (*Eval2)(int, double, double, double *, double *);
typedef int (*OdrEval)(int, double, double, double *, double *, int *, int *, double *, double *);

enum Call { XY2Z, XY2UV, XY2PK, UV2Z, UV2PK, ODR, LOAD };

static void *g_lib;
static volatile double g_sink;

static void *symbol(const char *name)
{
    void *f = dlsym(g_lib, name);
    if (!f) {
        fprintf(stderr, "hot_calls: %s\n", dlerror());
        exit(1);
    }
    return f;
}

/* The entry points a case calls, looked up before anything is counted. */
struct Calls {
    Eval1 e1;
    Eval2 e2;
    OdrEval odr;
    int (*load)(const char *);
};

/* Steps k0..k1 of the path, four wheels each (or one load). */
static __attribute__((noinline)) void run_calls(enum Call c, const struct Calls *f, const int *cps,
                                                const struct Path *p, long k0, long k1, const char *file)
{
    double sum = 0;
    if (c == LOAD) {
        g_sink = f->load(file);
        return;
    }
    for (long k = k0; k < k1; k++)
        for (int w = 0; w < WHEELS; w++) {
            long i = k * WHEELS + w;
            double a = 0, b = 0, s = 0, t = 0;
            int road = 0, lane = 0;
            switch (c) {
            case XY2Z: f->e1(cps[w], p->x[i], p->y[i], &a); break;
            case UV2Z: f->e1(cps[w], p->u[i], p->v[i], &a); break;
            case XY2UV:
            case XY2PK: f->e2(cps[w], p->x[i], p->y[i], &a, &b); break;
            case UV2PK: f->e2(cps[w], p->u[i], p->v[i], &a, &b); break;
            case ODR: f->odr(cps[w], p->x[i], p->y[i], &a, &b, &road, &lane, &s, &t); break;
            case LOAD: break;
            }
            sum += a + b + s + t;
        }
    g_sink = sum;
}

/* The calls counted (callgrind --toggle-collect=measured): `run_calls` once more. */
static __attribute__((noinline)) void measured(enum Call c, const struct Calls *f, const int *cps,
                                               const struct Path *p, long k0, long k1, const char *file)
{
    run_calls(c, f, cps, p, k0, k1, file);
}

/* The car's path along the first road of a map (index 0): s/t to x/y through
 * crgOdrEvalst2xyz (u is s, v is t). */
static void drive_map(int probe, double length, struct Path *p, long steps)
{
    int (*st2xyz)(int, int, double, double, double *, double *, double *) =
        (int (*)(int, int, double, double, double *, double *, double *))symbol("crgOdrEvalst2xyz");
    struct Road r = { 0.0, length };
    for (long k = 0; k < steps; k++) {
        double ur = rear_u(&r, SPEED * DT * (double)k), uf = ur + WHEELBASE;
        double u[WHEELS] = { uf, uf, ur, ur };
        double v[WHEELS] = { weave(uf) + TRACK / 2, weave(uf) - TRACK / 2, weave(ur) + TRACK / 2, weave(ur) - TRACK / 2 };
        for (int w = 0; w < WHEELS; w++) {
            long i = k * WHEELS + w;
            double z;
            p->u[i] = u[w];
            p->v[i] = v[w];
            if (!st2xyz(probe, 0, u[w], v[w], &p->x[i], &p->y[i], &z)) {
                fprintf(stderr, "hot_calls: no point at s %g t %g of the first road\n", u[w], v[w]);
                exit(1);
            }
        }
    }
}

/* The length attribute of the first <road> element of a map file. */
static double first_road_length(const char *file)
{
    static char text[1 << 20];
    FILE *f = fopen(file, "rb");
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f)
        fclose(f);
    text[n] = 0;
    const char *road = strstr(text, "<road "), *length = road ? strstr(road, "length=\"") : NULL;
    double value = length ? atof(length + 8) : 0;
    if (value <= 0) {
        fprintf(stderr, "hot_calls: no road length in %s\n", file);
        exit(1);
    }
    return value;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: hot_calls LIB.so CASE FILE [STEPS]\n");
        return 2;
    }
    static const char *names[] = { "xy2z", "xy2uv", "xy2pk", "uv2z", "uv2pk", "odr-wheels", "load" };
    const char *name = argv[2], *file = argv[3];
    long steps = argc > 4 ? atol(argv[4]) : 4000;
    int shared = strstr(name, "-shared") != NULL;
    int in_place = strstr(name, "-in-place") != NULL;
    if (in_place)
        setenv("OPENCRG_IN_PLACE", "always", 1);
    enum Call c = LOAD;
    for (int i = 0; i <= LOAD; i++) {
        size_t n = strlen(names[i]);
        if (!strncmp(name, names[i], n) && (name[n] == 0 || name[n] == '-'))
            c = (enum Call)i;
    }
    if (c == LOAD && strcmp(name, "load")) {
        fprintf(stderr, "hot_calls: unknown case %s\n", name);
        return 2;
    }
    g_lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!g_lib) {
        fprintf(stderr, "hot_calls: %s\n", dlerror());
        return 1;
    }
    ((void (*)(int))symbol("crgMsgSetLevel"))(0);
    struct Calls f = { 0 };
    if (c == LOAD) {
        f.load = (int (*)(const char *))symbol("crgLoaderReadFile");
        measured(LOAD, &f, NULL, NULL, 0, 0, file);
        printf("calls 1\n");
        return g_sink > 0 ? 0 : 1;
    }
    int cps[WHEELS];
    struct Path p;
    path_alloc(&p, 2 * steps);
    if (c == ODR) {
        int map = ((int (*)(const char *))symbol("crgOdrMapLoad"))(file);
        if (map <= 0) {
            fprintf(stderr, "hot_calls: cannot read the map %s\n", file);
            return 1;
        }
        for (int w = 0; w < WHEELS; w++)
            cps[w] = ((int (*)(int))symbol("crgOdrProbeCreate"))(map);
        double length = first_road_length(file);
        drive_map(cps[0], length, &p, 2 * steps);
    } else {
        int data = ((int (*)(const char *))symbol("crgLoaderReadFile"))(file);
        if (data <= 0 || !((int (*)(int))symbol("crgCheck"))(data)) {
            fprintf(stderr, "hot_calls: cannot read %s\n", file);
            return 1;
        }
        ((int (*)(int))symbol("crgDataSetModifiersApply"))(data);
        struct Road r;
        ((int (*)(int, double *, double *))symbol("crgDataSetGetURange"))(data, &r.umin, &r.umax);
        for (int w = 0; w < WHEELS; w++)
            cps[w] = (shared && w > 0) ? cps[0] : ((int (*)(int))symbol("crgContactPointCreate"))(data);
        drive(&r, &p, 0.0, SPEED, 2 * steps, (Uv2xy)symbol("crgEvaluv2xy"), cps[0]);
    }
    if (c == XY2Z || c == UV2Z)
        f.e1 = (Eval1)symbol(c == XY2Z ? "crgEvalxy2z" : "crgEvaluv2z");
    else if (c == ODR)
        f.odr = (OdrEval)symbol("crgOdrEvalxy");
    else
        f.e2 = (Eval2)symbol(c == XY2UV ? "crgEvalxy2uv" : c == XY2PK ? "crgEvalxy2pk" : "crgEvaluv2pk");
    /* The same calls unmeasured first: the contact points' histories and the caches filled. */
    run_calls(c, &f, cps, &p, 0, steps, file);
    /* Read in place: the tiles of the measured steps read, as on a lap driven before. */
    if (in_place)
        run_calls(c, &f, cps, &p, steps, 2 * steps, file);
    measured(c, &f, cps, &p, steps, 2 * steps, file);
    printf("calls %ld\n", steps * WHEELS);
    path_free(&p);
    return 0;
}
