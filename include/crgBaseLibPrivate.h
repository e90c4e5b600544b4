/*
 * crgBaseLibPrivate.h - for programs written against the reference OpenCRG C library
 * that include its private header but use only the public API.
 *
 * This library provides the public API of crgBaseLib.h only. The reference library's
 * internal structures and functions (its data set and contact point structs, its loader
 * and evaluation internals) are not provided: a program that uses them must be changed
 * to the public API. This header includes the public one, so that programs which include
 * the private header for the public functions build unchanged; and it defines
 * CRG_BASELIB_PRIVATE_INTERNALS as 0, so that code may test for the internals.
 */

#ifndef _CRG_BASELIB_PRIVATE_H
#define _CRG_BASELIB_PRIVATE_H

#include "crgBaseLib.h"

#define CRG_BASELIB_PRIVATE_INTERNALS 0

#endif
