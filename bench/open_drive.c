/*
 * Opens a road through the classic OpenCRG C API as a vehicle model does (read, check,
 * apply the modifiers, a contact point per wheel), drives the car of car.h over a stretch
 * of it (x/y to z at every wheel, 1 kHz), and prints what that took and what memory the
 * process holds (from /proc/self/status: RssAnon is its private memory, RssFile the
 * file pages it maps, which the system's cache shares with every process reading the
 * same file).
 *
 * usage: open_drive FILE [METRES [SPEED [START]]]   (default 200 m at 30 m/s from u = 1 m)
 *
 * Output, one line: "open S drive S calls N rss_anon KIB rss_file KIB hwm KIB sink X".
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "car.h"
#include "road_open.h"

/* A figure of /proc/self/status in KiB (-1 where the system does not tell it). */
static long status_kib(const char *key)
{
    char line[256];
    long value = -1;
    size_t n = strlen(key);
    FILE *f = fopen("/proc/self/status", "r");
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, key, n) && line[n] == ':')
            value = strtol(line + n + 1, NULL, 10);
    if (f)
        fclose(f);
    return value;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: open_drive FILE [METRES [SPEED [START]]]\n");
        return 2;
    }
    double metres = argc > 2 ? atof(argv[2]) : 200.0, speed = argc > 3 ? atof(argv[3]) : 30.0;
    double start = argc > 4 ? atof(argv[4]) : 1.0;
    crgMsgSetLevel(dCrgMsgLevelWarn);
    double t0 = now();
    int id = open_road("open_drive", argv[1]);
    if (!id)
        return 1;
    int cps[WHEELS];
    for (int w = 0; w < WHEELS; w++)
        cps[w] = crgContactPointCreate(id);
    double opened = now() - t0;
    struct Road road;
    crgDataSetGetURange(id, &road.umin, &road.umax);
    long steps = (long)(metres / (speed * DT));
    struct Path p;
    path_alloc(&p, steps);
    /* The path starts `start` metres into the road. */
    drive(&road, &p, start - MARGIN, speed, steps, crgEvaluv2xy, cps[0]);
    double sink = 0;
    long calls = 0;
    t0 = now();
    for (long k = 0; k < steps; k++)
        for (int w = 0; w < WHEELS; w++) {
            double z = 0;
            calls += crgEvalxy2z(cps[w], p.x[k * WHEELS + w], p.y[k * WHEELS + w], &z);
            sink += z;
        }
    double driven = now() - t0;
    printf("open %.3f drive %.3f calls %ld rss_anon %ld rss_file %ld hwm %ld sink %.17g\n", opened, driven, calls,
           status_kib("RssAnon"), status_kib("RssFile"), status_kib("VmHWM"), sink);
    path_free(&p);
    return 0;
}
