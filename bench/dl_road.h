/*
 * What the benchmarks that load a library offering the classic OpenCRG C API at run time
 * (bench/vehicle_ab.c, bench/call_cycles.c) share: loading it, finding its functions, and
 * opening a road with it as the vehicle benchmarks do (messages off, the file read, its
 * modifiers applied, its u range, a contact point per wheel). Every failure ends the
 * program with a message.
 */
#ifndef OPENCRG_BENCH_DL_ROAD_H
#define OPENCRG_BENCH_DL_ROAD_H
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include "car.h"

/* The library at `path`, loaded with `flags` (RTLD_NOW | RTLD_LOCAL and more). */
static inline void *dl_library(const char *path, int flags)
{
    void *h = dlopen(path, flags);
    if (!h) {
        fprintf(stderr, "%s\n", dlerror());
        exit(1);
    }
    return h;
}

/* The function `name` of the library `h`. */
static inline void *dl_symbol(void *h, const char *name)
{
    void *f = dlsym(h, name);
    if (!f) {
        fprintf(stderr, "%s\n", dlerror());
        exit(1);
    }
    return f;
}

/* Opens `road` with the library `h` (loaded from `lib`): its data set id; its u range
 * into `range` and a contact point per wheel into `cp`. */
static inline int dl_open_road(void *h, const char *lib, const char *road, struct Road *range, int cp[WHEELS])
{
    ((void (*)(int))dl_symbol(h, "crgMsgSetLevel"))(0);
    int data = ((int (*)(const char *))dl_symbol(h, "crgLoaderReadFile"))(road);
    if (data <= 0) {
        fprintf(stderr, "%s: cannot load %s\n", lib, road);
        exit(1);
    }
    ((int (*)(int))dl_symbol(h, "crgDataSetModifiersApply"))(data);
    ((int (*)(int, double *, double *))dl_symbol(h, "crgDataSetGetURange"))(data, &range->umin, &range->umax);
    for (int w = 0; w < WHEELS; w++)
        cp[w] = ((int (*)(int))dl_symbol(h, "crgContactPointCreate"))(data);
    return data;
}
#endif
