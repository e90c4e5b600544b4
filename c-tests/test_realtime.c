/*
 * Evaluation makes no heap allocation and no system call once a contact point exists, so
 * a real-time program (a vehicle model at 1 kHz, hardware in the loop) may call it from
 * its loop.
 *
 * A child process creates its contact points, then forbids itself every system call but
 * the two that end it (a seccomp filter: any other call traps, and the trap reports the
 * call's number and ends the child) and counts
 * every call of malloc, calloc, realloc, free and the aligned allocators (this program
 * defines them, so the library's calls land here). Then it evaluates: every classic call,
 * the normals and the batches, along a wheel's path and at random points on and off the
 * road, a short run and a long one, then the same on two threads at once, each with
 * contact points of its own. With SCRATCH_DIR, the same holds for OpenDRIVE maps
 * (crgOdr.h): a map written there lays ROAD on a curved road, and each car's wheels also
 * ask their probes for the ground, the normal and road coordinates, on the road and off
 * it. It reports through memory shared with the parent and ends with exit(2). The parent
 * checks that it ended normally with no allocation counted.
 *
 * usage: test_realtime ROAD [CALLS [SCRATCH_DIR]]   (CALLS per kind in the long run,
 * default 200000)
 */
#define _GNU_SOURCE
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>
#include <limits.h>
#include "crgBaseLib.h"
#include "crgOdr.h"

#if defined(__x86_64__)
#define THIS_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define THIS_ARCH AUDIT_ARCH_AARCH64
#else
#error "test_realtime: no seccomp architecture for this processor"
#endif

/* ---------------------------------------------------------------- allocation count */

extern void *__libc_malloc(size_t);
extern void *__libc_calloc(size_t, size_t);
extern void *__libc_realloc(void *, size_t);
extern void __libc_free(void *);
extern void *__libc_memalign(size_t, size_t);

static atomic_int g_counting;
static atomic_long g_allocations;

static void count(void)
{
    if (atomic_load_explicit(&g_counting, memory_order_relaxed))
        atomic_fetch_add_explicit(&g_allocations, 1, memory_order_relaxed);
}

void *malloc(size_t n) { count(); return __libc_malloc(n); }
void *calloc(size_t n, size_t size) { count(); return __libc_calloc(n, size); }
void *realloc(void *p, size_t n) { count(); return __libc_realloc(p, n); }
void free(void *p) { if (p) count(); __libc_free(p); }
void *memalign(size_t align, size_t n) { count(); return __libc_memalign(align, n); }
void *aligned_alloc(size_t align, size_t n) { count(); return __libc_memalign(align, n); }
int posix_memalign(void **out, size_t align, size_t n)
{
    count();
    void *p = __libc_memalign(align, n);
    if (!p)
        return 12; /* ENOMEM */
    *out = p;
    return 0;
}

/* ---------------------------------------------------------------- no system call */

/* What the child reports. */
struct Report {
    long calls;      /* evaluation calls made under the filter */
    long map_hits;   /* OpenDRIVE queries that found the road */
    long allocations;
    double sink;     /* the answers, summed, so nothing is left out */
    int filtered;    /* the filter was installed */
    int finished;    /* the child got through all of it */
    int syscall;     /* the number of the forbidden system call made, or -1 */
};
static struct Report *g_report;

/* A forbidden system call: its number into the report, and the end. */
static void on_sigsys(int sig, siginfo_t *info, void *context)
{
    (void)sig;
    (void)context;
    g_report->allocations = atomic_load(&g_allocations);
    g_report->syscall = info->si_syscall;
    syscall(SYS_exit_group, 4);
}

/* Every system call but exit and exit_group ends the process (through on_sigsys), on
 * every thread. */
static int forbid_system_calls(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_sigaction = on_sigsys;
    action.sa_flags = SA_SIGINFO;
    if (sigaction(SIGSYS, &action, NULL) != 0)
        return 0;
    struct sock_filter filter[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, THIS_ARCH, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_KILL_PROCESS),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_exit, 2, 0),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, SYS_exit_group, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_TRAP),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    struct sock_fprog program = { sizeof filter / sizeof filter[0], filter };
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
        return 0;
    return syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, SECCOMP_FILTER_FLAG_TSYNC, &program) == 0;
}

/* ---------------------------------------------------------------- the evaluation */

#define WHEELS 4
#define BATCH 64

