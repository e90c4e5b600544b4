/*
 * The differential tester's client: runs a script of classic OpenCRG C API calls and
 * prints every answer, one line per command. It includes only crgBaseLib.h and calls
 * only functions of the classic API, so the same source builds against any library
 * that offers it; the driver builds it twice and compares the two outputs.
 *
 * usage: difftest_client SCRIPT   (run from the folder holding the script's files;
 *        DIFFTEST_MSG_LEVEL=N in the environment shows the library's messages;
 *        DIFFTEST_WARNINGS=1 adds, after load, check and apply, a line saying whether
 *        the library warned and whether it reported an error, its texts unseen)
 *
 * Script commands, one a line (numbers in any form strtod reads):
 *   load FILE           crgLoaderReadFile; the other commands need a data set
 *   check | apply | modrm | modsetdef | optsetdef
 *   modi ID N | modd ID X | modgi ID | modgd ID | modrmid ID
 *   cp | cpdel | hist N | opti ID N | optd ID X | optgi ID | optgd ID | optrm ID | optrmall | cpdef
 *   info                the ranges, increments and closed-track data
 *   q U V               uv2xy, uv2z, uv2pk, then the three x/y calls at the x/y found
 *   qf FU FV            q at fractions of the current u and v ranges
 *   qo FU FV DX DY      uv2xy at fractions, then the x/y calls at x + DX, y + DY
 *   xy X Y              the three x/y calls at (X, Y)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "crgBaseLib.h"

static int gId = 0;
static int gCp = -1;

/* DIFFTEST_WARNINGS: whether a warning and whether an error came since the last report. */
static int gWarnings = 0;
static int gWarned = 0, gFailed = 0;

static int noteLevel(int level, char *message)
{
    (void)message;
    if (level == dCrgMsgLevelWarn)
        gWarned = 1;
    else if (level == dCrgMsgLevelFatal)
        gFailed = 1;
    return 0;
}

static void reportLevels(const char *cmd)
{
    if (gWarnings)
        printf("msgs %s warned %d failed %d\n", cmd, gWarned, gFailed);
    gWarned = gFailed = 0;
}

static void pr(double d)
{
    if (isnan(d))
        printf(" nan");
    else
        printf(" %.17g", d);
}

static void uvCalls(double u, double v)
{
    double x = NAN, y = NAN, z = NAN, phi = NAN, curv = NAN;
    int r1 = crgEvaluv2xy(gCp, u, v, &x, &y);
    int r2 = crgEvaluv2z(gCp, u, v, &z);
    int r3 = crgEvaluv2pk(gCp, u, v, &phi, &curv);
    printf(" | %d", r1); pr(x); pr(y);
    printf(" | %d", r2); pr(z);
    printf(" | %d", r3); pr(phi); pr(curv);
}

static void xyCalls(double x, double y)
{
    double u = NAN, v = NAN, z = NAN, phi = NAN, curv = NAN;
    int r4 = crgEvalxy2uv(gCp, x, y, &u, &v);
    int r5 = crgEvalxy2z(gCp, x, y, &z);
    int r6 = crgEvalxy2pk(gCp, x, y, &phi, &curv);
    printf(" | %d", r4); pr(u); pr(v);
    printf(" | %d", r5); pr(z);
    printf(" | %d", r6); pr(phi); pr(curv);
}

/* u and v at fractions of the data set's current ranges. */
static void fractions(double fu, double fv, double *u, double *v)
{
    double umin = NAN, umax = NAN, vmin = NAN, vmax = NAN;
    crgDataSetGetURange(gId, &umin, &umax);
    crgDataSetGetVRange(gId, &vmin, &vmax);
    *u = umin + fu * (umax - umin);
    *v = vmin + fv * (vmax - vmin);
}

static void query(double u, double v, double dx, double dy)
{
    double x = NAN, y = NAN;
    printf("q"); pr(u); pr(v);
    if (crgEvaluv2xy(gCp, u, v, &x, &y))
    {
        uvCalls(u, v);
        xyCalls(x + dx, y + dy);
    }
    else
    {
        uvCalls(u, v);
        printf(" | x/y skipped");
    }
    printf("\n");
}

static void info(void)
{
    double a = NAN, b = NAN;
    int closed = -1, rc;
    rc = crgDataSetGetURange(gId, &a, &b); printf("urange %d", rc); pr(a); pr(b); printf("\n");
    a = b = NAN;
    rc = crgDataSetGetVRange(gId, &a, &b); printf("vrange %d", rc); pr(a); pr(b); printf("\n");
    a = b = NAN;
    rc = crgDataSetGetIncrements(gId, &a, &b); printf("incs %d", rc); pr(a); pr(b); printf("\n");
    a = b = NAN;
    rc = crgDataSetGetUtilityDataClosedTrack(gId, &closed, &a, &b);
    printf("closed %d %d", rc, closed); pr(a); pr(b); printf("\n");
}

