/* The global origin and geodetic calls: the origin read and kept through modifiers,
 * geodetic round trips, and bad ids, null pointers and roads without a projection. */
#include <stdio.h>
#include <string.h>
#include "crgBaseLib.h"
#include "check.h"

/* A curved road of 41 x 5 nodes; `mpro` adds a map projection section. */
static int write_road(const char *path, int mpro)
{
    int i, j;
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f, "$ROAD_CRG\nREFERENCE_LINE_START_U = 0.0\nREFERENCE_LINE_END_U = 20.0\n");
    fprintf(f, "REFERENCE_LINE_INCREMENT = 0.5\nREFERENCE_LINE_START_X = 5.0\nREFERENCE_LINE_START_Y = 2.0\n");
    fprintf(f, "LONG_SECTION_V_RIGHT = -1.0\nLONG_SECTION_V_LEFT = 1.0\nLONG_SECTION_V_INCREMENT = 0.5\n");
    fprintf(f, "REFERENCE_LINE_OFFSET_X = 691000.25\nREFERENCE_LINE_OFFSET_Y = 5322000.5\n");
    fprintf(f, "REFERENCE_LINE_OFFSET_Z = 584.0\nREFERENCE_LINE_OFFSET_PHI = 0.4\n$\n");
    if (mpro)
        fprintf(f, "$ROAD_CRG_MPRO\nGELL_NM = WGS84\nPROJ_NM = 'UTM_32U'\n$\n");
    fprintf(f, "$KD_Definition\n#:LRFI\nD:reference line phi,rad\n");
    for (j = 1; j <= 5; j++)
        fprintf(f, "D:long section %d,m\n", j);
    fprintf(f, "$\n$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$\n");
    for (i = 0; i < 41; i++) {
        fprintf(f, "%10.5f", 0.01 * i);
        for (j = 0; j < 5; j++)
            fprintf(f, "%10.5f", 0.002 * i - 0.01 * j);
        fprintf(f, "\n");
    }
    fclose(f);
    return 1;
}

/* East/north/height and latitude/longitude/altitude of the surface point (u, v). */
static void place(int cp, double u, double v, double enh[3], double llh[3])
{
    double x, y, z;
    CHECK(crgEvaluv2xy(cp, u, v, &x, &y) == 1);
    CHECK(crgEvaluv2z(cp, u, v, &z) == 1);
    CHECK(crgEvalxyz2enh(cp, x, y, z, &enh[0], &enh[1], &enh[2]) == 1);
    CHECK(crgEvalxyz2llh(cp, x, y, z, &llh[0], &llh[1], &llh[2]) == 1);
}

