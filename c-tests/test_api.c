/* Every exported function of the classic API, including bad ids, null pointers
 * and missing files. usage: test_api ROAD.crg TMPDIR [VERSION] */
#include <stdlib.h>
#include <string.h>
#include "crgBaseLib.h"
#include "check.h"

static int g_messages;
static char g_last[2048];

static int on_message(int level, char *message)
{
    (void)level;
    g_messages++;
    strncpy(g_last, message, sizeof g_last - 1);
    return 0;
}

/* A callback that calls the library again, on the ids whose call sent the message. */
static int g_reenter_cp, g_reenter_ds, g_reentries;
static int reentrant(int level, char *message)
{
    double a, b, d;
    (void)level;
    (void)message;
    g_reentries++;
    crgContactPointOptionGetDouble(g_reenter_cp, dCrgCpOptionRefLineClose, &d);
    crgContactPointOptionSetDouble(g_reenter_cp, dCrgCpOptionRefLineClose, 0.3);
    crgDataSetGetURange(g_reenter_ds, &a, &b);
    crgDataSetModifierGetDouble(g_reenter_ds, dCrgModScaleZ, &d);
    return 0;
}

static size_t g_callocs, g_frees;
static void *my_calloc(size_t n, size_t s) { g_callocs++; return calloc(n, s); }
static void *my_realloc(void *p, size_t s) { return realloc(p, s); }
static void my_free(void *p) { g_frees++; free(p); }

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (f) { fputs(text, f); fclose(f); }
}

