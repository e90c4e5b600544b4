/*
 * A program that includes the reference library's private header but uses only the
 * public API (as COVISE's OpenCRGSurface does) builds unchanged and runs.
 * usage: test_private_header ROAD
 */
#include <stdio.h>
#include "crgBaseLibPrivate.h"

#if CRG_BASELIB_PRIVATE_INTERNALS != 0
#error "the private header should say that the reference's internals are not provided"
#endif

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
    crgContactPointDelete(cp);
    crgDataSetRelease(id);
    crgMemRelease();
    return 0;
}