static int g_data;
static double g_umin, g_umax, g_vmin, g_vmax;
/* The OpenDRIVE map (0 without one) and the length of its road. */
static int g_map;
static double g_map_length;

/* A small generator, the same on every run. */
static unsigned long long next(unsigned long long *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    return *state;
}

static double unit(unsigned long long *state) { return (next(state) >> 11) * (1.0 / 9007199254740992.0); }

/* A car's contact points: one per wheel and one shared by all; a probe per wheel on the
 * map, when there is one. */
struct Car {
    int cp[WHEELS];
    int shared;
    int probe[WHEELS];
    double start;
    long calls;
    long map_hits;
    long per_kind;
    double sink;
    unsigned long long seed;
    atomic_int ready, go, done;
};

static void make_car(struct Car *car, double start, long per_kind, unsigned long long seed)
{
    memset(car, 0, sizeof *car);
    for (int w = 0; w < WHEELS; w++)
        car->cp[w] = crgContactPointCreate(g_data);
    car->shared = crgContactPointCreate(g_data);
    for (int w = 0; w < WHEELS; w++)
        car->probe[w] = g_map ? crgOdrProbeCreate(g_map) : -1;
    car->start = start;
    car->per_kind = per_kind;
    car->seed = seed;
}

/* Every classic evaluation at (u, v) and its x/y, on contact point cp. */
static void evaluate(struct Car *car, int cp, double u, double v)
{
    double x = 0, y = 0, a = 0, b = 0, z = 0, n[3] = { 0, 0, 0 };
    crgEvaluv2xy(cp, u, v, &x, &y);
    crgEvalxy2z(cp, x, y, &z);
    car->sink += z;
    crgEvalxy2uv(cp, x, y, &a, &b);
    car->sink += a + b;
    crgEvalxy2pk(cp, x, y, &a, &b);
    car->sink += a + b;
    crgEvaluv2z(cp, u, v, &z);
    car->sink += z;
    crgEvaluv2pk(cp, u, v, &a, &b);
    car->sink += a + b;
    crgEvaluv2zn(cp, u, v, &z, &n[0], &n[1], &n[2]);
    crgEvalxy2zn(cp, x, y, &z, &n[0], &n[1], &n[2]);
    car->sink += z + n[2];
    car->calls += 9;
}

/* Every OpenDRIVE query of a wheel at (s, t) of the map's road, on its probe. */
static void probe_ground(struct Car *car, int probe, double s, double t)
{
    double x = 0, y = 0, z = 0, mu = 0, ss = 0, tt = 0, n[3] = { 0, 0, 0 };
    int road = 0, lane = 0;
    crgOdrEvalst2xyz(probe, 0, s, t, &x, &y, &z);
    car->map_hits += crgOdrEvalxy(probe, x, y, &z, &mu, &road, &lane, &ss, &tt);
    car->sink += z + ss + tt;
    crgOdrEvalxy2normal(probe, x, y, &n[0], &n[1], &n[2]);
    car->sink += n[2];
    car->calls += 3;
}

/* Drives the car along the road (every wheel, then the shared contact point), then
 * random points on and around the road, then the batches; on the map, its wheels along
 * the road and at random points on and off it. */
static void drive(struct Car *car)
{
    if (g_map) {
        for (long k = 0; k < car->per_kind; k++) {
            double s = fmod(car->start + 0.02 * (double)k, g_map_length - 4.0);
            for (int w = 0; w < WHEELS; w++)
                probe_ground(car, car->probe[w], s + (w < 2 ? 2.6 : 0.0), w % 2 ? -0.8 : 0.8);
        }
        for (long k = 0; k < car->per_kind / 4; k++) {
            double x = -20.0 + (g_map_length + 40.0) * unit(&car->seed);
            double y = -30.0 + 60.0 * unit(&car->seed);
            double z, mu, s, t;
            int road, lane;
            crgOdrEvalxy(car->probe[k % WHEELS], x, y, &z, &mu, &road, &lane, &s, &t);
            car->calls += 1;
        }
    }
    double length = g_umax - g_umin, width = g_vmax - g_vmin;
    for (long k = 0; k < car->per_kind; k++) {
        double u = g_umin + fmod(car->start + 0.03 * (double)k, length);
        double v = 0.3 * sin(u / 10.0);
        for (int w = 0; w < WHEELS; w++)
            evaluate(car, car->cp[w], u + (w < 2 ? 2.6 : 0.0), v + (w % 2 ? -0.8 : 0.8));
        evaluate(car, car->shared, u, v);
    }
    for (long k = 0; k < car->per_kind / 4; k++) {
        double u = g_umin - 0.2 * length + 1.4 * length * unit(&car->seed);
        double v = g_vmin - 0.5 * width + 2.0 * width * unit(&car->seed);
        evaluate(car, car->cp[k % WHEELS], u, v);
    }
    double u[BATCH], v[BATCH], x[BATCH], y[BATCH], p[BATCH], q[BATCH];
    for (long k = 0; k < car->per_kind / BATCH + 1; k++) {
        for (int i = 0; i < BATCH; i++) {
            u[i] = g_umin + length * unit(&car->seed);
            v[i] = g_vmin + width * unit(&car->seed);
        }
        int cp = car->cp[k % WHEELS];
        crgEvaluv2xyN(cp, BATCH, u, v, x, y);
        crgEvaluv2zN(cp, BATCH, u, v, p);
        crgEvaluv2pkN(cp, BATCH, u, v, p, q);
        crgEvalxy2uvN(cp, BATCH, x, y, p, q);
        crgEvalxy2zN(cp, BATCH, x, y, p);
        crgEvalxy2pkN(cp, BATCH, x, y, p, q);
        car->sink += p[0] + q[BATCH - 1];
        car->calls += 6;
    }
}