int main(int argc, char **argv)
{
    char line[4096];
    FILE *script;

    if (argc != 2)
    {
        fprintf(stderr, "usage: difftest_client SCRIPT\n");
        return 2;
    }
    script = fopen(argv[1], "r");
    if (!script)
    {
        perror(argv[1]);
        return 2;
    }
    /* DIFFTEST_MSG_LEVEL=N shows the library's messages, to find out why answers differ. */
    setvbuf(stdout, NULL, _IOLBF, 0); /* a hung call shows after the last complete line */
    crgMsgSetLevel(getenv("DIFFTEST_MSG_LEVEL") ? atoi(getenv("DIFFTEST_MSG_LEVEL")) : dCrgMsgLevelNone);
    if (getenv("DIFFTEST_WARNINGS") && !getenv("DIFFTEST_MSG_LEVEL"))
    {
        gWarnings = 1;
        crgMsgSetLevel(dCrgMsgLevelWarn);
        crgMsgSetCallback(noteLevel);
    }
    while (fgets(line, sizeof line, script))
    {
        char cmd[32], arg[4000];
        double a = NAN, b = NAN, c = 0.0, d = 0.0;
        int n = sscanf(line, "%31s", cmd);
        if (n != 1 || cmd[0] == '#')
            continue;
        if (!strcmp(cmd, "load"))
        {
            if (sscanf(line, "%*s %3999s", arg) != 1)
                continue;
            gId = crgLoaderReadFile(arg);
            printf("load %d\n", gId > 0);
            reportLevels("load");
            if (gId <= 0)
                break;
            continue;
        }
        sscanf(line, "%*s %lf %lf %lf %lf", &a, &b, &c, &d);
        if (!strcmp(cmd, "check"))
            printf("check %d\n", crgCheck(gId) ? 1 : 0), reportLevels("check");
        else if (!strcmp(cmd, "apply"))
            crgDataSetModifiersApply(gId), printf("apply\n"), reportLevels("apply");
        else if (!strcmp(cmd, "modrm"))
            printf("modrm %d\n", crgDataSetModifierRemoveAll(gId));
        else if (!strcmp(cmd, "modsetdef"))
            crgDataSetModifierSetDefault(gId), printf("modsetdef\n");
        else if (!strcmp(cmd, "optsetdef"))
            crgDataSetOptionSetDefault(gId), printf("optsetdef\n");
        else if (!strcmp(cmd, "modi"))
            printf("modi %d\n", crgDataSetModifierSetInt(gId, (unsigned)a, (int)b));
        else if (!strcmp(cmd, "modd"))
            printf("modd %d\n", crgDataSetModifierSetDouble(gId, (unsigned)a, b));
        else if (!strcmp(cmd, "modrmid"))
            printf("modrmid %d\n", crgDataSetModifierRemove(gId, (unsigned)a));
        else if (!strcmp(cmd, "modgi"))
        {
            int v = -12345;
            int rc = crgDataSetModifierGetInt(gId, (unsigned)a, &v);
            printf("modgi %g %d %d\n", a, rc, rc ? v : 0);
        }
        else if (!strcmp(cmd, "modgd"))
        {
            double v = -12345.0;
            int rc = crgDataSetModifierGetDouble(gId, (unsigned)a, &v);
            printf("modgd %g %d", a, rc); pr(rc ? v : 0.0); printf("\n");
        }
        else if (!strcmp(cmd, "cp"))
        {
            gCp = crgContactPointCreate(gId);
            printf("cp %d\n", gCp >= 0);
        }
        else if (!strcmp(cmd, "cpdel"))
            printf("cpdel %d\n", crgContactPointDelete(gCp));
        else if (!strcmp(cmd, "hist"))
            printf("hist %d\n", crgContactPointSetHistory(gCp, (int)a));
        else if (!strcmp(cmd, "opti"))
            printf("opti %d\n", crgContactPointOptionSetInt(gCp, (unsigned)a, (int)b));
        else if (!strcmp(cmd, "optd"))
            printf("optd %d\n", crgContactPointOptionSetDouble(gCp, (unsigned)a, b));
        else if (!strcmp(cmd, "optrm"))
            printf("optrm %d\n", crgContactPointOptionRemove(gCp, (unsigned)a));
        else if (!strcmp(cmd, "optrmall"))
            printf("optrmall %d\n", crgContactPointOptionRemoveAll(gCp));
        else if (!strcmp(cmd, "cpdef"))
            crgContactPointSetDefaultOptions(gCp), printf("cpdef\n");
        else if (!strcmp(cmd, "optgi"))
        {
            int v = -12345;
            int rc = crgContactPointOptionGetInt(gCp, (unsigned)a, &v);
            printf("optgi %g %d %d\n", a, rc, rc ? v : 0);
        }
        else if (!strcmp(cmd, "optgd"))
        {
            double v = -12345.0;
            int rc = crgContactPointOptionGetDouble(gCp, (unsigned)a, &v);
            printf("optgd %g %d", a, rc); pr(rc ? v : 0.0); printf("\n");
        }
        else if (!strcmp(cmd, "info"))
            info();
        else if (!strcmp(cmd, "q"))
            query(a, b, 0.0, 0.0);
        else if (!strcmp(cmd, "qf") || !strcmp(cmd, "qo"))
        {
            double u, v;
            fractions(a, b, &u, &v);
            query(u, v, c, d);
        }
        else if (!strcmp(cmd, "xy"))
        {
            printf("xy"); pr(a); pr(b);
            xyCalls(a, b);
            printf("\n");
        }
        else
        {
            fprintf(stderr, "difftest_client: unknown command <%s>\n", cmd);
            return 2;
        }
    }
    fclose(script);
    if (gCp >= 0)
        crgContactPointDelete(gCp);
    if (gId > 0)
        crgDataSetRelease(gId);
    crgMemRelease();
    return 0;
}
