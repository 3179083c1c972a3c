/*
 * fragments.c — OpenSCAD's fragment count (fragments.h).
 *
 * Numerics: the comparisons are written so that NaN falls to the small
 * answers (3 fragments, or the fa/fs rule's floor of 5) and never reaches
 * the conversion to int, whose result would be undefined.
 */
#include "fragments.h"

#include <math.h>

#define PI 3.14159265358979323846

int geom_fragments(double r, double fn, double fa, double fs)
{
    if (!(r >= GEOM_GRID_FINE) || isinf(fn) || isnan(fn)) return 3;
    if (fn > 0) return fn >= 3 ? (fn > GEOM_MAX_FRAGMENTS ? GEOM_MAX_FRAGMENTS : (int)fn) : 3;
    if (fa < 0.01) fa = 0.01;
    if (fs < 0.01) fs = 0.01;
    double n = ceil(fmax(fmin(360.0 / fa, r * 2 * PI / fs), 5));
    return n > GEOM_MAX_FRAGMENTS ? GEOM_MAX_FRAGMENTS : (int)n;
}
