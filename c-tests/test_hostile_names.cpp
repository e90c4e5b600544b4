/* The same test compiled as C++ (see test_hostile_names.c). */
#include "test_hostile_names.c"
