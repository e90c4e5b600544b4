/*
 * A road read in place whose file is cut short while it is open, through the classic API:
 * the process goes on; an elevation in the part cut off is refused (return 0) with a
 * warning that names the file; what was read before the cut still answers as before; the
 * x/y search (the reference line is in memory) goes on. Then the same for a file changed
 * in place (same size, other bytes, a later modification time).
 *
 * Windows refuses to cut short a file this process maps; there the file is cut from
 * outside, as a device that can no longer read it would fail (c-tests/cross/run.sh runs
 * it under wine, whose files are the Linux system's): the program writes COPY.cut and
 * waits until it is gone, and the runner cuts COPY to a third and removes COPY.cut.
 *
 * usage: test_cut_short ROAD COPY   (ROAD any road; COPY a path to write its KRBI copy to;
 *                                   a second copy is written to COPY followed by 2)
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "crgBaseLib.h"
#ifdef _WIN32
#include <windows.h>
#else
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#endif

static char g_messages[1 << 16];

static int collect(int level, char *message)
{
    (void)level;
    if (strlen(g_messages) + strlen(message) + 1 < sizeof g_messages)
        strcat(g_messages, message);
    return 0;
}

static int g_failures;

static void expect(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "test_cut_short: FAILED: %s\n", what);
        g_failures++;
    }
}

#ifdef _WIN32
/* Asks the runner to cut `path` to a third of its size; whether it did within a minute. */
static int cut_short(const char *path)
{
    char request[4096];
    snprintf(request, sizeof request, "%s.cut", path);
    FILE *f = fopen(request, "w");
    if (!f)
        return 0;
    fclose(f);
    for (int i = 0; i < 6000; i++) {
        if (GetFileAttributesA(request) == INVALID_FILE_ATTRIBUTES)
            return 1;
        Sleep(10);
    }
    return 0;
}

static void read_in_place(void) { _putenv_s("OPENCRG_IN_PLACE", "always"); }

static void pause_briefly(void) { Sleep(20); }
#else
/* Cuts `path` to a third of its size; whether it could. */
static int cut_short(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && truncate(path, st.st_size / 3) == 0;
}

static void read_in_place(void) { setenv("OPENCRG_IN_PLACE", "always", 1); }

static void pause_briefly(void)
{
    struct timespec pause = { 0, 20 * 1000 * 1000 };
    nanosleep(&pause, NULL);
}
#endif

/* A contact point on COPY read in place, checked and modified as a vehicle model does. */
static int open_in_place(const char *copy)
{
    int id = crgLoaderReadFile(copy);
    expect(id > 0, "the copy opens");
    crgCheck(id);
    crgDataSetModifiersApply(id);
    return crgContactPointCreate(id);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_cut_short ROAD COPY\n");
        return 2;
    }
    const char *copy = argv[2];
    crgMsgSetLevel(dCrgMsgLevelWarn);
    crgMsgSetCallback(collect);
    int source = crgLoaderReadFile(argv[1]);
    expect(source > 0 && crgDataSetWrite(source, copy, dCrgFormatKRBI), "the KRBI copy is written");
    double umin, umax, vmin, vmax;
    crgDataSetGetURange(source, &umin, &umax);
    crgDataSetGetVRange(source, &vmin, &vmax);
    read_in_place();

    /* Cut short. */
    int cp = open_in_place(copy);
    double early = 0, late = 0, again = 0, u = 0, v = 0, x = 0, y = 0;
    double u_early = umin + 0.05 * (umax - umin), u_late = umin + 0.9 * (umax - umin), v_mid = 0.5 * (vmin + vmax);
    expect(crgEvaluv2z(cp, u_early, v_mid, &early) == 1, "an elevation before the cut");
    expect(cut_short(copy), "the copy is cut short");
    g_messages[0] = 0;
    expect(crgEvaluv2z(cp, u_late, v_mid, &late) == 0, "an elevation in the part cut off is refused");
    expect(strstr(g_messages, copy) != NULL && strstr(g_messages, "cut short") != NULL, "the warning names the file");
    expect(crgEvaluv2xy(cp, u_late, v_mid, &x, &y) == 1, "u/v to x/y goes on (the reference line is in memory)");
    expect(crgEvalxy2z(cp, x, y, &late) == 0, "x/y to z in the part cut off is refused");
    expect(crgEvalxy2uv(cp, x, y, &u, &v) == 1, "x/y to u/v goes on");
    expect(crgEvaluv2z(cp, u_early, v_mid, &again) == 1 && again == early, "what was read before answers as before");

    /* Changed in place: another copy (Windows keeps a file an open road reads from being
     * replaced). */
    char changed[4096];
    snprintf(changed, sizeof changed, "%s2", copy);
    expect(crgDataSetWrite(source, changed, dCrgFormatKRBI), "another copy is written");
    cp = open_in_place(changed);
    expect(crgEvaluv2z(cp, u_early, v_mid, &early) == 1, "an elevation before the change");
    pause_briefly();
    FILE *f = fopen(changed, "r+b");
    expect(f != NULL, "the other copy opens for writing");
    if (f) {
        fseek(f, -100, SEEK_END);
        int c = fgetc(f);
        fseek(f, -100, SEEK_END);
        fputc(c ^ 0x40, f);
        fclose(f);
    }
    g_messages[0] = 0;
    expect(crgEvaluv2z(cp, u_late, v_mid, &late) == 0, "an elevation not read before the change is refused");
    expect(strstr(g_messages, changed) != NULL && strstr(g_messages, "changed") != NULL, "the warning names the file");
    if (g_failures == 0)
        printf("test_cut_short: the process went on; every refusal named the file (%s, %s)\n", copy, changed);
    return g_failures != 0;
}
