/*
 * A program that includes the reference library's private header builds unchanged and
 * runs: the public API (as COVISE's OpenCRGSurface uses it), and the performance
 * statistics of contact points (as ASAM's crgPerfTest and crgMultiCp use them), whose
 * report comes through the message channel at NOTICE level.
 * usage: test_private_header ROAD
 */
#include <stdio.h>
#include <string.h>
#include "crgBaseLibPrivate.h"

#if CRG_BASELIB_PRIVATE_INTERNALS != 0
#error "the private header should say that the reference's internals are not provided"
#endif

static char g_report[4096];
static int g_notices, g_warnings;

static int collect(int level, char *message)
{
    if (level == dCrgMsgLevelNotice) {
        g_notices++;
        strncat(g_report, message, sizeof g_report - strlen(g_report) - 1);
        strncat(g_report, "\n", sizeof g_report - strlen(g_report) - 1);
    } else if (level == dCrgMsgLevelWarn) {
        g_warnings++;
    }
    return 0;
}

static int failures;
static void check(int ok, const char *what)
{
    if (!ok) {
        printf("FAIL: %s\n", what);
        failures++;
    }
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: test_private_header ROAD\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    int id = crgLoaderReadFile(argv[1]);
    if (id <= 0 || !crgCheck(id))
        return 1;
    crgDataSetModifiersApply(id);
    int cp = crgContactPointCreate(id);
    double x = 0, y = 0, z = 0;
    if (cp < 0 || !crgEvaluv2xy(cp, 10.0, 0.5, &x, &y) || !crgEvalxy2z(cp, x, y, &z))
        return 1;
    printf("z at u = 10, v = 0.5: %.6f\n", z);

    /* 1000 evaluations counted, then 500 more not counted. */
    crgMsgSetLevel(dCrgMsgLevelNotice);
    crgMsgSetCallback(collect);
    crgContactPointActivatePerfStat(cp);
    for (int i = 0; i < 1000; i++)
        crgEvalxy2z(cp, x + 0.01 * i, y, &z);
    crgContactPointDeActivatePerfStat(cp);
    for (int i = 0; i < 500; i++)
        crgEvalxy2z(cp, x, y, &z);
    crgContactPointPrintPerfStat(cp);
    printf("%s", g_report);
    check(g_notices >= 3, "the report comes as NOTICE messages");
    check(strstr(g_report, "1000") != NULL && strstr(g_report, "1500") == NULL, "1000 calls counted");
    check(strstr(g_report, "ns") != NULL, "the time per call reported");
    /* An unknown contact point: a warning, no report. */
    g_report[0] = '\0';
    g_notices = 0;
    crgContactPointActivatePerfStat(cp + 1000);
    crgContactPointPrintPerfStat(cp + 1000);
    check(g_warnings == 2 && g_notices == 0, "a warning for an unknown contact point");
    crgMsgSetCallback(NULL);

    crgContactPointDelete(cp);
    crgDataSetRelease(id);
    crgMemRelease();
    printf("private header: %s\n", failures ? "FAILED" : "passed");
    return failures ? 1 : 0;
}
