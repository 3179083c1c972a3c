/*
 * maskcmp.c — compare the object masks of two images (ours and OpenSCAD's).
 *
 *   maskcmp OURS.png REF.png [--bg RRGGBB | --ink V] [--min-iou X] [--diff OUT.png]
 *
 * A pixel belongs to the mask when any channel differs from the background
 * colour by more than 8/255 (OpenSCAD's image_compare.py ignores differences
 * under 8); with --ink V (0..255), when every channel is below V/255 instead:
 * ink darker than V on paper, as a rasterised PDF page whose opaque black
 * outlines are to be told from its 40 % grey rulers and type.  Pixels within one pixel of the
 * reference silhouette (their 3×3 neighbourhood holds both mask values) form the band that is left
 * out: a faceted reference and an exact silhouette may disagree there by rounding. Prints the IoU
 * outside the band and exits 0 when it is at least --min-iou (default 0.99), 1 when below, 2 on bad
 * input.
 */
#include "../../src/io/io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ink < 0: the pixels that differ from bg; else those darker than ink. */
static unsigned char *mask_of(const float *px, int w, int h, int ch, const float bg[3], float ink)
{
    unsigned char *m = malloc((size_t)w * (size_t)h);
    if (!m) return NULL;
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
        int in = 0, dark = 1;
        for (int c = 0; c < 3; c++) {
            float v = px[i * (size_t)ch + (size_t)(ch >= 3 ? c : 0)];
            if (fabsf(v - bg[c]) * 255.0f > 8.0f) in = 1;
            if (v * 255.0f >= ink) dark = 0;
        }
        m[i] = (unsigned char)(ink < 0 ? in : dark);
    }
    return m;
}

static int in_band(const unsigned char *m, int w, int h, int x, int y)
{
    unsigned char v = m[(size_t)y * (size_t)w + (size_t)x];
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
            if (m[(size_t)yy * (size_t)w + (size_t)xx] != v) return 1;
        }
    return 0;
}

int main(int argc, char **argv)
{
    const char *paths[2] = {NULL, NULL}, *diff = NULL;
    float bg[3] = {0xff / 255.0f, 0xff / 255.0f, 0xe5 / 255.0f};
    double min_iou = 0.99;
    float ink = -1;
    int np = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--bg") == 0 && i + 1 < argc) {
            unsigned rgb;
            if (sscanf(argv[++i], "%6x", &rgb) != 1) return 2;
            bg[0] = (float)((rgb >> 16) & 255) / 255.0f;
            bg[1] = (float)((rgb >> 8) & 255) / 255.0f;
            bg[2] = (float)(rgb & 255) / 255.0f;
        } else if (strcmp(argv[i], "--ink") == 0 && i + 1 < argc) {
            ink = (float)atof(argv[++i]);
        } else if (strcmp(argv[i], "--min-iou") == 0 && i + 1 < argc) {
            min_iou = atof(argv[++i]);
        } else if (strcmp(argv[i], "--diff") == 0 && i + 1 < argc) {
            diff = argv[++i];
        } else if (np < 2) {
            paths[np++] = argv[i];
        } else {
            fprintf(stderr,
                    "usage: maskcmp OURS REF [--bg RRGGBB | --ink V] [--min-iou X] [--diff OUT]\n");
            return 2;
        }
    }
    if (np != 2) {
        fprintf(stderr,
                "usage: maskcmp OURS REF [--bg RRGGBB | --ink V] [--min-iou X] [--diff OUT]\n");
        return 2;
    }
    int w[2], h[2], ch[2];
    float *px[2] = {NULL, NULL};
    char err[512];
    for (int k = 0; k < 2; k++) {
        if (io_image_read(paths[k], &w[k], &h[k], &ch[k], &px[k], err, sizeof err) != 0) {
            fprintf(stderr, "maskcmp: %s\n", err);
            return 2;
        }
    }
    if (w[0] != w[1] || h[0] != h[1]) {
        fprintf(stderr, "maskcmp: sizes differ: %dx%d and %dx%d\n", w[0], h[0], w[1], h[1]);
        return 2;
    }
    unsigned char *ours = mask_of(px[0], w[0], h[0], ch[0], bg, ink);
    unsigned char *ref = mask_of(px[1], w[1], h[1], ch[1], bg, ink);
    if (!ours || !ref) return 2;
    long inter = 0, uni = 0, ref_count = 0, band = 0;
    float *out = diff ? calloc((size_t)w[0] * (size_t)h[0] * 3, sizeof *out) : NULL;
    for (int y = 0; y < h[0]; y++)
        for (int x = 0; x < w[0]; x++) {
            size_t i = (size_t)y * (size_t)w[0] + (size_t)x;
            int b = in_band(ref, w[0], h[0], x, y);
            if (out) {
                /* white both, black neither, red only ours, blue only ref, grey band */
                float r = ours[i] ? 1.f : 0.f, bl = ref[i] ? 1.f : 0.f;
                out[i * 3 + 0] = b ? 0.5f : r;
                out[i * 3 + 1] = b ? 0.5f : r * bl;
                out[i * 3 + 2] = b ? 0.5f : bl;
            }
            if (b) {
                band++;
                continue;
            }
            ref_count += ref[i];
            inter += ours[i] & ref[i];
            uni += ours[i] | ref[i];
        }
    double iou = uni ? (double)inter / (double)uni : 1.0;
    printf("iou=%.5f mask_px=%ld band_px=%ld only_ours=%ld only_ref=%ld\n", iou, ref_count, band,
           uni - ref_count, uni - inter - (uni - ref_count));
    if (out) {
        if (io_image_write(diff, w[0], h[0], 3, out, err, sizeof err) != 0)
            fprintf(stderr, "maskcmp: %s\n", err);
        free(out);
    }
    free(ours);
    free(ref);
    free(px[0]);
    free(px[1]);
    return iou >= min_iou && ref_count > 0 ? 0 : 1;
}
