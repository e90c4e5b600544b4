// The header is usable from C++: this compiles, links and runs as C++.
#include <cstdio>
#include "crgBaseLib.h"

int main(int argc, char** argv)
{
    const char* road = argc > 1 ? argv[1] : "examples/data/demo_road.crg";
    crgMsgSetLevel(dCrgMsgLevelNone);
    int id = crgLoaderReadFile(road);
    int cp = crgContactPointCreate(id);
    double z = 0.0;
    bool ok = id > 0 && cp >= 0 && crgEvaluv2z(cp, 10.0, 0.0, &z) == 1;
    crgMemRelease();
    std::printf("test_cpp: %d passed, %d failed\n", ok ? 1 : 0, ok ? 0 : 1);
    return ok ? 0 : 1;
}