static void *car_thread(void *arg)
{
    struct Car *car = arg;
    atomic_store(&car->ready, 1);
    while (!atomic_load(&car->go))
        ;
    drive(car);
    atomic_store(&car->done, 1);
    /* Ending a thread makes system calls: stay until the process ends. */
    for (;;)
        ;
    return NULL;
}

/* Writes a map into `folder` that lays `road` (attached) on a road of a line, a spiral
 * and an arc, superelevated, with lanes of a material, and loads it. */
static int load_map(const char *road, const char *folder)
{
    char path[4096], whole[PATH_MAX];
    if (!realpath(road, whole))
        return 0;
    snprintf(path, sizeof path, "%s/realtime_map.xodr", folder);
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    /* The arc starts where the spiral (curvature 0 to 0.01 over 50 m) ends. */
    double length = 200.0;
    double sx = 0.0, sy = 0.0;
    for (int i = 0; i < 100000; i++) {
        double s = 50.0 * (i + 0.5) / 100000.0, a = 0.01 * s * s / 100.0;
        sx += cos(a) * 50.0 / 100000.0;
        sy += sin(a) * 50.0 / 100000.0;
    }
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<OpenDRIVE><header revMajor=\"1\" revMinor=\"8\"/>\n"
            "<road id=\"r\" length=\"%.17g\" junction=\"-1\"><planView>\n"
            "<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"50\"><line/></geometry>\n"
            "<geometry s=\"50\" x=\"50\" y=\"0\" hdg=\"0\" length=\"50\"><spiral curvStart=\"0\" curvEnd=\"0.01\"/></geometry>\n"
            "<geometry s=\"100\" x=\"%.17g\" y=\"%.17g\" hdg=\"0.25\" length=\"100\"><arc curvature=\"0.01\"/></geometry>\n"
            "</planView>\n"
            "<elevationProfile><elevation s=\"0\" a=\"3\" b=\"0.01\" c=\"0\" d=\"0\"/></elevationProfile>\n"
            "<lateralProfile><superelevation s=\"0\" a=\"0.02\" b=\"0\" c=\"0\" d=\"0\"/></lateralProfile>\n"
            "<lanes><laneSection s=\"0\">\n"
            "<left><lane id=\"1\" type=\"driving\"><width sOffset=\"0\" a=\"3.5\" b=\"0\" c=\"0\" d=\"0\"/>"
            "<material sOffset=\"0\" friction=\"0.8\"/></lane></left>\n"
            "<center><lane id=\"0\" type=\"none\"/></center>\n"
            "<right><lane id=\"-1\" type=\"driving\"><width sOffset=\"0\" a=\"3.5\" b=\"0\" c=\"0\" d=\"0\"/>"
            "</lane></right>\n</laneSection></lanes>\n"
            "<surface><CRG file=\"%s\" sStart=\"0\" sEnd=\"%.17g\" mode=\"attached\" orientation=\"same\"/></surface>\n"
            "</road></OpenDRIVE>\n",
            length, 50.0 + sx, sy, whole, length);
    fclose(f);
    g_map = crgOdrMapLoad(path);
    g_map_length = length;
    if (g_map <= 0) {
        fprintf(stderr, "cannot load the map %s\n", path);
        return 0;
    }
    return 1;
}

