/* Loads a CRG file, checks it, applies its modifiers and prints what it holds.
 * usage: load_and_check FILE */
#include <stdio.h>
#include "crgBaseLib.h"

int main(int argc, char **argv)
{
    const char *file = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    double uMin, uMax, vMin, vMax, uInc, vInc;
    int id = crgLoaderReadFile(file);
    if (id <= 0) {
        fprintf(stderr, "could not load %s\n", file);
        return 1;
    }
    if (!crgCheck(id)) {
        fprintf(stderr, "%s: check failed\n", file);
        return 1;
    }
    crgDataSetModifiersApply(id);
    crgDataSetGetURange(id, &uMin, &uMax);
    crgDataSetGetVRange(id, &vMin, &vMax);
    crgDataSetGetIncrements(id, &uInc, &vInc);
    printf("%s: u %.3f .. %.3f m (step %.3f), v %.3f .. %.3f m (step %.3f)\n", file, uMin, uMax, uInc, vMin, vMax, vInc);
    crgDataPrintRoadInfo(id);
    crgMemRelease();
    return 0;
}
