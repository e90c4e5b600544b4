/*
 * A small FMI 2 host of the project's own: loads the binary of an FMU written by
 * `opencrg fmu` (on Linux, on Windows under wine, on 64-bit Arm under qemu), instantiates
 * it on an unpacked FMU's resources in co-simulation, and checks wheel 1's height at
 * every point of a file of expected answers, to the bit. With two FMUs, two instances
 * (one per FMU, from the one loaded binary) run at once on two threads and each still
 * gives its own road's answers. Also: a get before initialization and an unknown value
 * reference are refused, a folder without resources fails instantiation with a message
 * naming the file, and the process goes on.
 *
 * usage: fmu_host BINARY UNPACKED POINTS [UNPACKED2 POINTS2]
 * POINTS: lines "x y z" with z as `opencrg eval --xy` or `opencrg odr eval` print it
 * ("nan" where the road gives none: the FMU answers 0 and onRoad false there).
 */
#include "fmu_load.h"
#include <math.h>
#include <pthread.h>

#define MAX_POINTS 4096
#define REPEATS 20

struct Road {
    const char *unpacked;
    char uri[8192], token[128];
    int n;
    double x[MAX_POINTS], y[MAX_POINTS], z[MAX_POINTS];
};

static struct Fmi2 fmi;
static char said[4096];

static void logger(void *env, const char *instance, int status, const char *category, const char *message, ...)
{
    (void)env, (void)instance, (void)status, (void)category;
    snprintf(said, sizeof said, "%s", message);
}

static const Fmi2Callbacks callbacks = {logger, NULL, NULL, NULL, NULL};

static int read_road(struct Road *r, const char *unpacked, const char *points)
{
    r->unpacked = unpacked;
    resource_uri(unpacked, r->uri, sizeof r->uri);
    if (!read_token(unpacked, r->token, sizeof r->token)) {
        fprintf(stderr, "fmu_host: no token in %s/resources\n", unpacked);
        return 0;
    }
    FILE *f = fopen(points, "r");
    if (!f) {
        fprintf(stderr, "fmu_host: cannot read %s\n", points);
        return 0;
    }
    char z[64];
    r->n = 0;
    while (r->n < MAX_POINTS && fscanf(f, "%lf %lf %63s", &r->x[r->n], &r->y[r->n], z) == 3) {
        r->z[r->n] = strcmp(z, "nan") == 0 ? NAN : strtod(z, NULL);
        r->n++;
    }
    fclose(f);
    return r->n > 0;
}

/* An instance on `r`, initialized; NULL (said) when it cannot be made. */
static void *instance(struct Road *r, const char *name)
{
    void *c = fmi.instantiate(name, FMI2_CO_SIMULATION, r->token, r->uri, &callbacks, 0, 0);
    if (!c) {
        fprintf(stderr, "fmu_host: %s: instantiation failed: %s\n", r->unpacked, said);
        return NULL;
    }
    if (fmi.setup_experiment(c, 0, 0.0, 0.0, 0, 0.0) || fmi.enter_initialization(c) || fmi.exit_initialization(c)) {
        fprintf(stderr, "fmu_host: %s: initialization failed\n", r->unpacked);
        return NULL;
    }
    return c;
}

/* Wheel 1 along the road's points, `repeats` times: the number of wrong answers. */
static int drive(struct Fmi2 *f, void *c, const struct Road *r, int repeats)
{
    int wrong = 0;
    const unsigned xy[2] = {VR(1, Q_X), VR(1, Q_Y)}, z_vr = VR(1, Q_Z), on_vr = VR(1, Q_ON_ROAD);
    for (int k = 0; k < repeats; k++) {
        for (int i = 0; i < r->n; i++) {
            double at[2] = {r->x[i], r->y[i]}, z;
            int on;
            if (f->set_real(c, xy, 2, at) || f->do_step(c, i * 0.001, 0.001, 1) || f->get_real(c, &z_vr, 1, &z) ||
                f->get_boolean(c, &on_vr, 1, &on)) {
                wrong++;
                continue;
            }
            int right = isnan(r->z[i]) ? (z == 0.0 && !on) : memcmp(&z, &r->z[i], sizeof z) == 0;
            if (!right && wrong++ < 3)
                fprintf(stderr, "fmu_host: %s: (%.17g, %.17g): z %.17g, expected %.17g\n", r->unpacked, r->x[i],
                        r->y[i], z, r->z[i]);
        }
    }
    return wrong;
}

