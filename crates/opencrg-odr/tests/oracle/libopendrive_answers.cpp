// Answers of libOpenDRIVE (the independent implementation built by
// ../shared/oracles/build-libopendrive.sh) for the geometry tests of opencrg-odr.
// usage: libopendrive_answers MAP.xodr < queries > answers
// Each query line "ROAD S T" gets one line: the reference line at s (x y z heading
// superelevation lane-offset), the id of the lane at (s, t), the surface point at (s, t)
// (x y z) and its height above the cross section; "error MESSAGE" where it throws.
#include <OpenDriveMap.h>
#include <Road.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: %s MAP.xodr < queries\n", argv[0]);
        return 2;
    }
    odr::OpenDriveMap map(argv[1]);
    std::map<std::string, odr::Road> roads;
    for (const odr::Road& road : map.get_roads())
        roads.emplace(road.id, road);
    std::string id;
    double s = 0, t = 0;
    while (std::cin >> id >> s >> t)
    {
        auto found = roads.find(id);
        if (found == roads.end())
        {
            std::printf("error no road %s\n", id.c_str());
            continue;
        }
        const odr::Road& road = found->second;
        try
        {
            const odr::Vec3D p0 = road.ref_line.get_xyz(s);
            const odr::Vec3D d = road.ref_line.derivative(s);
            odr::Vec3D e_s, e_t, e_h;
            road.get_xyz(s, t, 0, &e_s, &e_t, &e_h);
            const odr::Vec3D p = road.get_surface_pt(s, t);
            const odr::Vec3D off{p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]};
            const double h = off[0] * e_h[0] + off[1] * e_h[1] + off[2] * e_h[2];
            const int lane = road.get_lanesection(s).get_lane_id(s, t);
            std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %d %.17g %.17g %.17g %.17g\n", p0[0], p0[1], p0[2],
                        std::atan2(d[1], d[0]), road.superelevation.evaluate(s), road.lane_offset.evaluate(s), lane, p[0],
                        p[1], p[2], h);
        }
        catch (const std::exception& e)
        {
            std::printf("error %s\n", e.what());
        }
    }
    return 0;
}
