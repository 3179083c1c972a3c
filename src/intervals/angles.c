/*
 * angles.c — trigonometry in degrees as OpenSCAD 2021.01 computes it
 * (angles.h): the argument reduced to the first quadrant first, so that
 * multiples of 30 and 45 degrees come out exact (sin 30 = 0.5, cos 90 = 0)
 * and a circle's points are symmetric to the bit.
 */
#include "angles.h"

#include <math.h>

/* Beyond 2^52 turns a degree has no meaning left; OpenSCAD answers NaN. */
#define TRIG_HUGE (4503599627370496.0 * 360.0)

double iv_sin_degrees(double x)
{
    if (!(fabs(x) < TRIG_HUGE)) return NAN;
    x = fmod(x, 360.0);
    if (x < 0) x += 360.0;
    int neg = x >= 180.0;
    if (neg) x -= 180.0;
    if (x > 90.0) x = 180.0 - x;
    double r;
    if (x == 0)
        r = 0;
    else if (x == 30.0)
        r = 0.5;
    else if (x == 45.0)
        r = 0.70710678118654752440;
    else if (x == 60.0)
        r = sqrt(3.0) / 2;
    else if (x == 90.0)
        r = 1;
    else if (x < 45.0)
        r = sin(x * IV_PI / 180.0);
    else
        r = cos((90.0 - x) * IV_PI / 180.0);
    return neg ? -r : r;
}

double iv_cos_degrees(double x)
{
    if (!(fabs(x) < TRIG_HUGE)) return NAN;
    x = fmod(x, 360.0);
    if (x < 0) x += 360.0;
    return iv_sin_degrees(x + 90.0 > 360.0 ? x - 270.0 : x + 90.0);
}

double iv_tan_degrees(double x)
{
    if (!isfinite(x)) return NAN;
    double r = fmod(x, 360.0);
    if (r < 0) r += 360.0;
    if (r == 90.0) return INFINITY;
    if (r == 270.0) return -INFINITY;
    r = fmod(r, 180.0);
    if (r == 0) return 0;
    if (r == 45.0) return 1;
    if (r == 135.0) return -1;
    return tan(r * IV_PI / 180.0);
}