int main(int argc, char **argv)
{
    const char *road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    const char *tmp = argc > 2 ? argv[2] : "/tmp";
    char path[1024];
    double a = 0, b = 0, x, y, z, u, v, phi, curv, d;
    int id, id2, cp, cp2, i, closed;
    float f;

    /* messages */
    crgMsgSetCallback(on_message);
    crgMsgSetLevel(dCrgMsgLevelDebug);
    crgMsgPrint(dCrgMsgLevelWarn, "value %d and %s\n", 42, "text");
    CHECK(g_messages == 1 && strcmp(g_last, "value 42 and text\n") == 0);
    crgMsgSetLevel(dCrgMsgLevelFatal);
    crgMsgPrint(dCrgMsgLevelWarn, "dropped");
    CHECK(g_messages == 1);
    CHECK(crgMsgIsPrintable(dCrgMsgLevelFatal) == 1);
    CHECK(crgMsgIsPrintable(dCrgMsgLevelNotice) == 0);
    crgMsgSetLevel(99); /* ignored */
    CHECK(crgMsgIsPrintable(dCrgMsgLevelFatal) == 1);
    crgMsgSetMaxLogMsgs(10);
    CHECK(strlen(crgGetReleaseInfo()) > 0);
    /* The version comes from one place (Cargo.toml); CMake passes it here. */
    if (argc > 3)
        CHECK(strstr(crgGetReleaseInfo(), argv[3]) != NULL);

    /* allocator hooks */
    crgCallocSetCallback(my_calloc);
    crgReallocSetCallback(my_realloc);
    crgFreeSetCallback(my_free);
    {
        char *p = crgCalloc(4, 8);
        CHECK(p && p[0] == 0 && g_callocs == 1);
        p = crgRealloc(p, 64);
        CHECK(p != NULL);
        crgFree(p);
        CHECK(g_frees == 1);
    }
    crgCallocSetCallback(NULL);
    crgReallocSetCallback(NULL);
    crgFreeSetCallback(NULL);

    /* NaN helpers (1.2.0 API) */
    d = NAN; f = NAN;
    CHECK(crgIsNan(&d) == 1 && crgIsNanf(&f) == 1);
    d = 1.0; f = 1.0f;
    CHECK(crgIsNan(&d) == 0 && crgIsNanf(&f) == 0 && crgIsNan(NULL) == 0);

    /* loading: missing file, directory, broken file, null name */
    g_messages = 0;
    CHECK(crgLoaderReadFile("no/such/file.crg") == 0);
    CHECK(g_messages == 1 && strstr(g_last, "no/such/file.crg") != NULL);
    crgLoaderSuppressFileNotFoundFatalMsg(true);
    CHECK(crgLoaderReadFile("no/such/file.crg") == 0);
    CHECK(g_messages == 1);
    crgLoaderSuppressFileNotFoundFatalMsg(false);
    CHECK(crgLoaderReadFile(tmp) == 0);
    CHECK(strstr(g_last, "directory") != NULL);
    CHECK(crgLoaderReadFile(NULL) == 0);
    snprintf(path, sizeof path, "%s/opencrg_broken.crg", tmp);
    write_file(path, "$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 0\n$\n$KD_Definition\n#:LRFI\n"
                     "D:long section 1,m\nD:long section 2,m\n$\n$$$$\n 1.0 2.0\n");
    CHECK(crgLoaderReadFile(path) == 0);
    CHECK(strstr(g_last, "REFERENCE_LINE_INCREMENT") != NULL);

    /* a good road */
    id = crgLoaderReadFile(road);
    CHECK(id > 0);
    CHECK(crgCheck(id) == 1);
    CHECK(crgCheck(id + 100) == 0);
    CHECK(crgDataSetGetURange(id, &a, &b) == 1 && a == 0.0 && b == 120.0);
    CHECK(crgDataSetGetVRange(id, &a, &b) == 1 && a == -3.0 && b == 3.0);
    CHECK(crgDataSetGetIncrements(id, &a, &b) == 1 && a == 0.5 && b == 0.25);
    CHECK(crgDataSetGetUtilityDataClosedTrack(id, &closed, &a, &b) == 1 && closed == 0);
    CHECK(crgDataSetGetURange(id + 100, &a, &b) == 0);
    CHECK(crgDataSetGetURange(id, NULL, &b) == 0);
    CHECK(crgDataSetGetVRange(-1, &a, &b) == 0);
    CHECK(crgDataSetGetIncrements(0, &a, &b) == 0);
    CHECK(crgDataSetGetUtilityDataClosedTrack(id, NULL, &a, &b) == 0);

    /* printing goes through the message path */
    crgMsgSetLevel(dCrgMsgLevelNotice);
    g_messages = 0;
    crgDataPrintHeader(id);
    crgDataPrintChannelInfo(id);
    crgDataPrintRoadInfo(id);
    crgDataSetModifiersPrint(id);
    CHECK(g_messages >= 4);
    crgDataPrintHeader(-5); /* unknown id: a warning, no crash */

    /* modifiers */
    CHECK(crgDataSetModifierGetInt(id, dCrgModGridNaNMode, &i) == 1 && i == dCrgGridNaNKeepLast);
    CHECK(crgDataSetModifierSetDouble(id, dCrgModScaleZ, 2.0) == 1);
    CHECK(crgDataSetModifierSetInt(id, dCrgModScaleZ, 2) == 0);            /* wrong type */
    CHECK(crgDataSetModifierSetDouble(id, dCrgCpOptionBorderOffsetU, 1.0) == 0); /* an option id */
    CHECK(crgDataSetModifierSetDouble(id + 100, dCrgModScaleZ, 2.0) == 0);
    CHECK(crgDataSetModifierGetDouble(id, dCrgModScaleZ, &d) == 1 && d == 2.0);
    CHECK(crgDataSetModifierGetDouble(id, dCrgModScaleZ, NULL) == 0);
    /* A getter of the other type reads the set value's other field, 0, as the reference does. */
    i = -1;
    CHECK(crgDataSetModifierGetInt(id, dCrgModScaleZ, &i) == 1 && i == 0);
    d = -1.0;
    CHECK(crgDataSetModifierGetDouble(id, dCrgModGridNaNMode, &d) == 1 && d == 0.0);
    CHECK(crgDataSetModifierRemove(id, dCrgModScaleZ) == 1);
    CHECK(crgDataSetModifierGetDouble(id, dCrgModScaleZ, &d) == 0);
    CHECK(crgDataSetModifierRemove(id, 1000) == 0);
    CHECK(crgDataSetModifierRemoveAll(id) == 1);
    CHECK(crgDataSetModifierGetInt(id, dCrgModGridNaNMode, &i) == 0);
    crgDataSetModifierSetDefault(id);
    CHECK(crgDataSetModifierGetDouble(id, dCrgModRefPointX, &d) == 1 && d == 0.0);
    crgDataSetOptionSetDefault(id);
    crgDataSetModifiersApply(id);
    crgDataSetModifiersApply(id + 100);

    /* contact points and options */
    cp = crgContactPointCreate(id);
    CHECK(cp >= 0);
    CHECK(crgContactPointCreate(id + 100) == -1);
    CHECK(crgContactPointOptionGetInt(cp, dCrgCpOptionBorderModeU, &i) == 1 && i == dCrgBorderModeExKeep);
    CHECK(crgContactPointOptionSetInt(cp, dCrgCpOptionBorderModeU, dCrgBorderModeNone) == 1);
    CHECK(crgContactPointOptionSetDouble(cp, dCrgCpOptionBorderModeU, 1.0) == 0);   /* wrong type */
    CHECK(crgContactPointOptionSetDouble(cp, dCrgModScaleZ, 1.0) == 0);             /* a modifier id */
    CHECK(crgContactPointOptionSetDouble(cp, dCrgCpOptionSmoothUBegin, -1.0) == 0); /* must be > 0 */
    CHECK(crgContactPointOptionSetDouble(cp, dCrgCpOptionBorderOffsetV, 0.5) == 1);
    CHECK(crgContactPointOptionGetDouble(cp, dCrgCpOptionBorderOffsetV, &d) == 1 && d == 0.5);
    CHECK(crgContactPointOptionGetDouble(cp, dCrgCpOptionBorderOffsetV, NULL) == 0);
    d = -1.0;
    CHECK(crgContactPointOptionGetDouble(cp, dCrgCpOptionBorderModeU, &d) == 1 && d == 0.0);
    CHECK(crgContactPointOptionSetInt(cp + 100, dCrgCpOptionBorderModeU, 1) == 0);
    /* A choice out of range is kept, as the reference keeps it, with the warning whose
       text the other bindings refuse it with. */
    g_messages = 0;
    CHECK(crgContactPointOptionSetInt(cp, dCrgCpOptionBorderModeV, 99) == 1);
    CHECK(g_messages == 1 && strstr(g_last, "<border mode v> = 99 is not one of its choices 0 to 4") != NULL);
    CHECK(crgContactPointOptionGetInt(cp, dCrgCpOptionBorderModeV, &i) == 1 && i == 99);
    CHECK(crgContactPointOptionSetInt(cp, dCrgCpOptionBorderModeV, dCrgBorderModeExKeep) == 1 && g_messages == 1);
    CHECK(crgContactPointOptionGetInt(-1, dCrgCpOptionBorderModeU, &i) == 0);
    g_messages = 0;
    crgContactPointOptionsPrint(cp);
    CHECK(g_messages > 0);

    /* evaluation */
    CHECK(crgEvaluv2xy(cp, 50.0, 1.0, &x, &y) == 1);
    CHECK(crgEvalxy2uv(cp, x, y, &u, &v) == 1);
    CHECK_NEAR(u, 50.0, 1e-9);
    CHECK_NEAR(v, 1.0, 1e-9);
    CHECK(crgEvaluv2z(cp, 50.0, 1.0, &z) == 1);
    CHECK(crgEvalxy2z(cp, x, y, &d) == 1);
    CHECK_NEAR(d, z, 1e-9);
    CHECK(crgEvaluv2pk(cp, 50.0, 1.0, &phi, &curv) == 1);
    CHECK(crgEvalxy2pk(cp, x, y, &a, &b) == 1);
    CHECK_NEAR(a, phi, 1e-12);
    CHECK(crgEvaluv2z(cp, -10.0, 0.0, &z) == 0);   /* border mode none refuses */
    CHECK(crgEvaluv2z(cp, 50.0, 100.0, &z) == 1);   /* v keeps the last value, plus offset */
    CHECK(crgEvaluv2z(cp, NAN, 0.0, &z) == 0);
    CHECK(crgEvaluv2z(cp, 1.0, 1.0, NULL) == 0);
    CHECK(crgEvaluv2xy(cp, 1.0, 1.0, NULL, &y) == 0);
    CHECK(crgEvalxy2uv(cp, 1.0, 1.0, &u, NULL) == 0);
    CHECK(crgEvaluv2pk(cp + 100, 1.0, 1.0, &phi, &curv) == 0);
    CHECK(crgEvalxy2z(-3, 1.0, 1.0, &z) == 0);
    CHECK(crgEvalxy2pk(cp, 1.0, 1.0, NULL, &curv) == 0);
    CHECK(crgContactPointOptionRemove(cp, dCrgCpOptionBorderModeU) == 1);
    CHECK(crgContactPointOptionGetInt(cp, dCrgCpOptionBorderModeU, &i) == 0);
    CHECK(crgContactPointOptionRemoveAll(cp) == 1);
    crgContactPointSetDefaultOptions(cp);
    CHECK(crgContactPointOptionGetDouble(cp, dCrgCpOptionRefLineFar, &d) == 1 && d == 2.2);
    CHECK(crgEvaluv2z(cp, -10.0, 0.0, &z) == 1);    /* default: keep the last value */

    /* history */
    CHECK(crgContactPointSetHistory(cp, 5) == 1);
    CHECK(crgContactPointSetHistory(cp, -1) == 0);
    CHECK(crgContactPointSetHistory(cp + 100, 5) == 0);
    crgContactPointSetHistoryForAllPoints(20);
    CHECK(crgContactPointOptionSetDouble(cp, dCrgCpOptionRefLineSearchUFrac, 0.5) == 1);
    CHECK(crgContactPointOptionSetDouble(cp, dCrgCpOptionRefLineSearchU, 10.0) == 1);
    CHECK(crgEvalxy2uv(cp, x, y, &u, &v) == 1);
    CHECK_NEAR(u, 50.0, 1e-9);

    /* a second data set and contact point; releasing */
    id2 = crgLoaderReadFile(road);
    CHECK(id2 > id);
    cp2 = crgContactPointCreate(id2);
    CHECK(cp2 >= 0 && cp2 != cp);
    CHECK(crgContactPointDelete(cp2) == 1);
    CHECK(crgContactPointDelete(cp2) == 0);
    cp2 = crgContactPointCreate(id2);
    crgContactPointDeleteAll(id2);
    CHECK(crgEvaluv2z(cp2, 1.0, 0.0, &z) == 0);
    CHECK(crgEvaluv2z(cp, 1.0, 0.0, &z) == 1);
    CHECK(crgDataSetRelease(id2) == 1);
    CHECK(crgDataSetRelease(id2) == 0);
    crgContactPointDeleteAll(-1);
    CHECK(crgEvaluv2z(cp, 1.0, 0.0, &z) == 0);
    crgMemRelease();
    CHECK(crgDataSetGetURange(id, &a, &b) == 0);
    crgMemRelease(); /* twice is fine */

    /* messages sent while a call works on a contact point or a data set reach a
     * callback that may call the library on the same ids (no deadlock) */
    g_reenter_ds = crgLoaderReadFile(road);
    g_reenter_cp = crgContactPointCreate(g_reenter_ds);
    CHECK(g_reenter_ds > 0 && g_reenter_cp >= 0);
    crgMsgSetLevel(dCrgMsgLevelNotice);
    crgMsgSetCallback(reentrant);
    CHECK(crgContactPointOptionSetDouble(g_reenter_cp, dCrgCpOptionBorderModeU, 1.0) == 0);
    CHECK(g_reentries == 1);
    crgContactPointOptionsPrint(g_reenter_cp);
    CHECK(g_reentries > 1);
    i = g_reentries;
    crgDataPrintHeader(g_reenter_ds);
    crgDataSetModifiersPrint(g_reenter_ds);
    CHECK(crgDataSetModifierSetInt(g_reenter_ds, 99999, 1) == 0);
    CHECK(g_reentries >= i + 3);
    crgMsgSetCallback(NULL);
    crgMemRelease();

    /* the warning budget */
    crgMsgSetCallback(NULL);
    crgMsgSetMaxWarnMsgs(0);
    CHECK(crgMsgIsPrintable(dCrgMsgLevelFatal) == 0);
    crgMsgSetMaxWarnMsgs(-1);
    crgMsgSetLevel(dCrgMsgLevelNone);
    return check_summary("test_api");
}
