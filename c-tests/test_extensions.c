/* The extensions: batches equal the classic calls bit for bit (random points inside
 * and outside, every border mode in u and v, x/y calls with their search history), and
 * the raw data equal the evaluation at the grid nodes.
 * usage: test_extensions ROAD.crg TMPDIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "crgBaseLib.h"
#include "check.h"

#define N 2000

static double g_u[N], g_v[N];

static int same(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* Random points reaching past every border, a few of them exactly on it. */
static void points(int dataSet)
{
    double u0, u1, v0, v1;
    int i;
    crgDataSetGetURange(dataSet, &u0, &u1);
    crgDataSetGetVRange(dataSet, &v0, &v1);
    srand(12345);
    for (i = 0; i < N; i++) {
        g_u[i] = u0 - 0.3 * (u1 - u0) + 1.6 * (u1 - u0) * rand() / (double)RAND_MAX;
        g_v[i] = v0 - 0.5 * (v1 - v0) + 2.0 * (v1 - v0) * rand() / (double)RAND_MAX;
    }
    g_u[0] = u0;
    g_v[1] = v1;
    g_u[2] = u1;
    g_v[3] = v0;
}

/* One contact point for the classic calls, one for the batches, with the same options. */
static void compare_batches(int dataSet, int modeU, int modeV)
{
    static double a[N], b[N], c[N], d[N], x[N], y[N];
    int single = crgContactPointCreate(dataSet), many = crgContactPointCreate(dataSet);
    int i, ok, expected, bad = 0;
    crgContactPointOptionSetInt(single, dCrgCpOptionBorderModeU, modeU);
    crgContactPointOptionSetInt(single, dCrgCpOptionBorderModeV, modeV);
    crgContactPointOptionSetInt(many, dCrgCpOptionBorderModeU, modeU);
    crgContactPointOptionSetInt(many, dCrgCpOptionBorderModeV, modeV);

    /* u/v to z */
    ok = crgEvaluv2zN(many, N, g_u, g_v, a);
    for (i = 0, expected = 0; i < N; i++) {
        double z = 0.0;
        if (crgEvaluv2z(single, g_u[i], g_v[i], &z)) { expected++; bad += !same(z, a[i]); }
        else bad += !isnan(a[i]);
    }
    CHECK(ok == expected && bad == 0);
    /* u/v to x/y, and u/v to heading and curvature */
    ok = crgEvaluv2xyN(many, N, g_u, g_v, x, y);
    for (i = 0, expected = 0, bad = 0; i < N; i++) {
        double p = 0, q = 0;
        if (crgEvaluv2xy(single, g_u[i], g_v[i], &p, &q)) { expected++; bad += !same(p, x[i]) || !same(q, y[i]); }
    }
    CHECK(ok == expected && bad == 0);
    ok = crgEvaluv2pkN(many, N, g_u, g_v, a, b);
    for (i = 0, expected = 0, bad = 0; i < N; i++) {
        double p = 0, q = 0;
        if (crgEvaluv2pk(single, g_u[i], g_v[i], &p, &q)) { expected++; bad += !same(p, a[i]) || !same(q, b[i]); }
    }
    CHECK(ok == expected && bad == 0);
    /* x/y calls, in the same order on both contact points: the histories stay alike. */
    ok = crgEvalxy2uvN(many, N, x, y, a, b);
    for (i = 0, expected = 0, bad = 0; i < N; i++) {
        double p = 0, q = 0;
        if (crgEvalxy2uv(single, x[i], y[i], &p, &q)) { expected++; bad += !same(p, a[i]) || !same(q, b[i]); }
        else bad += !isnan(a[i]);
    }
    CHECK(ok == expected && bad == 0);
    ok = crgEvalxy2zN(many, N, x, y, c);
    for (i = 0, expected = 0, bad = 0; i < N; i++) {
        double z = 0;
        if (crgEvalxy2z(single, x[i], y[i], &z)) { expected++; bad += !same(z, c[i]); }
        else bad += !isnan(c[i]);
    }
    CHECK(ok == expected && bad == 0);
    ok = crgEvalxy2pkN(many, N, x, y, c, d);
    for (i = 0, expected = 0, bad = 0; i < N; i++) {
        double p = 0, q = 0;
        if (crgEvalxy2pk(single, x[i], y[i], &p, &q)) { expected++; bad += !same(p, c[i]) || !same(q, d[i]); }
    }
    CHECK(ok == expected && bad == 0);
    crgContactPointDelete(single);
    crgContactPointDelete(many);
}

/* A road with a turning reference line and a slope, written here: the raw data equal
 * the evaluation at the grid nodes. */
