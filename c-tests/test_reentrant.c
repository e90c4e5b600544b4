/*
 * A message callback that calls the library again, on every path that sends a message
 * while the library works on a contact point: a history the system refuses the memory
 * for, on one contact point and on all of them. Each call must return with its messages
 * delivered (the reference library has no locks, so programs doing this work there); a
 * hang is turned into a failure by an alarm.
 *
 * usage: test_reentrant ROAD
 */
#define _GNU_SOURCE
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>
#include "crgBaseLib.h"
#include "check.h"

static int g_cp = -1, g_messages, g_reentered;

/* Logs the message, then uses the library: resets the contact point's options and
 * evaluates on it. */
static int callback(int level, char *text)
{
    double z = 0;
    (void)level;
    (void)text;
    g_messages++;
    crgContactPointSetDefaultOptions(g_cp);
    if (crgEvaluv2z(g_cp, 10.0, 0.5, &z))
        g_reentered++;
    return 0;
}

static void hung(int sig)
{
    (void)sig;
    fprintf(stderr, "test_reentrant: a call did not return within 20 s\n");
    _exit(1);
}

int main(int argc, char **argv)
{
    struct rlimit limit;
    int id, other;
    if (argc < 2) {
        fprintf(stderr, "usage: test_reentrant ROAD\n");
        return 2;
    }
    signal(SIGALRM, hung);
    alarm(20);
    crgMsgSetLevel(dCrgMsgLevelNone);
    id = crgLoaderReadFile(argv[1]);
    CHECK(id > 0 && crgCheck(id));
    crgDataSetModifiersApply(id);
    g_cp = crgContactPointCreate(id);
    other = crgContactPointCreate(id);
    CHECK(g_cp >= 0 && other >= 0);
    /* 2 GB of address space: a history of INT_MAX entries (51 GB) is refused. */
    limit.rlim_cur = 2UL << 30;
    limit.rlim_max = RLIM_INFINITY;
    CHECK(setrlimit(RLIMIT_AS, &limit) == 0);
    crgMsgSetLevel(dCrgMsgLevelWarn);
    crgMsgSetCallback(callback);

    CHECK(crgContactPointSetHistory(g_cp, INT_MAX) == 0);
    CHECK(g_messages >= 1);
    CHECK(g_reentered == g_messages);

    g_messages = g_reentered = 0;
    crgContactPointSetHistoryForAllPoints(INT_MAX);
    CHECK(g_messages >= 2);
    CHECK(g_reentered == g_messages);

    /* The contact points work as before. */
    crgMsgSetCallback(NULL);
    crgMsgSetLevel(dCrgMsgLevelNone);
    {
        double z = 0;
        CHECK(crgEvaluv2z(g_cp, 10.0, 0.5, &z) && crgEvaluv2z(other, 10.0, 0.5, &z));
    }
    crgMemRelease();
    return check_summary("reentrant callback");
}