int main(int argc, char **argv)
{
    const char *tmp = argc > 2 ? argv[2] : "/tmp"; /* argv[1]: the road of the other tests, unused */
    char path[1024], plain_path[1024];
    double ox, oy, oz, ophi, e, n, h, x, y, z, lat, lon, alt;
    double enh0[3], llh0[3], enh1[3], llh1[3];
    int id, cp, plain, plain_cp, k;

    crgMsgSetLevel(dCrgMsgLevelNone);
    snprintf(path, sizeof path, "%s/georef_road.crg", tmp);
    snprintf(plain_path, sizeof plain_path, "%s/georef_plain.crg", tmp);
    CHECK(write_road(path, 1) && write_road(plain_path, 0));
    id = crgLoaderReadFile(path);
    CHECK(id > 0);
    cp = crgContactPointCreate(id);

    /* The origin as the file gives it. */
    CHECK(crgDataSetGetGlobalOrigin(id, &ox, &oy, &oz, &ophi) == 1);
    CHECK(ox == 691000.25 && oy == 5322000.5 && oz == 584.0 && ophi == 0.4);

    /* Local to global and back; the first point turns about itself. */
    CHECK(crgEvalxyz2enh(cp, 5.0, 2.0, 1.0, &e, &n, &h) == 1);
    CHECK_NEAR(e, 691005.25, 1e-9);
    CHECK_NEAR(n, 5322002.5, 1e-9);
    CHECK_NEAR(h, 585.0, 1e-12);
    CHECK(crgEvalenh2xyz(cp, e + 1.0, n, h, &x, &y, &z) == 1);
    CHECK_NEAR(x, 5.0 + cos(0.4), 1e-9);
    CHECK_NEAR(y, 2.0 - sin(0.4), 1e-9);

    /* Geodetic round trip near 48 N 11.7 E (UTM 32U). */
    CHECK(crgEvalxyz2llh(cp, 12.0, 7.0, 3.0, &lat, &lon, &alt) == 1);
    CHECK(lat > 47.9 && lat < 48.2 && lon > 11.5 && lon < 11.9);
    CHECK(crgEvalllh2xyz(cp, lat, lon, alt, &x, &y, &z) == 1);
    CHECK_NEAR(x, 12.0, 1e-4);
    CHECK_NEAR(y, 7.0, 1e-4);
    CHECK_NEAR(z, 3.0, 1e-4);

    /* Modifiers move the road, not its place on the earth: the default relocation, then
     * a reference point turned and shifted. */
    place(cp, 13.25, 0.6, enh0, llh0);
    for (k = 0; k < 2; k++) {
        if (k == 1) {
            crgDataSetModifierRemoveAll(id);
            crgDataSetModifierSetDouble(id, dCrgModRefPointUFrac, 0.5);
            crgDataSetModifierSetDouble(id, dCrgModRefPointX, 100.2);
            crgDataSetModifierSetDouble(id, dCrgModRefPointY, 30.5);
            crgDataSetModifierSetDouble(id, dCrgModRefPointZ, 12.9);
            crgDataSetModifierSetDouble(id, dCrgModRefPointPhi, 3.0);
        }
        crgDataSetModifiersApply(id);
        place(cp, 13.25, 0.6, enh1, llh1);
        CHECK_NEAR(enh1[0], enh0[0], 1e-6);
        CHECK_NEAR(enh1[1], enh0[1], 1e-6);
        CHECK_NEAR(enh1[2], enh0[2], 1e-6);
        CHECK_NEAR(llh1[0], llh0[0], 1e-11);
        CHECK_NEAR(llh1[1], llh0[1], 1e-11);
        CHECK_NEAR(llh1[2], llh0[2], 1e-6);
    }
    CHECK(crgDataSetGetGlobalOrigin(id, &ox, &oy, &oz, &ophi) == 1);
    CHECK(ox != 691000.25 && ophi != 0.4);

    /* Setting the origin moves the frame: with a zero origin, e/n/h are x/y/z. */
    CHECK(crgDataSetSetGlobalOrigin(id, 0.0, 0.0, 0.0, 0.0) == 1);
    CHECK(crgEvalxyz2enh(cp, 1.5, -2.5, 3.5, &e, &n, &h) == 1);
    CHECK(e == 1.5 && n == -2.5 && h == 3.5);
    CHECK(crgDataSetSetGlobalOrigin(id, ox, oy, oz, ophi) == 1);
    place(cp, 13.25, 0.6, enh1, llh1);
    CHECK_NEAR(llh1[0], llh0[0], 1e-11);

    /* Bad ids, null pointers, non-finite origins. */
    CHECK(crgDataSetGetGlobalOrigin(id + 100, &ox, &oy, &oz, &ophi) == 0);
    CHECK(crgDataSetGetGlobalOrigin(id, NULL, &oy, &oz, &ophi) == 0);
    CHECK(crgDataSetSetGlobalOrigin(id + 100, 0.0, 0.0, 0.0, 0.0) == 0);
    CHECK(crgDataSetSetGlobalOrigin(id, NAN, 0.0, 0.0, 0.0) == 0);
    CHECK(crgEvalxyz2enh(cp + 100, 0.0, 0.0, 0.0, &e, &n, &h) == 0);
    CHECK(crgEvalxyz2enh(cp, 0.0, 0.0, 0.0, &e, NULL, &h) == 0);
    CHECK(crgEvalenh2xyz(-1, 0.0, 0.0, 0.0, &x, &y, &z) == 0);
    CHECK(crgEvalenh2xyz(cp, 0.0, 0.0, 0.0, &x, &y, NULL) == 0);
    CHECK(crgEvalxyz2llh(cp + 100, 0.0, 0.0, 0.0, &lat, &lon, &alt) == 0);
    CHECK(crgEvalxyz2llh(cp, 0.0, 0.0, 0.0, NULL, &lon, &alt) == 0);
    CHECK(crgEvalllh2xyz(cp + 100, 48.0, 11.0, 0.0, &x, &y, &z) == 0);
    CHECK(crgEvalllh2xyz(cp, 48.0, 11.0, 0.0, &x, NULL, &z) == 0);
    CHECK(crgEvalllh2xyz(cp, 95.0, 11.0, 0.0, &x, &y, &z) == 0);

    /* A road without a projection: the origin works, geodetic calls give 0. */
    plain = crgLoaderReadFile(plain_path);
    CHECK(plain > 0);
    plain_cp = crgContactPointCreate(plain);
    CHECK(crgEvalxyz2enh(plain_cp, 5.0, 2.0, 0.0, &e, &n, &h) == 1 && e == 691005.25);
    CHECK(crgEvalxyz2llh(plain_cp, 5.0, 2.0, 0.0, &lat, &lon, &alt) == 0);
    CHECK(crgEvalllh2xyz(plain_cp, 48.0, 11.0, 0.0, &x, &y, &z) == 0);

    crgMemRelease();
    return check_summary("test_georef");
}