static void raw_data(const char *tmp)
{
    char path[1024];
    FILE *f;
    int i, j, nu = 0, nv = 0, id, cp, bad = 0;
    double v[5], u[21], x[21], y[21], phi[21], zl[21];
    float z[21 * 5];
    snprintf(path, sizeof path, "%s/raw_data.crg", tmp);
    f = fopen(path, "w");
    if (!f) { CHECK(0); return; }
    fprintf(f, "$ROAD_CRG\nREFERENCE_LINE_START_U = 2.0\nREFERENCE_LINE_END_U = 12.0\nREFERENCE_LINE_INCREMENT = 0.5\n");
    fprintf(f, "REFERENCE_LINE_START_X = 10.0\nREFERENCE_LINE_START_Y = -4.0\nREFERENCE_LINE_START_Z = 3.0\n");
    fprintf(f, "LONG_SECTION_V_RIGHT = -1.0\nLONG_SECTION_V_LEFT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n$\n");
    fprintf(f, "$KD_Definition\n#:LRFI\nD:reference line phi,rad\nD:reference line slope,m/m\n");
    for (j = 1; j <= 5; j++) fprintf(f, "D:long section %d,m\n", j);
    fprintf(f, "$\n$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$\n");
    for (i = 0; i < 21; i++) {
        fprintf(f, "%10.5f%10.5f", 0.03 * i, 0.01 * (i % 3));
        for (j = 0; j < 5; j++) fprintf(f, "%10.5f", (i == 4 && j == 2) ? NAN : 0.001 * i * j - 0.002);
        fprintf(f, "\n");
    }
    fclose(f);
    id = crgLoaderReadFile(path);
    CHECK(id > 0);
    CHECK(crgDataSetGetGridSize(id, &nu, &nv) == 1 && nu == 21 && nv == 5);
    CHECK(crgDataSetGetGridSize(id, NULL, NULL) == 1);
    CHECK(crgDataSetGetGridV(id, v, 4) == 0);                 /* wrong size */
    CHECK(crgDataSetGetGridV(id, v, 5) == 1 && v[0] == -1.0 && v[4] == 1.0);
    CHECK(crgDataSetGetGridZ(id, NULL, 21, 5) == 0);
    CHECK(crgDataSetGetGridZ(id, z, 21, 5) == 1 && isnan(z[4 * 5 + 2]));
    CHECK(crgDataSetGetRefLine(id, u, x, y, phi, zl, 21) == 1);
    CHECK(crgDataSetGetRefLine(id, NULL, NULL, NULL, NULL, zl, 21) == 1);
    CHECK(crgDataSetGetRefLine(id + 100, u, x, y, phi, zl, 21) == 0);
    cp = crgContactPointCreate(id);
    for (i = 0; i < 21; i++) {
        double px, py, pz;
        bad += u[i] != 2.0 + 0.5 * i;
        crgEvaluv2xy(cp, u[i], 0.0, &px, &py);
        bad += px != x[i] || py != y[i];
        for (j = 0; j < 5; j++) {
            if (crgEvaluv2z(cp, u[i], v[j], &pz) && !isnan(z[i * 5 + j]))
                bad += fabs(pz - (z[i * 5 + j] + zl[i])) > 1e-6;
        }
    }
    CHECK(bad == 0);
    CHECK(fabs(zl[0] - 3.0) < 1e-12 && x[0] == 10.0 && y[0] == -4.0);
    crgDataSetRelease(id);
}

int main(int argc, char **argv)
{
    const char *road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    const char *tmp = argc > 2 ? argv[2] : "/tmp";
    double out[4];
    int id, mu, mv, cp;
    crgMsgSetLevel(dCrgMsgLevelNone);
    id = crgLoaderReadFile(road);
    CHECK(id > 0);
    crgCheck(id);
    crgDataSetModifiersApply(id);
    points(id);
    for (mu = dCrgBorderModeNone; mu <= dCrgBorderModeReflect; mu++)
        for (mv = dCrgBorderModeNone; mv <= dCrgBorderModeReflect; mv++)
            compare_batches(id, mu, mv);
    /* Bad arguments: no crash, 0. */
    cp = crgContactPointCreate(id);
    CHECK(crgEvaluv2zN(cp, 4, NULL, g_v, out) == 0);
    CHECK(crgEvaluv2zN(cp, -1, g_u, g_v, out) == 0);
    CHECK(crgEvaluv2zN(cp, 0, g_u, g_v, out) == 0);
    CHECK(crgEvaluv2zN(cp + 100, 4, g_u, g_v, out) == 0);
    CHECK(crgEvaluv2zN(cp, 4, g_u, g_v, out) >= 0);
    raw_data(tmp);
    crgMemRelease();
    return check_summary("test_extensions");
}
