// Milliseconds libOpenDRIVE takes to read a map (its OpenDriveMap constructor, with the
// lateral profile and lane heights, without objects and signals), for bench/odr.sh.
#include <OpenDriveMap.h>

#include <chrono>
#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2)
        return 2;
    const auto start = std::chrono::steady_clock::now();
    odr::OpenDriveMap map(argv[1], false, false, true, true, false, true, false);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("libOpenDRIVE %s: read %.2f ms, %zu roads\n", argv[1], ms, map.get_roads().size());
    return 0;
}