/* The child: contact points first, then the filter and the count, then the evaluation. */
static void child(struct Report *report, long calls)
{
    struct Car short_run, long_run, threaded[2];
    pthread_t threads[2];
    make_car(&short_run, 1.0, 1000, 1);
    make_car(&long_run, 5.0, calls, 2);
    for (int t = 0; t < 2; t++) {
        make_car(&threaded[t], 7.0 + 40.0 * t, calls / 4, 3 + (unsigned long long)t);
        if (pthread_create(&threads[t], NULL, car_thread, &threaded[t]) != 0)
            syscall(SYS_exit, 3);
    }
    /* The threads' own start makes system calls: wait until they run. */
    for (int t = 0; t < 2; t++)
        while (!atomic_load(&threaded[t].ready))
            ;
    report->filtered = forbid_system_calls();
    if (!report->filtered)
        syscall(SYS_exit_group, 2);
    atomic_store(&g_counting, 1);
    drive(&short_run);
    drive(&long_run);
    for (int t = 0; t < 2; t++)
        atomic_store(&threaded[t].go, 1);
    for (int t = 0; t < 2; t++)
        while (!atomic_load(&threaded[t].done))
            ;
    atomic_store(&g_counting, 0);
    report->allocations = atomic_load(&g_allocations);
    report->calls = short_run.calls + long_run.calls + threaded[0].calls + threaded[1].calls;
    report->map_hits = short_run.map_hits + long_run.map_hits + threaded[0].map_hits + threaded[1].map_hits;
    report->sink = short_run.sink + long_run.sink + threaded[0].sink + threaded[1].sink;
    report->finished = 1;
    syscall(SYS_exit_group, 0);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_realtime ROAD [CALLS [SCRATCH_DIR]]\n");
        return 2;
    }
    long calls = argc > 2 ? atol(argv[2]) : 200000;
    g_data = crgLoaderReadFile(argv[1]);
    if (g_data <= 0 || !crgCheck(g_data)) {
        fprintf(stderr, "cannot load %s\n", argv[1]);
        return 1;
    }
    crgDataSetModifiersApply(g_data);
    /* The count sees the library's own allocations (creating a contact point allocates). */
    atomic_store(&g_counting, 1);
    int probe = crgContactPointCreate(g_data);
    atomic_store(&g_counting, 0);
    if (probe < 0 || atomic_exchange(&g_allocations, 0) == 0) {
        printf("FAIL: the library's allocations do not reach this program's malloc: nothing would be counted\n");
        return 1;
    }
    crgContactPointDelete(probe);
    crgDataSetGetURange(g_data, &g_umin, &g_umax);
    crgDataSetGetVRange(g_data, &g_vmin, &g_vmax);
    if (argc > 3 && !load_map(argv[1], argv[3]))
        return 1;
    struct Report *report = mmap(NULL, sizeof *report, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (report == MAP_FAILED)
        return 1;
    memset(report, 0, sizeof *report);
    report->syscall = -1;
    g_report = report;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0)
        child(report, calls);
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) != pid)
        return 1;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 2 && !report->filtered) {
        printf("seccomp filters are refused here: system calls NOT checked\n");
        return 77;
    }
    if (report->syscall >= 0) {
        printf("FAIL: the evaluation made system call %d (allocations counted before it: %ld)\n", report->syscall,
               report->allocations);
        return 1;
    }
    if (WIFSIGNALED(status)) {
        printf("FAIL: the evaluation was killed by signal %d%s after %s\n", WTERMSIG(status),
               WTERMSIG(status) == 31 ? " (SIGSYS: a system call)" : "", report->finished ? "finishing" : "starting");
        return 1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !report->finished) {
        printf("FAIL: the evaluation ended with status %d before finishing\n", status);
        return 1;
    }
    printf("%ld evaluation calls on 2 threads and alone (%ld OpenDRIVE grounds found): %ld allocations, no system "
           "call (sum %g)\n",
           report->calls, report->map_hits, report->allocations, report->sink);
    if (g_map && report->map_hits < 100000) {
        printf("FAIL: the wheels found the map's road %ld times\n", report->map_hits);
        return 1;
    }
    if (report->allocations != 0) {
        printf("FAIL: evaluation allocated memory\n");
        return 1;
    }
    crgMemRelease();
    return 0;
}
