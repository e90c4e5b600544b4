/*
 * crgBaseLibPrivate.h - for programs written against the reference OpenCRG C library
 * that include its private header.
 *
 * This library provides the public API of crgBaseLib.h and, of the reference library's
 * private functions, the performance statistics of contact points below. Its internal
 * structures and other functions (its data set and contact point structs, its loader and
 * evaluation internals) are not provided: a program that uses them must be changed to
 * the public API. This header includes the public one, so that programs which include the
 * private header for the public functions build unchanged; and it defines
 * CRG_BASELIB_PRIVATE_INTERNALS as 0, so that code may test for the internals.
 */

#ifndef _CRG_BASELIB_PRIVATE_H
#define _CRG_BASELIB_PRIVATE_H

#include "crgBaseLib.h"

#define CRG_BASELIB_PRIVATE_INTERNALS 0

#ifdef __cplusplus
extern "C" {
#endif /* __cplusplus */

/*
 * Starts counting the calls on a contact point and the time they take, from zero (a
 * warning for an unknown id).
 */
void crgContactPointActivatePerfStat(int cpId);

/*
 * Stops counting the calls on a contact point; what was counted is kept.
 */
void crgContactPointDeActivatePerfStat(int cpId);

/*
 * Prints what was counted on a contact point (calls, their total, mean and longest time)
 * through the message channel at NOTICE level.
 */
void crgContactPointPrintPerfStat(int cpId);

#ifdef __cplusplus
}  /* extern "C" */
#endif /* __cplusplus */

#endif
