/*
 * The FMI layer's cost: four wheels of a car at 1 kHz and 20 m/s, each step one
 * fmi2SetReal of the eight x/y inputs and one fmi2GetReal of the four heights, as an
 * importer calls an FMU of `opencrg fmu`, against the plain calls of the C library along
 * the same paths, a contact point or probe per wheel: crgEvalxy2z on a CRG file (the FMU
 * of that file), crgOdrEvalxy on a map with an attached CRG file (the FMU of that map).
 * The road and the map are those `odr_bench wheels DIR` writes (track.crg, track.xodr),
 * their FMUs unpacked into CRG_FMU and MAP_FMU. Prints ns per wheel of each, the four
 * alternating ROUNDS times.
 *
 * usage: fmu_wheels BINARY CRG_FMU MAP_FMU DIR [ROUNDS]
 */
#include "crgBaseLib.h"
#include "crgOdr.h"
#include "fmu_load.h"
#include <time.h>

#define STEPS 45000
#define WHEELS 4

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static struct Fmi2 fmi;
static double x[STEPS][WHEELS], y[STEPS][WHEELS];
static double xc[STEPS][WHEELS], yc[STEPS][WHEELS];

static void *instance(const char *unpacked)
{
    char uri[8192], token[128];
    resource_uri(unpacked, uri, sizeof uri);
    if (!read_token(unpacked, token, sizeof token))
        return NULL;
    void *c = fmi.instantiate("bench", FMI2_CO_SIMULATION, token, uri, NULL, 0, 0);
    if (!c || fmi.setup_experiment(c, 0, 0.0, 0.0, 0, 0.0) || fmi.enter_initialization(c) ||
        fmi.exit_initialization(c))
        return NULL;
    return c;
}

/* ns per wheel of the FMU along the paths (px, py); the heights' sum in *sum. */
static double drive_fmu(void *c, double (*px)[WHEELS], double (*py)[WHEELS], double *sum)
{
    unsigned in[2 * WHEELS], out[WHEELS];
    for (int w = 0; w < WHEELS; w++) {
        in[2 * w] = VR(w + 1, Q_X), in[2 * w + 1] = VR(w + 1, Q_Y), out[w] = VR(w + 1, Q_Z);
    }
    double start = now();
    for (int i = 0; i < STEPS; i++) {
        double at[2 * WHEELS], z[WHEELS];
        for (int w = 0; w < WHEELS; w++)
            at[2 * w] = px[i][w], at[2 * w + 1] = py[i][w];
        fmi.set_real(c, in, 2 * WHEELS, at);
        fmi.get_real(c, out, WHEELS, z);
        for (int w = 0; w < WHEELS; w++)
            *sum += z[w];
    }
    return (now() - start) * 1e9 / (STEPS * WHEELS);
}

int main(int argc, char **argv)
{
    if (argc < 5) {
        fprintf(stderr, "usage: fmu_wheels BINARY CRG_FMU MAP_FMU DIR [ROUNDS]\n");
        return 2;
    }
    int rounds = argc > 5 ? atoi(argv[5]) : 5;
    crgMsgSetLevel(dCrgMsgLevelNone);
    if (!fmi2_load(argv[1], &fmi))
        return 1;
    void *crg_fmu = instance(argv[2]), *map_fmu = instance(argv[3]);
    char path[4096];
    snprintf(path, sizeof path, "%s/track.xodr", argv[4]);
    int map = crgOdrMapLoad(path);
    snprintf(path, sizeof path, "%s/track.crg", argv[4]);
    int data = crgLoaderReadFile(path);
    if (!crg_fmu || !map_fmu || map <= 0 || data <= 0 || !crgCheck(data)) {
        fprintf(stderr, "fmu_wheels: cannot make the FMU instances or read %s\n", argv[4]);
        return 1;
    }
    crgDataSetModifiersApply(data);
    /* The wheels at (0, +-0.8) and (2.7, +-0.8) from the car, 2 cm a step: on the map's
     * road from s = 10 m, on the CRG file (straight along x) from u = 10 m. */
    static const double ds[WHEELS] = {0.0, 0.0, 2.7, 2.7}, t[WHEELS] = {0.8, -0.8, 0.8, -0.8};
    int probes[WHEELS], cps[WHEELS];
    for (int w = 0; w < WHEELS; w++) {
        probes[w] = crgOdrProbeCreate(map);
        cps[w] = crgContactPointCreate(data);
        for (int i = 0; i < STEPS; i++) {
            double z;
            if (!crgOdrEvalst2xyz(probes[w], 0, 10.0 + ds[w] + i * 0.02, t[w], &x[i][w], &y[i][w], &z)) {
                fprintf(stderr, "fmu_wheels: no road at step %d\n", i);
                return 1;
            }
            xc[i][w] = 10.0 + ds[w] + i * 0.02, yc[i][w] = t[w];
        }
    }
    for (int r = 0; r < rounds; r++) {
        double sums[4] = {0, 0, 0, 0};
        double start = now();
        for (int i = 0; i < STEPS; i++)
            for (int w = 0; w < WHEELS; w++) {
                double z;
                if (crgEvalxy2z(cps[w], xc[i][w], yc[i][w], &z))
                    sums[0] += z;
            }
        double plain = (now() - start) * 1e9 / (STEPS * WHEELS);
        double crg = drive_fmu(crg_fmu, xc, yc, &sums[1]);
        start = now();
        for (int i = 0; i < STEPS; i++)
            for (int w = 0; w < WHEELS; w++) {
                double z, friction, s, tt;
                int road, lane;
                if (crgOdrEvalxy(probes[w], x[i][w], y[i][w], &z, &friction, &road, &lane, &s, &tt))
                    sums[2] += z;
            }
        double odr = (now() - start) * 1e9 / (STEPS * WHEELS);
        double fmu_map = drive_fmu(map_fmu, x, y, &sums[3]);
        printf("fmu wheels: %.1f ns per crgEvalxy2z, %.1f ns per wheel through the CRG file's FMU, "
               "%.1f ns per crgOdrEvalxy, %.1f ns per wheel through the map's FMU (sums %.6f %.6f %.6f %.6f)\n",
               plain, crg, odr, fmu_map, sums[0], sums[1], sums[2], sums[3]);
    }
    return 0;
}
