/*
 * accumulate.h — the viewer's progressive refinement: the mean of ever more
 * pictures of one view (rayscad_render_options.pass 0, 1, 2, …) and how far
 * that mean may still be from the one it converges to (its standard error).
 */
#ifndef RAYSCAD_CLI_ACCUMULATE_H
#define RAYSCAD_CLI_ACCUMULATE_H

#include <stddef.h>

typedef struct cli_accum {
    double *sum, *sq; /* per channel (RGB) of every pixel: Σx, Σx² */
    size_t n, cap;    /* channels in use, and room */
    int count;        /* pictures added */
    int linear;       /* averaged in linear light (the path tracer's space) */
} cli_accum;

/* Start again with pictures of npix pixels, averaged as sRGB values, as the
 * preview renderer averages its samples, or (linear = 1) in linear light,
 * as the path tracer averages its own.  Returns 0, or -1 out of memory. */
int cli_accum_reset(cli_accum *a, size_t npix, int linear);

/* Add a picture: npix RGBA floats, sRGB-encoded, as rayscad_render writes
 * them (above 1 where it leaves them unclamped). */
void cli_accum_add(cli_accum *a, const float *rgba);

/* The mean so far into rgba (alpha 1), clamped to 1 to be shown. */
void cli_accum_mean(const cli_accum *a, float *rgba);

/* The root mean square over every pixel's channels of the mean's standard
 * error (the spread of the pictures over √count), on the sRGB scale of 0 to
 * 1; INFINITY before two pictures. */
double cli_accum_error(const cli_accum *a);

void cli_accum_free(cli_accum *a);

#endif
