/*
 * angles.c — trigonometry in degrees as OpenSCAD 2021.01 computes it
 * (angles.h): the argument reduced to the first quadrant first, so that
 * multiples of 30 and 45 degrees come out exact (sin 30 = 0.5, cos 90 = 0)
 * and a circle's points are symmetric to the bit.
 */
#include "angles.h"

#include <math.h>

/* Beyond 2^52 turns a degree has no meaning left; OpenSCAD answers NaN. */
#define TRIG_HUGE (67108864.0 * 360.0 * 67108864.0)

static const double SQRT3 = 1.73205080756887719318;   /* tan 60 */
static const double SQRT3_4 = 0.86602540378443859659; /* sin 60 */
static const double SQRT1_3 = 0.57735026918962573106; /* tan 30 */
static const double SQRT1_2 = 0.70710678118654752440; /* sin 45 */

/* OpenSCAD's conversions: by the rounded constants π/180 and 180/π. */
static const double DEG2RAD = 0.017453292519943295769;
static const double RAD2DEG = 57.2957795130823208767;

static double radians(double x)
{
    return x * DEG2RAD;
}

/* x reduced to [0, period) by whole periods, as OpenSCAD does it (x less
 * period times floor(x / period), not fmod); NaN past TRIG_HUGE. */
static double reduce(double x, double period)
{
    if (x < period && x >= 0.0) return x;
    if (!(x < TRIG_HUGE && x > -TRIG_HUGE)) return NAN;
    return x - period * floor(x / period);
}

double iv_sin_degrees(double x)
{
    x = reduce(x, 360.0);
    int neg = x >= 180.0;
    if (neg) x -= 180.0;
    if (x > 90.0) x = 180.0 - x;
    double r;
    if (x < 45.0)
        r = x == 30.0 ? 0.5 : sin(radians(x));
    else if (x == 45.0)
        r = SQRT1_2;
    else if (x == 60.0)
        r = SQRT3_4;
    else /* NaN too */
        r = cos(radians(90.0 - x));
    return neg ? -r : r;
}

double iv_cos_degrees(double x)
{
    x = reduce(x, 360.0);
    int neg = x >= 180.0;
    if (neg) x -= 180.0;
    if (x > 90.0) {
        x = 180.0 - x;
        neg = !neg;
    }
    double r;
    if (x > 45.0)
        r = x == 60.0 ? 0.5 : sin(radians(90.0 - x));
    else if (x == 45.0)
        r = SQRT1_2;
    else if (x == 30.0)
        r = SQRT3_4;
    else /* NaN too */
        r = cos(radians(x));
    return neg ? -r : r;
}

/* floor(x / 180) as an int the way x86-64 converts it (INT_MIN when out
 * of range or NaN), which decides the sign of tan's zeros and poles. */
static int half_turns(double x)
{
    double c = floor(x / 180.0);
    return c >= -2147483648.0 && c < 2147483648.0 ? (int)c : (-2147483647 - 1);
}

double iv_tan_degrees(double x)
{
    int cycles = half_turns(x);
    if (!(x < 180.0 && x >= 0.0)) {
        if (!(x < TRIG_HUGE && x > -TRIG_HUGE)) return NAN;
        x -= 180.0 * cycles;
    }
    int neg = x > 90.0;
    if (neg) x = 180.0 - x;
    double r;
    if (x == 0.0)
        r = cycles % 2 == 0 ? 0.0 : -0.0;
    else if (x == 30.0)
        r = SQRT1_3;
    else if (x == 45.0)
        r = 1.0;
    else if (x == 60.0)
        r = SQRT3;
    else if (x == 90.0)
        r = cycles % 2 == 0 ? INFINITY : -INFINITY;
    else
        r = tan(radians(x));
    return neg ? -r : r;
}

/* The inverse functions answer a whole number of degrees where the forward
 * function of it gives x back exactly (asin 0.5 = 30), as OpenSCAD does. */
double iv_asin_degrees(double x)
{
    double d = asin(x) * RAD2DEG, whole = round(d);
    return iv_sin_degrees(whole) == x ? whole : d;
}

double iv_acos_degrees(double x)
{
    double d = acos(x) * RAD2DEG, whole = round(d);
    return iv_cos_degrees(whole) == x ? whole : d;
}

double iv_atan_degrees(double x)
{
    double d = atan(x) * RAD2DEG, whole = round(d);
    return iv_tan_degrees(whole) == x ? whole : d;
}

double iv_atan2_degrees(double y, double x)
{
    double d = atan2(y, x) * RAD2DEG, whole = round(d);
    return fabs(d - whole) < 3.0e-14 ? whole : d;
}