struct Job {
    struct Road *road;
    int wrong;
};

static void *job(void *arg)
{
    struct Job *j = arg;
    void *c = instance(j->road, "thread");
    j->wrong = c ? drive(&fmi, c, j->road, REPEATS) : -1;
    if (c)
        fmi.free_instance(c);
    return NULL;
}

static struct Road roads[2];

int main(int argc, char **argv)
{
    if (argc != 4 && argc != 6) {
        fprintf(stderr, "usage: fmu_host BINARY UNPACKED POINTS [UNPACKED2 POINTS2]\n");
        return 2;
    }
    if (!fmi2_load(argv[1], &fmi))
        return 1;
    int n = argc == 6 ? 2 : 1;
    for (int k = 0; k < n; k++)
        if (!read_road(&roads[k], argv[2 + 2 * k], argv[3 + 2 * k]))
            return 1;
    int points = 0;
    for (int k = 0; k < n; k++) {
        void *c = instance(&roads[k], "alone");
        if (!c)
            return 1;
        int wrong = drive(&fmi, c, &roads[k], 1);
        if (wrong) {
            fprintf(stderr, "fmu_host: %s: %d of %d points wrong\n", roads[k].unpacked, wrong, roads[k].n);
            return 1;
        }
        points += roads[k].n;
        /* An unknown value reference is refused, with a message. */
        unsigned unknown = 99999;
        double v;
        said[0] = 0;
        if (fmi.get_real(c, &unknown, 1, &v) != 3 || !strstr(said, "99999")) {
            fprintf(stderr, "fmu_host: an unknown value reference was not refused (%s)\n", said);
            return 1;
        }
        fmi.terminate(c);
        fmi.free_instance(c);
    }
    /* Two instances at once, each on its own thread (one per FMU; both on the first with one). */
    struct Job jobs[2] = {{&roads[0], 0}, {&roads[n - 1], 0}};
    pthread_t threads[2];
    for (int k = 0; k < 2; k++)
        pthread_create(&threads[k], NULL, job, &jobs[k]);
    for (int k = 0; k < 2; k++)
        pthread_join(threads[k], NULL);
    for (int k = 0; k < 2; k++)
        if (jobs[k].wrong) {
            fprintf(stderr, "fmu_host: thread %d: %d wrong answers\n", k, jobs[k].wrong);
            return 1;
        }
    /* A get before initialization is refused. */
    void *c = fmi.instantiate("early", FMI2_CO_SIMULATION, roads[0].token, roads[0].uri, &callbacks, 0, 0);
    unsigned z_vr = VR(1, Q_Z);
    double z;
    said[0] = 0;
    if (!c || fmi.get_real(c, &z_vr, 1, &z) != 3 || !strstr(said, "not allowed")) {
        fprintf(stderr, "fmu_host: a get before initialization was not refused (%s)\n", said);
        return 1;
    }
    fmi.free_instance(c);
    /* Resources that are not there: no instance, a message naming the file. */
    static char missing[sizeof roads[0].uri + 16];
    snprintf(missing, sizeof missing, "%s-missing", roads[0].uri);
    said[0] = 0;
    c = fmi.instantiate("missing", FMI2_CO_SIMULATION, roads[0].token, missing, &callbacks, 0, 0);
    if (c || !strstr(said, "opencrg-fmu.txt")) {
        fprintf(stderr, "fmu_host: missing resources not refused as expected (%s)\n", said);
        return 1;
    }
    printf("fmu_host: %d points answered to the bit, two instances on two threads %d times each, refusals said\n",
           points, REPEATS);
    return 0;
}
