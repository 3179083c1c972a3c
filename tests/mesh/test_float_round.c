/*
 * test_float_round.c — mesh_round_to_float rounds every coordinate to the
 * float a mesh vertex holds.  GCC 12.2's basic-block SLP vectorizer, at -O3,
 * dropped the rounding of the first two of three in-place conversions, so
 * the mesher's decisions about corners differed between the -O3 build and
 * the sanitizer build's -O1 (Makefile, NOSLP).  The expected values are the
 * floats nearest 0.1, 0.2, 0.3 and -7.3497033 written out exactly.
 */
#include <criterion/criterion.h>

#include "../../src/mesh/dexels.h"

Test(float_round, every_coordinate)
{
    double x[3] = {0.1, 0.2, 0.3};
    mesh_round_to_float(x);
    cr_expect_eq(x[0], 0.100000001490116119384765625);
    cr_expect_eq(x[1], 0.20000000298023223876953125);
    cr_expect_eq(x[2], 0.300000011920928955078125);
}

Test(float_round, far_and_negative)
{
    double x[3] = {-7.3497033, 1e6 + 0.3, 3.0};
    mesh_round_to_float(x);
    cr_expect_eq(x[0], -7.34970331192016601562500);
    cr_expect_eq(x[1], 1000000.3125);
    cr_expect_eq(x[2], 3.0);
}
