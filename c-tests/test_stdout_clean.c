/* A converter that writes its result (here: OBJ vertices) to stdout while the library
 * talks at its default level. Run by stdout_clean.cmake, which checks that stdout holds
 * only the program's own lines and stderr the library's messages.
 * usage: test_stdout_clean ROAD.crg */
#include <stdio.h>
#include "crgBaseLib.h"

int main(int argc, char **argv)
{
    const char *road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    double z = 0.0;
    int id, cp, i;

    printf("# mesh\n");
    id = crgLoaderReadFile(road);             /* NOTICE messages */
    crgCheck(id);
    crgDataSetModifiersApply(id);
    cp = crgContactPointCreate(id);
    for (i = 0; i < 3; i++) {
        crgEvaluv2z(cp, i * 10.0, 0.0, &z);
        printf("v %d 0 %.6f\n", i * 10, z);
    }
    crgEvaluv2z(cp + 1000, 0.0, 0.0, &z);     /* WARNING: unknown contact point */
    crgMsgPrint(dCrgMsgLevelNotice, "a message of the application\n");
    crgDataSetRelease(id);
    printf("# end\n");
    return 0;
}
