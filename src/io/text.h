/*
 * text.h — text() glyph outlines through fontconfig (font lookup),
 * HarfBuzz (shaping) and FreeType (outlines), laid out as OpenSCAD 2021.01's
 * FreetypeRenderer does.  Nothing here prints or throws.
 */
#ifndef RAYSCAD_IO_TEXT_H
#define RAYSCAD_IO_TEXT_H

#include <stddef.h>

#include "polygon.h"

#ifdef __cplusplus
extern "C" {
#endif

/* text()'s arguments (strings borrowed; NULL or "" means not given). */
typedef struct io_text_params {
    const char *text;      /* UTF-8 */
    double size;           /* OpenSCAD's size: about the ascent of capitals */
    const char *font;      /* a fontconfig pattern; "": "Liberation Sans" */
    const char *halign;    /* left (default), center, right */
    const char *valign;    /* baseline (default), bottom, center, top */
    double spacing;        /* advance multiplier, default 1 */
    const char *direction; /* ltr, rtl, ttb, btt; "": from the script */
    const char *language;  /* default "en" */
    const char *script;    /* ISO 15924 ("latn"); "": from the text */
    int segments;          /* points per Bézier segment (OpenSCAD: fragments/8 + 1, >= 2) */
    const char *const *font_files; /* added to fontconfig's fonts first (a */
    int nfont_files;               /* script's use <font.ttf>, as OpenSCAD's) */
    char *font_used;               /* out (may be NULL): the font file opened, */
    size_t font_used_len;          /* "" when none */
} io_text_params;

/* The outlines of the shaped text in model units, each glyph filled by the
 * even-odd rule and the glyphs united (a normalised set, polygon.h).  Text
 * with no outlines (spaces, "") gives an empty set.  Returns 0 and *out;
 * 1 with a message in err when no font matches, the one found cannot be
 * opened or not set to the size (OpenSCAD 2021.01 then draws nothing and
 * goes on); -1 with a
 * message (FreeType failure, out of memory). */
int io_text_render(const io_text_params *p, io_paths *out, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
