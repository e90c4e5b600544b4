/* Four wheels of a car at 1 kHz and 20 m/s through the C API: crgOdrEvalxy on the map
 * with an attached CRG file (the map and the file `odr_bench wheels DIR` writes), against
 * crgEvalxy2z on the same CRG file alone along paths of the same length and step, a
 * contact point per wheel. Prints ns per call of each, the two alternating ROUNDS times.
 *
 * usage: odr_wheels DIR [ROUNDS] */
#include "crgBaseLib.h"
#include "crgOdr.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define STEPS 45000
#define WHEELS 4

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: odr_wheels DIR [ROUNDS]\n");
        return 2;
    }
    int rounds = argc > 2 ? atoi(argv[2]) : 5;
    char path[4096];
    crgMsgSetLevel(dCrgMsgLevelNone);
    snprintf(path, sizeof path, "%s/track.xodr", argv[1]);
    int map = crgOdrMapLoad(path);
    snprintf(path, sizeof path, "%s/track.crg", argv[1]);
    int data = crgLoaderReadFile(path);
    if (map <= 0 || data <= 0 || !crgCheck(data)) {
        fprintf(stderr, "odr_wheels: cannot read the map or the CRG file in %s\n", argv[1]);
        return 1;
    }
    static const double ds[WHEELS] = {0.0, 0.0, 2.7, 2.7}, t[WHEELS] = {0.8, -0.8, 0.8, -0.8};
    static double x[WHEELS][STEPS], y[WHEELS][STEPS];
    int probes[WHEELS], cps[WHEELS];
    for (int w = 0; w < WHEELS; w++) {
        probes[w] = crgOdrProbeCreate(map);
        cps[w] = crgContactPointCreate(data);
        for (int i = 0; i < STEPS; i++) {
            double z;
            if (!crgOdrEvalst2xyz(probes[w], 0, 10.0 + ds[w] + i * 0.02, t[w], &x[w][i], &y[w][i], &z)) {
                fprintf(stderr, "odr_wheels: no road at step %d\n", i);
                return 1;
            }
        }
    }
    for (int r = 0; r < rounds; r++) {
        double sum = 0.0, sum2 = 0.0;
        double start = now();
        for (int i = 0; i < STEPS; i++) {
            for (int w = 0; w < WHEELS; w++) {
                double z, friction, s, tt;
                int road, lane;
                if (crgOdrEvalxy(probes[w], x[w][i], y[w][i], &z, &friction, &road, &lane, &s, &tt))
                    sum += z;
            }
        }
        double odr = (now() - start) * 1e9 / (STEPS * WHEELS);
        start = now();
        for (int i = 0; i < STEPS; i++) {
            for (int w = 0; w < WHEELS; w++) {
                double z;
                if (crgEvalxy2z(cps[w], 10.0 + ds[w] + i * 0.02, t[w], &z))
                    sum2 += z;
            }
        }
        double plain = (now() - start) * 1e9 / (STEPS * WHEELS);
        printf("c wheels: %.1f ns per crgOdrEvalxy, %.1f ns per crgEvalxy2z (sums %.3f %.3f)\n", odr, plain, sum, sum2);
    }
    return 0;
}
