/* OpenDRIVE maps through crgOdr.h: a straight road written by this test with the demo
 * road laid on it (mode attached0), answers against the classic API's crgEvaluv2z on the
 * same file, friction from the lane material, road coordinates, refusals.
 * usage: test_odr ROAD.crg SCRATCH_DIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "crgBaseLib.h"
#include "crgOdr.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s ROAD.crg SCRATCH_DIR\n", argv[0]);
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    char map_path[4096];
    snprintf(map_path, sizeof map_path, "%s/odr_test_map.xodr", argv[2]);
    FILE *f = fopen(map_path, "w");
    CHECK(f != NULL);
    if (!f)
        return check_summary("test_odr");
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<OpenDRIVE><header revMajor=\"1\" revMinor=\"8\"/>\n"
            "<road id=\"main\" length=\"200\" junction=\"-1\">\n"
            "<planView><geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"200\"><line/></geometry></planView>\n"
            "<elevationProfile><elevation s=\"0\" a=\"2\" b=\"0\" c=\"0\" d=\"0\"/></elevationProfile>\n"
            "<lanes><laneSection s=\"0\">\n"
            "<left><lane id=\"1\" type=\"driving\"><width sOffset=\"0\" a=\"4\" b=\"0\" c=\"0\" d=\"0\"/>"
            "<material sOffset=\"0\" friction=\"0.6\"/></lane></left>\n"
            "<center><lane id=\"0\" type=\"none\"/></center>\n"
            "<right><lane id=\"-1\" type=\"driving\"><width sOffset=\"0\" a=\"4\" b=\"0\" c=\"0\" d=\"0\"/>"
            "<material sOffset=\"0\" friction=\"0.6\"/></lane></right>\n"
            "</laneSection></lanes>\n"
            "<surface><CRG file=\"%s\" sStart=\"10\" sEnd=\"110\" mode=\"attached0\" orientation=\"same\" "
            "sOffset=\"10\" zOffset=\"0.5\"/></surface>\n"
            "</road></OpenDRIVE>\n",
            argv[1]);
    fclose(f);

    int map = crgOdrMapLoad(map_path);
    CHECK(map > 0);
    CHECK(crgOdrMapGetRoadCount(map) == 1);
    int probe = crgOdrProbeCreate(map);
    CHECK(probe >= 0);

    /* The same file through the classic API, without the default modifiers. */
    int data = crgLoaderReadFile(argv[1]);
    CHECK(data > 0);
    crgDataSetModifierRemoveAll(data);
    crgDataSetModifiersApply(data);
    int cp = crgContactPointCreate(data);
    CHECK(cp >= 0);

    double z, mu, s, t, want;
    int road, lane;
    for (double x = 15.0; x < 108.0; x += 7.0) {
        for (double y = -2.5; y < 3.0; y += 2.0) {
            CHECK(crgOdrEvalxy(probe, x, y, &z, &mu, &road, &lane, &s, &t) == 1);
            CHECK(crgEvaluv2z(cp, x - 10.0, y, &want) == 1);
            CHECK_NEAR(z, want + 0.5, 1e-9);
            CHECK(road == 0 && lane == (y > 0 ? 1 : -1));
            CHECK_NEAR(s, x, 1e-9);
            CHECK_NEAR(t, y, 1e-9);
            CHECK(mu == 0.6);
        }
    }
    /* Beyond the record: the road's own height. */
    CHECK(crgOdrEvalxy(probe, 150.0, 1.0, &z, &mu, &road, &lane, &s, &t) == 1);
    CHECK_NEAR(z, 2.0, 1e-12);
    double nx, ny, nz;
    CHECK(crgOdrEvalxy2normal(probe, 150.0, 1.0, &nx, &ny, &nz) == 1);
    CHECK_NEAR(nx, 0.0, 1e-9);
    CHECK_NEAR(ny, 0.0, 1e-9);
    CHECK_NEAR(nz, 1.0, 1e-9);
    /* Road coordinates to the world. */
    double x, y;
    CHECK(crgOdrEvalst2xyz(probe, 0, 50.0, 1.0, &x, &y, &z) == 1);
    CHECK(crgEvaluv2z(cp, 40.0, 1.0, &want) == 1);
    CHECK_NEAR(x, 50.0, 1e-12);
    CHECK_NEAR(y, 1.0, 1e-12);
    CHECK_NEAR(z, want + 0.5, 1e-9);
    /* Off every road, unknown ids, null outputs: 0 and the outputs unchanged. */
    z = -7.0;
    CHECK(crgOdrEvalxy(probe, 50.0, 30.0, &z, &mu, &road, &lane, &s, &t) == 0);
    CHECK(z == -7.0);
    CHECK(crgOdrEvalxy(probe + 100, 50.0, 1.0, &z, &mu, &road, &lane, &s, &t) == 0);
    CHECK(crgOdrEvalxy(probe, 50.0, 1.0, NULL, &mu, &road, &lane, &s, &t) == 0);
    CHECK(crgOdrEvalst2xyz(probe, 5, 50.0, 1.0, &x, &y, &z) == 0);
    CHECK(crgOdrEvalst2xyz(probe, -1, 50.0, 1.0, &x, &y, &z) == 0);
    CHECK(crgOdrMapLoad(NULL) == 0);
    CHECK(crgOdrMapLoad("/nonexistent/map.xodr") == 0);
    CHECK(crgOdrMapGetRoadCount(map + 100) == -1);
    CHECK(crgOdrProbeCreate(map + 100) == -1);
    /* Releasing: the probe once, the map with its other probes. */
    int second = crgOdrProbeCreate(map);
    CHECK(second >= 0 && second != probe);
    CHECK(crgOdrProbeRelease(probe) == 1);
    CHECK(crgOdrProbeRelease(probe) == 0);
    CHECK(crgOdrEvalxy(probe, 50.0, 1.0, &z, &mu, &road, &lane, &s, &t) == 0);
    CHECK(crgOdrMapRelease(map) == 1);
    CHECK(crgOdrMapRelease(map) == 0);
    CHECK(crgOdrEvalxy(second, 50.0, 1.0, &z, &mu, &road, &lane, &s, &t) == 0);
    remove(map_path);
    return check_summary("test_odr");
}
