/*
 * What reading a tile of a road read in place costs: one contact point asks u/v to z at
 * one point of every half of a tile along the road (a tile is read from the file half by
 * half, HALF_U cross sections each: the points lie one cross section more apart), in
 * strips 0.8 m apart across it, so that every call reads half a tile from the file;
 * prints the time of opening and the time per call, which is one half's reading. Run it with
 * OPENCRG_IN_PLACE=always on a binary road whose file the system has cached (read it
 * once first); a road whose tiles the pool (OPENCRG_IN_PLACE_CACHE) all holds measures
 * nothing after its first pass.
 *
 * cc -O2 -Iinclude bench/tile_fill.c target/release/libopencrg.a -lm -lpthread -ldl -o tile_fill
 * usage: OPENCRG_IN_PLACE=always ./tile_fill ROAD.crg
 */
#include "road_open.h"

/* Cross sections of the half of a tile read at once (opencrg_core::tiles::HALF_U;
 * -DHALF_U=N for a build of another tile size). */
#ifndef HALF_U
#define HALF_U 512
#endif

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: tile_fill ROAD.crg\n");
        return 2;
    }
    crgMsgSetLevel(dCrgMsgLevelNone);
    double start = now();
    int data = open_road("tile_fill", argv[1]);
    if (!data)
        return 1;
    double opened = now() - start;
    int cp = crgContactPointCreate(data);
    double u0, u1, v0, v1, du, dv, z, sum = 0.0;
    crgDataSetGetURange(data, &u0, &u1);
    crgDataSetGetVRange(data, &v0, &v1);
    crgDataSetGetIncrements(data, &du, &dv);
    double step = (HALF_U + 1) * du;
    long calls = 0;
    start = now();
    for (double v = v0 + 0.5; v < v1 - 0.5; v += 0.8)
        for (double u = u0 + 1.0; u < u1 - step; u += step, calls++)
            if (crgEvaluv2z(cp, u, v, &z))
                sum += z;
    double took = now() - start;
    if (calls == 0) {
        fprintf(stderr, "tile_fill: %s is too short or too narrow\n", argv[1]);
        return 1;
    }
    printf("open %.2f s; %ld halves of tiles read, %.1f us each (heights' sum %.6f)\n", opened, calls, took / calls * 1e6, sum);
    return 0;
}
