/*
 * accumulate.c — see accumulate.h.
 */
#include "accumulate.h"

#include <math.h>
#include <stdlib.h>

static double to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double to_srgb(double c)
{
    if (c <= 0) return 0;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1 / 2.4) - 0.055;
}

int cli_accum_reset(cli_accum *a, size_t npix, int linear)
{
    size_t n = 3 * npix;
    if (n > a->cap) {
        double *s = realloc(a->sum, n * sizeof *s);
        if (!s) return -1;
        a->sum = s;
        double *q = realloc(a->sq, n * sizeof *q);
        if (!q) return -1;
        a->sq = q;
        a->cap = n;
    }
    for (size_t i = 0; i < n; i++)
        a->sum[i] = a->sq[i] = 0;
    a->n = n;
    a->count = 0;
    a->linear = linear;
    return 0;
}

void cli_accum_add(cli_accum *a, const float *rgba)
{
    for (size_t i = 0, p = 0; i < a->n; i += 3, p += 4)
        for (int k = 0; k < 3; k++) {
            double x = a->linear ? to_linear(rgba[p + k]) : rgba[p + k];
            a->sum[i + k] += x;
            a->sq[i + k] += x * x;
        }
    a->count++;
}

void cli_accum_mean(const cli_accum *a, float *rgba)
{
    double inv = a->count > 0 ? 1.0 / a->count : 0;
    for (size_t i = 0, p = 0; i < a->n; i += 3, p += 4) {
        for (int k = 0; k < 3; k++) {
            double m = a->sum[i + k] * inv;
            m = a->linear ? to_srgb(m) : m;
            rgba[p + k] = (float)(m > 1 ? 1 : m);
        }
        rgba[p + 3] = 1;
    }
}

double cli_accum_error(const cli_accum *a)
{
    if (a->count < 2 || a->n == 0) return INFINITY;
    double m = a->count, total = 0;
    for (size_t i = 0; i < a->n; i++) {
        double var = (a->sq[i] - a->sum[i] * a->sum[i] / m) / (m - 1);
        if (var <= 0) continue;
        if (a->linear) { /* to the sRGB scale: times the encoding's slope there */
            double c = a->sum[i] / m;
            double slope = c <= 0.0031308 ? 12.92 : 1.055 / 2.4 * pow(c, 1 / 2.4 - 1);
            var *= slope * slope;
        }
        total += var / m;
    }
    return sqrt(total / (double)a->n);
}

void cli_accum_free(cli_accum *a)
{
    free(a->sum);
    free(a->sq);
    a->sum = a->sq = NULL;
    a->n = a->cap = 0;
    a->count = 0;
}
