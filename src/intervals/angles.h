/*
 * angles.h — π and exact trigonometry in degrees, shared by every layer
 * (the language's sin() and rotate(), circles and extrusions, the camera).
 */
#ifndef RAYSCAD_INTERVALS_ANGLES_H
#define RAYSCAD_INTERVALS_ANGLES_H

#define IV_PI 3.14159265358979323846

/* sin and cos of x degrees: exact at multiples of 30 and 45 degrees, NaN
 * for |x| of 2^52 turns or more (where a degree means nothing, as in
 * OpenSCAD) and for NaN and infinities. */
double iv_sin_degrees(double x);
double iv_cos_degrees(double x);
/* tan of x degrees: exact at multiples of 45 degrees; 90 (mod 360) is +inf
 * and 270 -inf, as OpenSCAD's tan_degrees gives them. */
double iv_tan_degrees(double x);
/* asin, acos, atan and atan2 in degrees: a whole number of degrees where
 * it is the exact answer (asin 0.5 = 30; atan2 within 3e-14 of one). */
double iv_asin_degrees(double x);
double iv_acos_degrees(double x);
double iv_atan_degrees(double x);
double iv_atan2_degrees(double y, double x);

#endif
