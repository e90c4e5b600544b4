/*
 * What the programs that open one road through the classic API share (bench/open_drive.c,
 * bench/tile_fill.c): a monotonic clock, and opening a road as a vehicle model does
 * (read, check, apply the modifiers).
 */
#ifndef OPENCRG_BENCH_ROAD_OPEN_H
#define OPENCRG_BENCH_ROAD_OPEN_H
#include <stdio.h>
#include <time.h>
#include "crgBaseLib.h"

/* Seconds on a monotonic clock. */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* The data set of the road in `path`, read, checked and modified; 0 (said on stderr,
 * naming `program` and the file) where it cannot be opened. */
static int open_road(const char *program, const char *path)
{
    int id = crgLoaderReadFile(path);
    if (id <= 0 || !crgCheck(id)) {
        fprintf(stderr, "%s: %s not opened\n", program, path);
        return 0;
    }
    crgDataSetModifiersApply(id);
    return id;
}
#endif
