/*
 * crgOdr.h - OpenDRIVE maps with OpenCRG surfaces, served by the OpenCRG Rust library
 * (libopencrg) beside the classic API of crgBaseLib.h.
 *
 * A map is loaded once (its roads indexed, the CRG files its <surface><CRG> records name
 * read); a probe per wheel or thread answers at world points: the surface's height with
 * the CRG records laid on, its normal and friction, the road, lane, s and t.
 * Ids as in the classic API: maps > 0, probes >= 0. Calls return 1 on success and 0
 * otherwise (an unknown id, a null output, a point off every road); outputs are written
 * only on success. Messages go through crgMsgPrint. A probe is used by one thread at a
 * time; its queries allocate nothing.
 *
 * Kept in step with crates/opencrg-sys/src/odr.rs by crates/opencrg-sys/tests/header.rs.
 */
#ifndef _CRG_ODR_H
#define _CRG_ODR_H

#ifdef __cplusplus
extern "C" {
#endif

/* Reads an OpenDRIVE map (.xodr) and the CRG files its records name; the map's id (> 0),
 * or 0 with a message naming the file, line and element. */
int crgOdrMapLoad(const char *filename);

/* Releases a map and its probes; 1, or 0 for an unknown id. */
int crgOdrMapRelease(int mapId);

/* The number of roads of a map (road indexes count from 0 in the file's order), or -1. */
int crgOdrMapGetRoadCount(int mapId);

/* A probe on a map, for one wheel or thread; its id (>= 0), or -1 for an unknown map. */
int crgOdrProbeCreate(int mapId);

/* Releases a probe; 1, or 0 for an unknown id. */
int crgOdrProbeRelease(int probeId);

/* The ground at the world point (x, y): height (NaN in a hole of a CRG grid), friction
 * coefficient (NaN where neither a friction record nor the lane's material gives one),
 * road index, lane id, s and t. 0 off every road. */
int crgOdrEvalxy(int probeId, double x, double y, double *z, double *friction, int *road, int *lane, double *s,
                 double *t);

/* The upward unit normal of the surface at the world point (x, y). */
int crgOdrEvalxy2normal(int probeId, double x, double y, double *nx, double *ny, double *nz);

/* The world point of the surface at (s, t) of the road with this index. */
int crgOdrEvalst2xyz(int probeId, int road, double s, double t, double *x, double *y, double *z);

#ifdef __cplusplus
}
#endif

#endif /* _CRG_ODR_H */
