/* The native counterpart of bench/wasm_speed.mjs: crgEvaluv2z at the road's points and
 * crgOdrEvalxy at the map's (the files that script writes), one contact point or probe,
 * point after point. Prints ns per point.
 *
 * usage: wasm_native ROAD MAP DIR */
#include "crgBaseLib.h"
#include "crgOdr.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double *points(const char *dir, const char *name, long *n)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "wasm_native: cannot read %s (bench/wasm_speed.mjs writes it)\n", path);
        exit(1);
    }
    fseek(f, 0, SEEK_END);
    long bytes = ftell(f);
    fseek(f, 0, SEEK_SET);
    double *p = malloc((size_t)bytes);
    if (!p || fread(p, 1, (size_t)bytes, f) != (size_t)bytes)
        exit(1);
    fclose(f);
    *n = bytes / 16;
    return p;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: wasm_native ROAD MAP DIR\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    int data = crgLoaderReadFile(argv[1]);
    int map = crgOdrMapLoad(argv[2]);
    if (data <= 0 || map <= 0)
        return 1;
    crgDataSetModifiersApply(data);
    int cp = crgContactPointCreate(data), probe = crgOdrProbeCreate(map);
    long n, m;
    double *uv = points(argv[3], "road_points.f64", &n), *xy = points(argv[3], "map_points.f64", &m);
    double sz = 0, sg = 0, start = now();
    for (long i = 0; i < n; i++) {
        double z;
        if (crgEvaluv2z(cp, uv[i], uv[n + i], &z) && !isnan(z))
            sz += z;
    }
    double road_ns = (now() - start) * 1e9 / n;
    start = now();
    for (long i = 0; i < m; i++) {
        double z, friction, s, t;
        int road, lane;
        if (crgOdrEvalxy(probe, xy[i], xy[m + i], &z, &friction, &road, &lane, &s, &t) && !isnan(z))
            sg += z;
    }
    double map_ns = (now() - start) * 1e9 / m;
    printf("native: %.1f ns per crgEvaluv2z point, %.1f ns per crgOdrEvalxy point (sums %.3f %.3f)\n", road_ns, map_ns, sz, sg);
    return 0;
}
