/*
 * A road read in place whose file is cut short while it is open, through the classic API:
 * the process goes on; an elevation in the part cut off is refused (return 0) with a
 * warning that names the file; what was read before the cut still answers as before; the
 * x/y search (the reference line is in memory) goes on. Then the same for a file changed
 * in place (same size, other bytes, a later modification time).
 *
 * usage: test_cut_short ROAD COPY   (ROAD any road; COPY a path to write its KRBI copy to)
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "crgBaseLib.h"

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
    setenv("OPENCRG_IN_PLACE", "always", 1);

    /* Cut short. */
    int cp = open_in_place(copy);
    double early = 0, late = 0, again = 0, u = 0, v = 0, x = 0, y = 0;
    double u_early = umin + 0.05 * (umax - umin), u_late = umin + 0.9 * (umax - umin), v_mid = 0.5 * (vmin + vmax);
    expect(crgEvaluv2z(cp, u_early, v_mid, &early) == 1, "an elevation before the cut");
    struct stat st;
    stat(copy, &st);
    expect(truncate(copy, st.st_size / 3) == 0, "the copy is cut short");
    g_messages[0] = 0;
    expect(crgEvaluv2z(cp, u_late, v_mid, &late) == 0, "an elevation in the part cut off is refused");
    expect(strstr(g_messages, copy) != NULL && strstr(g_messages, "cut short") != NULL, "the warning names the file");
    expect(crgEvaluv2xy(cp, u_late, v_mid, &x, &y) == 1, "u/v to x/y goes on (the reference line is in memory)");
    expect(crgEvalxy2z(cp, x, y, &late) == 0, "x/y to z in the part cut off is refused");
    expect(crgEvalxy2uv(cp, x, y, &u, &v) == 1, "x/y to u/v goes on");
    expect(crgEvaluv2z(cp, u_early, v_mid, &again) == 1 && again == early, "what was read before answers as before");

    /* Changed in place. */
    expect(crgDataSetWrite(source, copy, dCrgFormatKRBI), "the copy is written again");
    cp = open_in_place(copy);
    expect(crgEvaluv2z(cp, u_early, v_mid, &early) == 1, "an elevation before the change");
    struct timespec pause = { 0, 20 * 1000 * 1000 };
    nanosleep(&pause, NULL);
    FILE *f = fopen(copy, "r+b");
    expect(f != NULL, "the copy opens for writing");
    if (f) {
        fseek(f, -100, SEEK_END);
        int c = fgetc(f);
        fseek(f, -100, SEEK_END);
        fputc(c ^ 0x40, f);
        fclose(f);
    }
    g_messages[0] = 0;
    expect(crgEvaluv2z(cp, u_late, v_mid, &late) == 0, "an elevation not read before the change is refused");
    expect(strstr(g_messages, copy) != NULL && strstr(g_messages, "changed") != NULL, "the warning names the file");
    if (g_failures == 0)
        printf("test_cut_short: the process went on; every refusal named %s\n", copy);
    return g_failures != 0;
}
